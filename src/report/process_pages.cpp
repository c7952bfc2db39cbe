#include "nckit/report/process_pages.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

namespace nckit {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::string um(double value) {
    return fmt::format("{:.4g} µm", value);
}

}  // namespace

ReportPage piston_page(const cam::PistonJob& job, const PistonSimulation& simulation, const std::string& job_name) {
    const FtsSimulation& f = simulation.fts;
    ReportPage page;
    page.kind = "piston";
    page.title = fmt::format("nckit piston: {}", job_name);
    page.figures = {
        {"spindle",
         fmt::format("{:g} rpm, {} counts per turn ({:.6g} Hz control)", job.rpm, job.encoder_counts, f.tick_rate_hz)},
        {"uncompensated", fmt::format("P-V {}, RMS {}", um(f.uncompensated.pv_um), um(f.uncompensated.rms_um))},
        {"feedforward", fmt::format("P-V {}, RMS {}", um(f.feedforward.pv_um), um(f.feedforward.rms_um))},
        {"feedforward + learning", fmt::format("P-V {}, RMS {}", um(f.learning.pv_um), um(f.learning.rms_um))},
        {"learning settled", simulation.settled_turn < 0
                                 ? std::string("never within 1 µm per turn")
                                 : fmt::format("every turn within 1 µm from turn {}", simulation.settled_turn)},
        {"stroke used",
         fmt::format("{:.4f} of {:.4f} mm", simulation.fit.peak_displacement_mm, simulation.fit.limit_mm)},
    };

    // Polar section at the middle station: base circle for D/2, the deviation magnified so the
    // ovality fills about a fifth of the radius.
    const double z = job.z_mm[job.z_mm.size() / 2];
    double base = 0, dev_min = 1e300, dev_max = -1e300;
    std::vector<double> radius(361);
    for (int k = 0; k <= 360; ++k) radius[k] = job.profile(k, z);
    base = *std::max_element(radius.begin(), radius.end());
    for (double r : radius) dev_min = std::min(dev_min, r - base), dev_max = std::max(dev_max, r - base);
    const double spread = std::max(1e-9, dev_max - dev_min);
    const double magnify = std::pow(10.0, std::floor(std::log10(0.2 * base / spread)));
    ChartSeries section{"section (deviation × " + fmt::format("{:g}", magnify) + ")", {}, {}};
    ChartSeries circle{"D/2", {}, {}};
    for (int k = 0; k <= 360; ++k) {
        const double a = k * std::numbers::pi / 180.0;
        const double r = base + magnify * (radius[k] - base);
        section.x.push_back(r * std::cos(a));
        section.y.push_back(r * std::sin(a));
        circle.x.push_back(base * std::cos(a));
        circle.y.push_back(base * std::sin(a));
    }
    page.charts.push_back(
        {fmt::format("section at Z {:g} mm, to scale with the deviation from D/2 magnified {:g}×", z, magnify),
         "mm",
         "mm",
         true,
         {circle, section},
         {}});

    ReportChart turns{"peak to valley of the error in each turn (turn 0 is the first air turn)",
                      "turn",
                      "µm (log)",
                      false,
                      {},
                      {{"1 µm goal", 1.0}}};
    turns.log_y = true;
    for (const auto& [name, run] :
         {std::pair{"uncompensated", &f.uncompensated}, std::pair{"feedforward", &f.feedforward},
          std::pair{"feedforward + learning", &f.learning}}) {
        ChartSeries s{name, {}, {}};
        for (std::size_t i = 0; i < run->turn_pv_um.size(); ++i) {
            s.x.push_back(static_cast<double>(i));
            s.y.push_back(std::max(run->turn_pv_um[i], 1e-6));
        }
        turns.series.push_back(std::move(s));
    }
    page.charts.push_back(std::move(turns));
    return page;
}

