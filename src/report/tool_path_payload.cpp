// The tool path as the page reads it: moves and vertices packed as deltas (most neighbours
// differ by little), the time samples as floats.
#include <algorithm>
#include <cmath>

#include "nckit/report/report_page.hpp"

namespace nckit {

namespace {

nlohmann::json machine_json(const MachineConfig& machine) {
    nlohmann::json axes = nlohmann::json::array();
    for (std::size_t i = 0; i < axis_count; ++i) {
        const AxisConfig* axis = machine.find(static_cast<Axis>(i));
        if (axis == nullptr) continue;
        axes.push_back({{"name", std::string(1, axis_letters[i])},
                        {"rotary", axis->kind == AxisKind::rotary},
                        {"max_velocity", axis->max_velocity},
                        {"max_acceleration", axis->max_acceleration},
                        {"max_jerk", axis->max_jerk}});
    }
    return {{"name", machine.name},
            {"profile", machine.profile == ProfileKind::scurve ? "scurve" : "trapezoid"},
            {"axes", axes}};
}

}  // namespace

void add_tool_path(Payload& payload, const ToolPathSection& section) {
    const ToolPathReport& r = section.report;
    nlohmann::json& h = payload.header["tool_path"];
    h["machine"] = machine_json(section.machine);
    h["cycle_time_s"] = r.cycle_time_s;
    h["moves"] = r.moves.size();
    h["vertices"] = r.vertices.size();
    h["points_before_decimation"] = r.points_before_decimation;
    h["tolerance_mm"] = r.tolerance_mm;
    h["files"] = r.files;

    nlohmann::json peaks = nlohmann::json::object();
    for (Axis axis : r.samples.axes) {
        peaks[std::string(1, letter(axis))] = {{"max_velocity", r.peaks.max_velocity[axis]},
                                               {"max_acceleration", r.peaks.max_acceleration[axis]},
                                               {"max_jerk", r.peaks.max_jerk[axis]}};
    }
    h["peaks"] = peaks;

    // Where the feed was not reached: counts and the time it cost against running at feed.
    nlohmann::json slow = nlohmann::json::object();
    for (const ReportMove& m : r.moves) {
        if (m.slowdown == Slowdown::none) continue;
        auto& entry = slow[std::string(slowdown_name(m.slowdown))];
        if (entry.is_null()) entry = {{"moves", 0}, {"time_s", 0.0}};
        entry["moves"] = entry["moves"].get<std::int64_t>() + 1;
        entry["time_s"] = entry["time_s"].get<double>() + (m.end_s - m.start_s);
    }
    h["slowdowns"] = slow;

    const std::size_t n = r.moves.size();
    std::vector<std::uint8_t> kind(n), reason(n);
    std::vector<std::int64_t> file(n), line(n), vertex_end(n);
    std::vector<double> start(n), end(n), feed(n), peak(n);
    for (std::size_t i = 0; i < n; ++i) {
        const ReportMove& m = r.moves[i];
        kind[i] = static_cast<std::uint8_t>(m.kind);
        reason[i] = static_cast<std::uint8_t>(m.slowdown);
        file[i] = m.file;
        line[i] = m.line;
        vertex_end[i] = m.vertex_end;
        start[i] = m.start_s;
        end[i] = m.end_s;
        feed[i] = m.feed_mm_s;
        peak[i] = m.peak_mm_s;
    }
    payload.add_u8("move_kind", kind);
    payload.add_u8("move_slowdown", reason);
    payload.add_delta_int("move_file", file);
    payload.add_delta_int("move_line", line);
    payload.add_delta_int("move_vertex_end", vertex_end);
    payload.add_delta("move_start_s", start, 1e-6);
    payload.add_delta("move_end_s", end, 1e-6);
    payload.add_delta("move_feed_mm_s", feed, 1e-4);
    payload.add_delta("move_peak_mm_s", peak, 1e-4);

    // Coordinates on a grid of a quarter of the tolerance: the rounding adds at most 0.22 of it.
    const double quantum_mm = r.tolerance_mm / 4;
    std::vector<double> xyz;
    xyz.reserve(r.vertices.size() * 3);
    std::vector<std::uint8_t> speed;
    speed.reserve(r.vertices.size());
    // The colour scale spans the cutting moves' speeds: rapids are drawn grey, and their far
    // higher speed would leave every cut at the bottom of the scale.
    double top = 0;
    std::size_t from = 0;
    for (const ReportMove& m : r.moves) {
        if (m.kind != ReportMoveKind::rapid) {
            for (std::size_t v = from; v <= m.vertex_end && v < r.vertices.size(); ++v) {
                top = std::max(top, r.vertices[v].speed_mm_s);
            }
        }
        from = m.vertex_end;
    }
    for (const ReportVertex& v : r.vertices) {
        xyz.insert(xyz.end(), {v.x_mm, v.y_mm, v.z_mm});
        const double level = top > 0 ? std::min(1.0, v.speed_mm_s / top) : 0.0;
        speed.push_back(static_cast<std::uint8_t>(std::lround(255.0 * level)));
    }
    h["top_speed_mm_s"] = top;
    payload.add_delta("vertex_xyz", xyz, quantum_mm);
    payload.add_u8("vertex_speed", speed);
    // A dot lies within a move's length of the vertex its move ends at: stored as its offset
    // from that vertex, which takes a byte or two where its own coordinates would take more.
    std::vector<double> offsets;
    offsets.reserve(r.point_places.size() * 3);
    std::vector<std::uint8_t> place_speed;
    place_speed.reserve(r.point_places.size());
    std::size_t dot = 0;
    std::uint32_t previous_end = 0;
    for (std::size_t i = 0; i < r.moves.size() && dot < r.point_places.size(); ++i) {
        const std::uint32_t move_end = r.moves[i].vertex_end;
        const bool is_dot = move_end == previous_end;
        previous_end = move_end;
        if (!is_dot) continue;
        const ReportVertex& v = r.point_places[dot++];
        const ReportVertex base = move_end < r.vertices.size() ? r.vertices[move_end] : ReportVertex{};
        // On the grid of the vertices, so that vertex + offset is the rounded place.
        auto q = [&](double x) { return std::llround(x / quantum_mm); };
        offsets.insert(offsets.end(), {static_cast<double>(q(v.x_mm) - q(base.x_mm)) * quantum_mm,
                                       static_cast<double>(q(v.y_mm) - q(base.y_mm)) * quantum_mm,
                                       static_cast<double>(q(v.z_mm) - q(base.z_mm)) * quantum_mm});
        const double level = top > 0 ? std::min(1.0, v.speed_mm_s / top) : 0.0;
        place_speed.push_back(static_cast<std::uint8_t>(std::lround(255.0 * level)));
    }
    payload.add_delta("point_offset_xyz", offsets, quantum_mm);
    payload.add_u8("point_speed", place_speed);

    const TimeSamples& s = r.samples;
    nlohmann::json axes = nlohmann::json::array();
    for (Axis axis : s.axes) axes.push_back(std::string(1, letter(axis)));
    h["samples"] = {{"period_s", s.period_s}, {"count", s.t_s.size()}, {"axes", axes}};
    payload.add_f64("sample_t", s.t_s);
    payload.add_f32("sample_speed", s.speed_mm_s);
    for (std::size_t k = 0; k < s.axes.size(); ++k) {
        const std::string a(1, letter(s.axes[k]));
        payload.add_f64("sample_pos_" + a, s.position[k]);
        payload.add_f32("sample_vel_" + a, s.velocity[k]);
        payload.add_f32("sample_acc_" + a, s.acceleration[k]);
        payload.add_f32("sample_jerk_" + a, s.jerk[k]);
    }
    for (std::size_t i = 0; i < section.sources.size(); ++i) {
        payload.add_text("source_" + std::to_string(i), section.sources[i]);
    }
}

}  // namespace nckit
