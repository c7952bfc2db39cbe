// The unrolled bore as SVG: head angle across (the wall's circumference to scale), depth down,
// every laser track as straight lines wrapped at 360°: a diamond net when the pattern is right.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "nckit/process/crosshatch/crosshatch_scan.hpp"
#include "../svg_plot.hpp"

namespace nckit {

namespace {

constexpr double margin_left_px = 70;
constexpr double margin_top_px = 70;
constexpr double margin_right_px = 30;
constexpr double margin_bottom_px = 50;
constexpr double max_plot_width_px = 960;
constexpr double max_plot_height_px = 640;

struct Frame {
    double px_per_mm = 1;
    double width_mm = 0;   //!< circumference
    double height_mm = 0;  //!< stroke
    [[nodiscard]] double x(double angle_deg) const { return margin_left_px + angle_deg / 360.0 * width_mm * px_per_mm; }
    [[nodiscard]] double y(double z_mm) const { return margin_top_px - z_mm * px_per_mm; }
};

void draw_track(std::string& out, const Frame& frame, const CrosshatchTrack& track) {
    const double a_low = std::min(track.start_deg, track.end_deg);
    const double a_high = std::max(track.start_deg, track.end_deg);
    const double span = track.end_deg - track.start_deg;
    auto z_at = [&](double angle) {
        if (span == 0) return track.start_z_mm;
        return track.start_z_mm + (angle - track.start_deg) / span * (track.end_z_mm - track.start_z_mm);
    };
    const char* colour = track.down ? "#1f5fa8" : "#c8372d";
    if (span == 0) {
        const double a = std::fmod(std::fmod(track.start_deg, 360.0) + 360.0, 360.0);
        out += fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="{}"/>)", frame.x(a),
                           frame.y(track.start_z_mm), frame.x(a), frame.y(track.end_z_mm), colour);
        out += '\n';
        return;
    }
    // One line per turn of the head: the piece of the track between two multiples of 360°.
    for (double turn = std::floor(a_low / 360.0); turn * 360.0 < a_high; turn += 1.0) {
        const double from = std::max(a_low, turn * 360.0);
        const double to = std::min(a_high, (turn + 1.0) * 360.0);
        if (to - from < 1e-9) continue;
        out += fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="{}"/>)",
                           frame.x(from - turn * 360.0), frame.y(z_at(from)), frame.x(to - turn * 360.0),
                           frame.y(z_at(to)), colour);
        out += '\n';
    }
}

}  // namespace

std::string crosshatch_svg(const CrosshatchPlan& plan, const CrosshatchScan& scan) {
    const CrosshatchJob& job = plan.job;
    Frame frame;
    frame.width_mm = std::numbers::pi * job.bore_diameter_mm;
    frame.height_mm = scan.stroke_mm;
    frame.px_per_mm = std::min(max_plot_width_px / frame.width_mm, max_plot_height_px / frame.height_mm);
    const double plot_w = frame.width_mm * frame.px_per_mm;
    const double plot_h = frame.height_mm * frame.px_per_mm;
    const double width = margin_left_px + plot_w + margin_right_px;
    const double height = margin_top_px + plot_h + margin_bottom_px;

    std::string out = process_detail::svg_open(width, height);
    out += fmt::format(
        R"(<text x="{}" y="22" font-size="15">Crosshatch, bore unrolled: D {} mm, H {} mm, {} heads, N {}: angle {:.3f}°</text>)",
        margin_left_px, job.bore_diameter_mm, job.bore_length_mm, job.heads, job.lines_per_length,
        scan.track_angle_deg);
    out += '\n';
    out += fmt::format(
        R"(<text x="{}" y="42">rotation {:.6g} rpm, feed {:.6g} mm/min; index {:.6g}°: {} (move {:+.6g}°); closure {:.3g} steps. Blue: down, red: up.</text>)",
        margin_left_px, plan.rotation_rpm, plan.feed_mm_min, job.index_deg,
        plan.special ? "special angle" : "arbitrary angle", plan.index_move_deg, scan.closure_error_steps);
    out += '\n';

    // Axes: angle across every 30°, depth down at round steps, the bore wall as a frame.
    out += "<g stroke=\"#bbbbbb\" stroke-width=\"0.5\">\n";
    for (int angle = 0; angle <= 360; angle += 30) {
        out += fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}"/>)", frame.x(angle), frame.y(0),
                           frame.x(angle), frame.y(-frame.height_mm));
        out += '\n';
    }
    const double depth_step = process_detail::tick_step(frame.height_mm, 6);
    for (double depth = 0; depth <= frame.height_mm + 1e-9; depth += depth_step) {
        out += fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}"/>)", frame.x(0), frame.y(-depth),
                           frame.x(360), frame.y(-depth));
        out += '\n';
    }
    out += "</g>\n<g fill=\"#333333\">\n";
    for (int angle = 0; angle <= 360; angle += 30) {
        out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" text-anchor="middle">{}°</text>)", frame.x(angle),
                           frame.y(-frame.height_mm) + 18, angle);
        out += '\n';
    }
    for (double depth = 0; depth <= frame.height_mm + 1e-9; depth += depth_step) {
        out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" text-anchor="end">{:g} mm</text>)", frame.x(0) - 6,
                           frame.y(-depth) + 4, depth);
        out += '\n';
    }
    out += "</g>\n";
    out += fmt::format(R"(<rect x="{:.2f}" y="{:.2f}" width="{:.2f}" height="{:.2f}" fill="none" stroke="#333333"/>)",
                       frame.x(0), frame.y(0), plot_w, plot_h);
    out += "\n<g stroke-width=\"1\" fill=\"none\">\n";
    for (const CrosshatchTrack& track : scan.tracks) draw_track(out, frame, track);
    out += "</g>\n</svg>\n";
    return out;
}

}  // namespace nckit