ReportPage crosshatch_page(const CrosshatchPlan& plan, const CrosshatchScan& scan, const std::string& job_name) {
    const CrosshatchJob& job = plan.job;
    ReportPage page;
    page.kind = "crosshatch";
    page.title = fmt::format("nckit crosshatch: {}", job_name);
    auto timer = [](const MotorDrive& d) {
        return fmt::format("{:.6g} steps/s wanted, divisor {} gives {:.6g} steps/s ({:+.4f} %)", d.timer.wanted_hz,
                           d.timer.divisor, d.timer.rate_hz, d.timer.speed_error * 100);
    };
    page.figures = {
        {"bore", fmt::format("D {} mm × H {} mm, {} heads, {} lines per length", job.bore_diameter_mm,
                             job.bore_length_mm, job.heads, job.lines_per_length)},
        {"feed", fmt::format("{:.6g} mm/min: {}", plan.feed_mm_min, timer(plan.feed))},
        {"rotation", fmt::format("{:.6g} rpm: {}", plan.rotation_rpm, timer(plan.rotation))},
        {"crosshatch angle", fmt::format("{:.4f}° (tracks as stepped {:.4f}°), line spacing {:.4f} mm",
                                         plan.crosshatch_angle_deg, scan.track_angle_deg, plan.line_spacing_mm)},
        {"index", plan.special ? std::string("special angle: the pattern closes with no correction")
                               : fmt::format("correction {:+.6g}° ({} steps) after each cycle", plan.index_move_deg,
                                             plan.index_move_steps)},
        {"scan", fmt::format("{} cycles, {:.1f} s, closure error {:.3g} steps", job.cycles, scan.duration_s,
                             scan.closure_error_steps)},
    };
    // The net: circumference across (mm of wall), depth down; each track wrapped at 360°, the
    // pieces of one family in one series with gaps (NaN) between them.
    const double circumference_mm = std::numbers::pi * job.bore_diameter_mm;
    ChartSeries down{"into the bore", {}, {}}, up{"out of the bore", {}, {}};
    for (const CrosshatchTrack& t : scan.tracks) {
        ChartSeries& s = t.down ? down : up;
        const double a_low = std::min(t.start_deg, t.end_deg), a_high = std::max(t.start_deg, t.end_deg);
        const double span = t.end_deg - t.start_deg;
        auto z_at = [&](double a) {
            return span == 0 ? t.start_z_mm : t.start_z_mm + (a - t.start_deg) / span * (t.end_z_mm - t.start_z_mm);
        };
        for (double turn = std::floor(a_low / 360.0); turn * 360.0 < a_high || span == 0; turn += 1.0) {
            const double from = std::max(a_low, turn * 360.0), to = std::min(a_high, (turn + 1.0) * 360.0);
            s.x.insert(s.x.end(), {(from - turn * 360.0) / 360.0 * circumference_mm,
                                   (to - turn * 360.0) / 360.0 * circumference_mm, nan});
            s.y.insert(s.y.end(), {span == 0 ? t.start_z_mm : z_at(from), span == 0 ? t.end_z_mm : z_at(to), nan});
            if (span == 0) break;
        }
    }
    page.charts.push_back({"the bore unrolled: laser tracks over the wall (to scale)",
                           "along the circumference (mm)",
                           "depth Z (mm)",
                           true,
                           {down, up},
                           {}});
    return page;
}

