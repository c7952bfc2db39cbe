// The report's data: the recorder against the planner it listens to, the decimation against its
// tolerance, the slowdown rules on programs whose cause is known, the payload's encodings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <variant>

#include <zlib.h>

#include "../../src/report/polyline_decimate.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/plan/planner.hpp"
#include "nckit/report/payload.hpp"
#include "nckit/report/report_page.hpp"
#include "nckit/report/tool_path.hpp"

namespace nckit {
namespace {

struct Recorded {
    ToolPathReport report;
    double planned_cycle_s = 0;
    std::int64_t motion_moves = 0;
};

Recorded record(const std::string& program, ToolPathOptions options = {}) {
    const MachineConfig machine = default_mill();
    Interpreter interpreter(machine, ProgramSource::from_string(program, "test.ngc"));
    Planner planner(machine);
    ToolPathRecorder recorder(machine, machine.profile, options);
    Recorded out;
    TrajectoryPiece piece;
    for (;;) {
        InterpResult r = interpreter.next();
        if (std::holds_alternative<ProgramEnd>(r)) break;
        EXPECT_FALSE(std::holds_alternative<Diagnostic>(r));
        if (!std::holds_alternative<Move>(r)) break;
        const Move& move = std::get<Move>(r);
        if (std::holds_alternative<Line>(move.what) || std::holds_alternative<Arc>(move.what)) ++out.motion_moves;
        recorder.add_move(move);
        planner.push(move);
        while (planner.pop(piece)) {
            recorder.add_piece(piece);
            out.planned_cycle_s = piece.start_time_s + piece.duration_s;
        }
    }
    planner.finish();
    while (planner.pop(piece)) {
        recorder.add_piece(piece);
        out.planned_cycle_s = piece.start_time_s + piece.duration_s;
    }
    out.report = recorder.finish();
    return out;
}

TEST(ToolPathRecorder, EveryMoveKeepsItsLineAndTimesFollowThePlan) {
    const Recorded r =
        record("G0 X0 Y0 Z5\nG1 Z0 F300\nG1 X20 F1200\nG1 X20\nG3 X30 Y10 I0 J10\nG1 Y30\nG0 Z5\nG0 X0 Y0\nM30\n");
    ASSERT_EQ(static_cast<std::int64_t>(r.report.moves.size()), r.motion_moves);
    EXPECT_DOUBLE_EQ(r.report.cycle_time_s, r.planned_cycle_s);
    const std::uint32_t lines[] = {1, 2, 3, 4, 5, 6, 7, 8};
    for (std::size_t i = 0; i < r.report.moves.size(); ++i) {
        const ReportMove& m = r.report.moves[i];
        EXPECT_EQ(m.line, lines[i]);
        if (i > 0) {
            EXPECT_GE(m.vertex_end, r.report.moves[i - 1].vertex_end);
            EXPECT_GE(m.start_s, r.report.moves[i - 1].start_s);
        }
        EXPECT_LE(m.start_s, m.end_s);
    }
    // "G1 X20" to where the tool stands goes nowhere: a point, no vertex of its own.
    EXPECT_EQ(r.report.moves[3].vertex_end, r.report.moves[2].vertex_end);
    EXPECT_EQ(r.report.moves[4].kind, ReportMoveKind::arc);
    // The arc is drawn as an arc: several points, all on its circle (the planner's jerk-limited
    // join from the line eases into it within a few hundredths of a mm).
    EXPECT_GE(r.report.moves[4].vertex_end - r.report.moves[3].vertex_end, 5U);
    for (std::uint32_t v = r.report.moves[3].vertex_end + 1; v <= r.report.moves[4].vertex_end; ++v) {
        // Past Y10 the move's end eases into the next line (the join belongs to the move's end).
        const ReportVertex& p = r.report.vertices[v];
        if (p.y_mm <= 10) {
            EXPECT_NEAR(std::hypot(p.x_mm - 20, p.y_mm - 10), 10, 0.03);
        }
    }
    const ReportVertex& last = r.report.vertices.back();
    EXPECT_NEAR(last.x_mm, 0, 1e-9);
    EXPECT_NEAR(last.y_mm, 0, 1e-9);
    EXPECT_NEAR(last.z_mm, 5, 1e-9);
}

//! mm from p to the segment a-b in the XY plane.
double distance_to_segment(const ReportVertex& p, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((p.x_mm - ax) * dx + (p.y_mm - ay) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(ax + t * dx - p.x_mm, ay + t * dy - p.y_mm);
}

TEST(ToolPathRecorder, MovesEatenByTheirCornersAreDotsOnThePath) {
    // 0.14 mm and 0.1 mm moves between long ones under G64 P0.2: each corner's transition may
    // take half of the short move, so the two transitions take all of it and no piece of its
    // own comes. "G1 Y20" to where the tool stands goes nowhere. Every move with an empty
    // polyline has a place; an eaten one lies on its own programmed segment (where its two
    // transitions meet), at a time between its neighbours'.
    const Recorded r =
        record("G64 P0.2\nG1 X20 F1200\nG1 X20.1 Y0.1\nG1 X20.1 Y20\nG1 Y20\nG1 X20 Y20.1\nG1 X0 Y20.1\nM30\n");
    const auto& moves = r.report.moves;
    ASSERT_EQ(moves.size(), 6U);
    std::size_t dots = 0;
    for (std::size_t i = 0; i < moves.size(); ++i) {
        const std::uint32_t from = i > 0 ? moves[i - 1].vertex_end : 0;
        if (moves[i].vertex_end == from) ++dots;
        if (i > 0) {
            EXPECT_GE(moves[i].start_s, moves[i - 1].start_s) << "move " << i;
        }
    }
    ASSERT_EQ(r.report.point_places.size(), dots);
    // Moves 2 and 5 (0-based 1 and 4) are eaten, move 4 (0-based 3) goes nowhere.
    ASSERT_EQ(moves[1].vertex_end, moves[0].vertex_end);
    ASSERT_EQ(moves[3].vertex_end, moves[2].vertex_end);
    ASSERT_EQ(moves[4].vertex_end, moves[3].vertex_end);
    ASSERT_EQ(dots, 3U);
    EXPECT_LT(distance_to_segment(r.report.point_places[0], 20, 0, 20.1, 0.1), 1e-3);
    EXPECT_LT(distance_to_segment(r.report.point_places[2], 20.1, 20, 20, 20.1), 1e-3);
    // Not at either end of the eaten move: where the transitions meet is inside it.
    EXPECT_GT(std::hypot(r.report.point_places[0].x_mm - 20, r.report.point_places[0].y_mm), 0.01);
    EXPECT_GT(std::hypot(r.report.point_places[0].x_mm - 20.1, r.report.point_places[0].y_mm - 0.1), 0.01);
    EXPECT_GT(moves[1].start_s, moves[0].start_s);
    EXPECT_LT(moves[1].start_s, moves[2].start_s);
    EXPECT_GT(moves[1].peak_mm_s, 0);
    // The dot of the move that goes nowhere is its programmed point (the corner that the
    // path rounds within P0.2).
    EXPECT_NEAR(r.report.point_places[1].x_mm, 20.1, 1e-12);
    EXPECT_NEAR(r.report.point_places[1].y_mm, 20, 1e-12);
}

TEST(ToolPathRecorder, SlowdownCausesOnProgramsWhoseCauseIsKnown) {
    // A long move at a feed the axes reach: reached. A 0.1 mm move under G61 cannot reach
    // 6000 mm/min (100 mm/s needs some 10 mm): its end is an exact stop, slower than its start
    // (a corner blend).
    const Recorded r = record("G1 X100 F1200\nG61\nG1 Y0.1 F6000\nG64\nG1 X0 F12000\nG2 X-2 Y0.1 I-1 J0 F6000\nM30\n");
    ASSERT_EQ(r.report.moves.size(), 4U);
    EXPECT_EQ(r.report.moves[0].slowdown, Slowdown::none);
    EXPECT_EQ(r.report.moves[1].slowdown, Slowdown::exact_stop);
    // 12000 mm/min = 200 mm/s is above the X axis's 100 mm/s.
    EXPECT_EQ(r.report.moves[2].slowdown, Slowdown::axis_limit);
    // A 1 mm radius at 100 mm/s needs 10000 mm/s² of a 500 mm/s² axis.
    EXPECT_EQ(r.report.moves[3].slowdown, Slowdown::arc_limit);
}

TEST(SlowdownRules, TheSlowerEndDecides) {
    SlowdownFacts f;
    f.feed_mm_s = 20;
    f.limit_mm_s = 20;
    f.peak_mm_s = 10;
    f.start_mm_s = 0;
    f.end_mm_s = 5;
    f.start = Junction::corner;
    f.end = Junction::tangent;
    EXPECT_EQ(classify_slowdown(f), Slowdown::corner);
    f.start_mm_s = 8;
    EXPECT_EQ(classify_slowdown(f), Slowdown::short_segment);
    f.peak_mm_s = 19.9;
    EXPECT_EQ(classify_slowdown(f), Slowdown::none);
}

TEST(Decimate, RandomPolylinesStayWithinTolerance) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> noise(-0.004, 0.004);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<ReportVertex> points;
        const double bend = noise(random) * 50;
        for (int i = 0; i < 300; ++i) {
            const double s = i * 0.1;
            points.push_back({s, bend * s * s + noise(random), noise(random), 10 + noise(random) * 100});
        }
        const double tolerance = 0.01;
        const auto kept = report_detail::decimate(points, tolerance, 0.5);
        ASSERT_FALSE(kept.empty());
        EXPECT_EQ(kept.back().x_mm, points.back().x_mm);
        // Every dropped point lies within tolerance of the chord that replaced it.
        std::vector<ReportVertex> chain{points.front()};
        chain.insert(chain.end(), kept.begin(), kept.end());
        std::size_t c = 0;
        for (const ReportVertex& p : points) {
            while (c + 1 < chain.size() && chain[c + 1].x_mm < p.x_mm) ++c;
            if (c + 1 >= chain.size()) break;
            const ReportVertex& a = chain[c];
            const ReportVertex& b = chain[c + 1];
            const double dx = b.x_mm - a.x_mm, dy = b.y_mm - a.y_mm, dz = b.z_mm - a.z_mm;
            const double len2 = dx * dx + dy * dy + dz * dz;
            const double t =
                std::clamp(((p.x_mm - a.x_mm) * dx + (p.y_mm - a.y_mm) * dy + (p.z_mm - a.z_mm) * dz) / len2, 0.0, 1.0);
            const double d = std::hypot(p.x_mm - a.x_mm - t * dx, p.y_mm - a.y_mm - t * dy, p.z_mm - a.z_mm - t * dz);
            EXPECT_LE(d, tolerance + 1e-12);
        }
        EXPECT_LT(kept.size(), points.size());
    }
}

//! The page's decoder in C++ (web/src/payload.js does the same): zigzag varint deltas.
std::vector<double> decode_delta(const std::string& bytes, std::size_t count, double scale) {
    std::vector<double> out;
    std::size_t pos = 0;
    std::int64_t acc = 0;
    for (std::size_t i = 0; i < count; ++i) {
        std::uint64_t v = 0;
        int shift = 0;
        std::uint8_t b = 0;
        do {
            b = static_cast<std::uint8_t>(bytes[pos++]);
            v |= static_cast<std::uint64_t>(b & 0x7f) << shift;
            shift += 7;
        } while (b & 0x80);
        acc += static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
        out.push_back(static_cast<double>(acc) * scale);
    }
    return out;
}

TEST(Payload, DeltaBlobsRoundTripAndGzipInflates) {
    Payload p;
    std::vector<double> values{0, 1.25, -3.5, 1e6, -1e6, 2.5e9, 0.001};
    p.add_delta("v", values, 0.001);
    p.add_text("t", "G1 X1\n");
    const std::string packed = p.pack();
    std::uint32_t head_len = 0;
    std::memcpy(&head_len, packed.data(), 4);
    const auto header = nlohmann::json::parse(packed.substr(4, head_len));
    const std::size_t base = (4 + head_len + 7) / 8 * 8;
    const auto& e = header["blobs"]["v"];
    const auto decoded = decode_delta(
        packed.substr(base + e["offset"].get<std::size_t>(), e["length"].get<std::size_t>()), e["count"], e["scale"]);
    ASSERT_EQ(decoded.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) EXPECT_NEAR(decoded[i], values[i], 0.0005);
    EXPECT_EQ(packed.substr(base + header["blobs"]["t"]["offset"].get<std::size_t>(), 6), "G1 X1\n");

    const std::string zipped = gzip(packed);
    std::string inflated(packed.size(), '\0');
    z_stream z{};
    ASSERT_EQ(inflateInit2(&z, 15 + 16), Z_OK);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(zipped.data()));
    z.avail_in = static_cast<uInt>(zipped.size());
    z.next_out = reinterpret_cast<Bytef*>(inflated.data());
    z.avail_out = static_cast<uInt>(inflated.size());
    EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
    inflateEnd(&z);
    EXPECT_EQ(inflated, packed);
    EXPECT_EQ(base64("Man"), "TWFu");
    EXPECT_EQ(base64("Ma"), "TWE=");
    EXPECT_EQ(base64("M"), "TQ==");
}

