#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <variant>

#include "nckit/plan/segment_limits.hpp"
#include "nckit/report/tool_path.hpp"
#include "piece_points.hpp"
#include "polyline_decimate.hpp"

namespace nckit {

namespace {
// mm/s: a junction slower than this is a stop.
constexpr double stop_speed_mm_s = 1e-9;
}  // namespace

struct ToolPathRecorder::Impl {
    //! What the classification needs of a move still waiting for its end junction.
    struct OpenMove {
        std::size_t index = 0;
        bool exact_stop = false;
        SlowdownFacts facts;
        std::vector<ReportVertex> points;  //!< its polyline, starting at the previous end
    };

    //! Where a corner transition (or blend arc) begins: for a move that no main piece came for,
    //! the start of the transition its own block made is the middle of its planned path.
    struct BlendStart {
        std::uint32_t line = 0;
        std::string file;
        ReportVertex at;
        double time_s = 0;
    };
    struct Place {
        ReportVertex at;
        double time_s = 0;
    };

    MachineConfig machine;
    ProfileKind kind;
    ToolPathOptions options;
    double speed_tolerance_mm_s = 0;
    ToolPathReport report;
    std::map<const std::string*, std::uint32_t> file_index;
    bool first_file_seen = false;      //!< a move of options.first_file has come
    std::deque<std::size_t> awaiting;  //!< moves with length, waiting for their piece
    std::vector<bool> exact_stop;      //!< per move: G61/G9 at its end
    std::size_t finalized = 0;         //!< moves before this have their vertices and times
    std::optional<OpenMove> open;
    std::optional<Junction> boundary;              //!< what happened since the last main piece, if anything
    std::vector<BlendStart> run_blends;            //!< blend pieces since the last main piece, in order
    std::size_t run_first_free = 0;                //!< run_blends before this are not another move's
    std::map<std::size_t, Place> consumed;         //!< moves eaten by transitions: where they are drawn
    std::map<std::size_t, ReportVertex> standing;  //!< moves that go nowhere: their programmed point
    PeakTracker peaks;
    TimeSampler sampler;
    double time_s = 0;  //!< end of the last piece

    Impl(const MachineConfig& m, ProfileKind k, ToolPathOptions o)
        : machine(m), kind(k), options(o), sampler(m, o.max_samples) {
        double top = 0;
        for (const AxisConfig& axis : machine.axes) top = std::max(top, axis.max_velocity);
        speed_tolerance_mm_s = options.speed_tolerance * top;
        report.tolerance_mm = options.tolerance_mm;
        if (!options.first_file.empty()) report.files.push_back(options.first_file);
    }

    std::uint32_t file_of(const SourceLocation& where) {
        auto [it, added] = file_index.try_emplace(where.file.get(), static_cast<std::uint32_t>(report.files.size()));
        if (added) {
            if (!first_file_seen && !options.first_file.empty() && where.file_name() == options.first_file) {
                it->second = 0;  // the program's own file, named up front
                first_file_seen = true;
            } else {
                report.files.push_back(where.file_name());
            }
        }
        return it->second;
    }

    void add_move(const Move& move) {
        ReportMove out;
        double length = 0;
        bool stops = false;
        if (const auto* line = std::get_if<Line>(&move.what)) {
            out.kind = line->rapid ? ReportMoveKind::rapid : ReportMoveKind::feed;
            out.feed_mm_s = line->rapid ? 0.0 : line->feed.mm_per_min / 60.0;
            length = make_line(line->from, line->to).length;
            stops = line->path.exact_stop;
        } else if (const auto* arc = std::get_if<Arc>(&move.what)) {
            out.kind = ReportMoveKind::arc;
            out.feed_mm_s = arc->feed.mm_per_min / 60.0;
            length = make_arc(*arc).length;
            stops = arc->path.exact_stop;
        } else if (const auto* sync = std::get_if<SyncMove>(&move.what)) {
            out.kind = ReportMoveKind::sync;
            out.feed_mm_s = sync->feed.mm_per_min / 60.0;
            length = make_line(sync->from, sync->to).length;
        } else {
            return;
        }
        out.file = file_of(move.where);
        out.line = move.where.line;
        if (length > min_move_length) {
            awaiting.push_back(report.moves.size());
        } else if (const auto* line = std::get_if<Line>(&move.what)) {
            standing[report.moves.size()] = {line->to[Axis::X], line->to[Axis::Y], line->to[Axis::Z], 0.0};
        }
        report.moves.push_back(out);
        exact_stop.push_back(stops);
    }