ReportPage eccentric_page(const EccentricReport& report, const std::string& job_name) {
    const EccentricJob& job = report.job;
    ReportPage page;
    page.kind = "eccentric";
    page.title = fmt::format("nckit eccentric: {}", job_name);
    page.figures = {
        {"part", fmt::format("e {} mm, r {} mm, {} rpm, {} updates per turn", job.eccentricity_mm,
                             job.eccentric_radius_mm, job.rpm, report.updates_per_turn)},
        {"with feedforward", fmt::format("roundness {}, centre offset {}", um(report.compensated.roundness_um),
                                         um(report.compensated.center_offset_um))},
        {"without", fmt::format("roundness {}, centre offset {}", um(report.uncompensated.roundness_um),
                                um(report.uncompensated.center_offset_um))},
        {"highest rpm", fmt::format("{:.0f} rpm (by {})", std::floor(report.max_rpm), report.limited_by)},
        {"X diameters", fmt::format("{:.4f} .. {:.4f} mm", report.x_min_diameter_mm, report.x_max_diameter_mm)},
    };
    // The section in the part's frame: the tool at a(θ) from the spindle axis, the drawing's
    // circle of radius r about (e, 0).
    ChartSeries cut{"tool path a(θ) about the spindle axis", {}, {}}, drawing{"drawing: r about (e, 0)", {}, {}};
    ChartSeries axis{"spindle axis and eccentric centre", {0.0, job.eccentricity_mm}, {0.0, 0.0}};
    ChartSeries cam{"X radius a(θ)", {}, {}};
    for (int k = 0; k <= 360; ++k) {
        const double th = k * std::numbers::pi / 180.0;
        const double a = eccentric_cam(job, th).radius_mm;
        cut.x.push_back(a * std::cos(th));
        cut.y.push_back(a * std::sin(th));
        drawing.x.push_back(job.eccentricity_mm + job.eccentric_radius_mm * std::cos(th));
        drawing.y.push_back(job.eccentric_radius_mm * std::sin(th));
        cam.x.push_back(k);
        cam.y.push_back(eccentric_cam(job, th).radius_mm);
    }
    page.charts.push_back({"section (to scale)", "mm", "mm", true, {drawing, cut, axis}, {}});
    page.charts.push_back({"the X axis's cam against the spindle angle", "θ (deg)", "a (mm)", false, {cam}, {}});
    ReportChart offsets{
        "centre offset of the cut section", "run (0: without, 1: with feedforward)", "µm", false, {}, {}};
    offsets.series.push_back(
        {"centre offset", {0, 1}, {report.uncompensated.center_offset_um, report.compensated.center_offset_um}});
    offsets.series.push_back(
        {"roundness", {0, 1}, {report.uncompensated.roundness_um, report.compensated.roundness_um}});
    page.charts.push_back(std::move(offsets));
    return page;
}

ReportPage notch_page(const NotchJob& job, const std::string& program_name) {
    ReportPage page;
    page.kind = "notch";
    page.title = fmt::format("nckit notch: {}", program_name);
    page.figures.push_back({"cuts", std::to_string(job.cuts.size())});
    for (std::size_t i = 0; i < job.cuts.size(); ++i) {
        const NotchCut& cut = job.cuts[i];
        page.figures.push_back(
            {fmt::format("cut {} (line {})", i + 1, cut.where.line),
             fmt::format("{:.4f} mm at F{}: before min {:.1f} mm/min, after min {:.1f} mm/min; run-up "
                         "{:.4f} mm, overrun {:.4f} mm",
                         cut.length_mm, cut.feed_mm_min, cut.before.min_mm_min, cut.after.min_mm_min, cut.run_up_mm,
                         cut.overrun_mm)});
        if (i >= 6) continue;  // the figures list every cut; charts for the first six
        ReportChart chart{fmt::format("cut {} (line {}): planned speed over the cut", i + 1, cut.where.line),
                          cut.profile_axis ? fmt::format("{} (mm)", letter(*cut.profile_axis)) : "s (mm)",
                          "mm/min",
                          false,
                          {},
                          {{"F", cut.feed_mm_min}}};
        for (const auto& [name, speed] : {std::pair{"before", &cut.before}, std::pair{"after rewriting", &cut.after}}) {
            ChartSeries s{name, {}, {}};
            for (const auto& p : speed->profile) {
                s.x.push_back(p[0]);
                s.y.push_back(p[1]);
            }
            chart.series.push_back(std::move(s));
        }
        page.charts.push_back(std::move(chart));
    }
    return page;
}

}  // namespace nckit