TEST(ReportPage, IsOneFileWithItsScriptInline) {
    ReportPage page;
    page.title = "a <b> & c";
    page.kind = "program";
    const std::string html = render_report_html(page);
    EXPECT_NE(html.find("<title>a &lt;b&gt; &amp; c</title>"), std::string::npos);
    EXPECT_EQ(html.find("src=\"http"), std::string::npos);
    EXPECT_NE(html.find("id=\"nckit-data\""), std::string::npos);
    EXPECT_GT(html.size(), 100000U);  // three.js and uPlot are in it
}

TEST(ReportPage, DataComesInPiecesOfWholeBase64Quads) {
    // Random values barely compress: the base64 of this page is several MiB, so several pieces.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> value(0.0, 1.0);
    ChartSeries series;
    series.name = "noise";
    for (int i = 0; i < 400000; ++i) {
        series.x.push_back(i);
        series.y.push_back(value(random));
    }
    ReportPage page;
    page.title = "pieces";
    page.kind = "piston";
    page.charts.push_back({"noise", "i", "v", false, {series}, {}, false});
    const std::string html = render_report_html(page);
    const std::string open = "<script type=\"application/octet-stream\">";
    const std::string close = "</script><script>self.nckitData&&nckitData()</script>";
    std::string joined;
    std::size_t pieces = 0;
    for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at)) {
        at += open.size();
        const std::size_t end = html.find(close, at);
        ASSERT_NE(end, std::string::npos);
        const std::string piece = html.substr(at, end - at);
        EXPECT_EQ(piece.size() % 4, 0U);
        EXPECT_LE(piece.size(), std::size_t{1} << 20);
        joined += piece;
        ++pieces;
    }
    EXPECT_GE(pieces, 3U);
    // Every piece but the last is full, and together they are the whole data in order: the
    // first bytes are gzip's magic number 1f 8b (base64 "H4s").
    EXPECT_GT(joined.size(), (pieces - 1) * (std::size_t{1} << 20));
    EXPECT_EQ(joined.rfind("H4s", 0), 0U);
    EXPECT_EQ(joined.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/="),
              std::string::npos);
}

}  // namespace
}  // namespace nckit