    //! Moves before `upto` without a piece of their own are dots: where their transitions meet
    //! if they were eaten by them, else where the path stands.
    void finalize_before(std::size_t upto) {
        for (; finalized < upto; ++finalized) {
            ReportMove& m = report.moves[finalized];
            m.vertex_end = static_cast<std::uint32_t>(report.vertices.empty() ? 0 : report.vertices.size() - 1);
            // Not after a later move that was eaten: the slider's search needs starts in order.
            const auto later = consumed.lower_bound(finalized);
            m.start_s = m.end_s = later != consumed.end() ? std::min(time_s, later->second.time_s) : time_s;
            ReportVertex at = report.vertices.empty() ? ReportVertex{} : report.vertices.back();
            if (auto stands = standing.find(finalized); stands != standing.end()) {
                // Where the program puts it: under G64 the path may pass that corner inside it.
                at = {stands->second.x_mm, stands->second.y_mm, stands->second.z_mm, at.speed_mm_s};
                standing.erase(stands);
            } else if (auto eaten = consumed.find(finalized); eaten != consumed.end()) {
                at = eaten->second.at;
                m.start_s = m.end_s = eaten->second.time_s;
                m.peak_mm_s = at.speed_mm_s;
                const bool cuts = m.kind == ReportMoveKind::feed || m.kind == ReportMoveKind::arc;
                if (cuts && at.speed_mm_s < reached_fraction * m.feed_mm_s) m.slowdown = Slowdown::corner;
                consumed.erase(eaten);
            }
            report.point_places.push_back(at);
        }
    }

    //! A move with length that no main piece came for: its place is the start of the next
    //! unclaimed transition its block made, if there is one.
    void mark_consumed(std::size_t index) {
        const ReportMove& m = report.moves[index];
        for (std::size_t b = run_first_free; b < run_blends.size(); ++b) {
            if (run_blends[b].line == m.line && run_blends[b].file == report.files[m.file]) {
                consumed[index] = {run_blends[b].at, run_blends[b].time_s};
                run_first_free = b + 1;
                return;
            }
        }
    }

    void close_open(Junction end) {
        if (!open) return;
        open->facts.end = end;
        ReportMove& m = report.moves[open->index];
        m.slowdown = (m.kind == ReportMoveKind::feed || m.kind == ReportMoveKind::arc) ? classify_slowdown(open->facts)
                                                                                       : Slowdown::none;
        report.points_before_decimation += open->points.size() - 1;
        for (const ReportVertex& v :
             report_detail::decimate(open->points, options.tolerance_mm * 0.75, speed_tolerance_mm_s)) {
            report.vertices.push_back(v);
        }
        m.vertex_end = static_cast<std::uint32_t>(report.vertices.size() - 1);
        m.end_s = time_s;
        finalized = open->index + 1;
        open.reset();
    }

    void main_piece(const TrajectoryPiece& piece) {
        // The move this piece is the path of: the next move with length from the same block.
        std::size_t index = report.moves.size();
        while (!awaiting.empty()) {
            const std::size_t candidate = awaiting.front();
            awaiting.pop_front();
            const ReportMove& m = report.moves[candidate];
            if (m.line == piece.where.line && report.files[m.file] == piece.where.file_name()) {
                index = candidate;
                break;
            }
            mark_consumed(candidate);
        }
        run_blends.clear();
        run_first_free = 0;
        const report_detail::PiecePoints pts = report_detail::piece_points(piece, options.arc_step_deg);
        Junction start = Junction::exact_stop;
        if (open) {
            if (boundary) {
                start = *boundary;
            } else if (exact_stop[open->index]) {
                start = Junction::exact_stop;
            } else {
                start = open->facts.end_mm_s < stop_speed_mm_s ? Junction::corner : Junction::tangent;
            }
            close_open(start);
        } else if (boundary) {
            start = *boundary;
        }
        boundary.reset();
        if (index >= report.moves.size()) return;  // no move of its block left: nothing to hang it on
        finalize_before(index);
        if (report.vertices.empty()) report.vertices.push_back(pts.points.front());
        OpenMove next;
        next.index = index;
        ReportMove& m = report.moves[index];
        m.start_s = piece.start_time_s;
        m.peak_mm_s = pts.peak_mm_s;
        next.facts.feed_mm_s = m.feed_mm_s;
        next.facts.arc = piece.segment.shape == SegmentShape::arc;
        next.facts.limit_mm_s =
            m.feed_mm_s > 0 ? segment_limits(piece.segment, machine, m.feed_mm_s, kind).max_velocity : 0.0;
        next.facts.peak_mm_s = pts.peak_mm_s;
        next.facts.start_mm_s = pts.start_mm_s;
        next.facts.end_mm_s = pts.end_mm_s;
        next.facts.start = start;
        next.points.push_back(report.vertices.back());
        next.points.insert(next.points.end(), pts.points.begin() + 1, pts.points.end());
        open = std::move(next);
    }

    void add_piece(const TrajectoryPiece& piece) {
        peaks.add(piece);
        sampler.add(piece);
        if (piece.kind == PieceKind::motion && piece.continues_move && open) {
            // More of the open move (a trapezoid arc planned in pieces).
            const report_detail::PiecePoints pts = report_detail::piece_points(piece, options.arc_step_deg);
            open->points.insert(open->points.end(), pts.points.begin() + 1, pts.points.end());
            ReportMove& m = report.moves[open->index];
            m.peak_mm_s = std::max(m.peak_mm_s, pts.peak_mm_s);
            open->facts.peak_mm_s = std::max(open->facts.peak_mm_s, pts.peak_mm_s);
            open->facts.end_mm_s = pts.end_mm_s;
            if (m.feed_mm_s > 0) {
                open->facts.limit_mm_s = std::max(
                    open->facts.limit_mm_s, segment_limits(piece.segment, machine, m.feed_mm_s, kind).max_velocity);
            }
        } else if (piece.kind == PieceKind::motion && !piece.blend) {
            main_piece(piece);
        } else if (piece.kind == PieceKind::motion) {
            boundary = Junction::corner;
            const report_detail::PiecePoints pts = report_detail::piece_points(piece, options.arc_step_deg);
            // The first transition after a main piece is that move's own corner; any later one
            // before the next main piece starts in the middle of a move it ate.
            if (run_blends.empty() && open) run_first_free = 1;
            run_blends.push_back({piece.where.line, piece.where.file_name(), pts.points.front(), piece.start_time_s});
            if (open) open->points.insert(open->points.end(), pts.points.begin() + 1, pts.points.end());
        } else if (piece.kind == PieceKind::dwell || piece.io.waits) {
            boundary = Junction::exact_stop;
        }
        time_s = piece.start_time_s + piece.duration_s;
        if (open && piece.kind == PieceKind::motion) report.moves[open->index].end_s = time_s;
    }

    ToolPathReport finish() {
        while (!awaiting.empty()) {
            if (awaiting.front() >= finalized) mark_consumed(awaiting.front());
            awaiting.pop_front();
        }
        close_open(Junction::exact_stop);
        finalize_before(report.moves.size());
        report.peaks = peaks.peaks();
        report.samples = sampler.finish();
        report.cycle_time_s = time_s;
        return std::move(report);
    }
};

ToolPathRecorder::ToolPathRecorder(const MachineConfig& machine, ProfileKind kind, ToolPathOptions options)
    : impl_(std::make_unique<Impl>(machine, kind, options)) {}
ToolPathRecorder::~ToolPathRecorder() = default;
ToolPathRecorder::ToolPathRecorder(ToolPathRecorder&&) noexcept = default;
ToolPathRecorder& ToolPathRecorder::operator=(ToolPathRecorder&&) noexcept = default;
void ToolPathRecorder::add_move(const Move& move) {
    impl_->add_move(move);
}
void ToolPathRecorder::add_piece(const TrajectoryPiece& piece) {
    impl_->add_piece(piece);
}
ToolPathReport ToolPathRecorder::finish() {
    return impl_->finish();
}

}  // namespace nckit
