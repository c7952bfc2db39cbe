#include "job_checks.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include <fmt/format.h>

namespace nckit::piston_detail {

namespace {

//! mm: a larger diameter is a typing slip, not a piston.
constexpr double max_diameter_mm = 5000;

//! What a value must satisfy at Z; a reason when it does not.
using Rule = std::function<std::optional<std::string>(double z_mm, double value)>;

//! Checks `rule` at each station value of a table (reported where written), then on the fine
//! Z grid (reported at the key: a spline bulge or a formula).
bool check_function(const FunctionEntry& entry, std::string_view key, std::span<const double> stations,
                    std::span<const double> grid, const Rule& rule, ConfigSink& sink) {
    auto report = [&](const toml::source_region& where, double z, double value, const std::string& why) {
        sink.error(where, "config-value", fmt::format("'{}' is {} at Z {} mm: {}", key, value, z, why));
        return false;
    };
    if (entry.table != nullptr) {
        for (std::size_t i = 0; i < stations.size(); ++i) {
            const double value = entry.function->value(stations[i]);
            if (auto why = rule(stations[i], value)) {
                return report((*entry.table)[i].source(), stations[i], value, *why);
            }
        }
    }
    for (double z : grid) {
        const double value = entry.function->value(z);
        if (!std::isfinite(value)) return report(entry.where, z, value, "not a finite number");
        if (auto why = rule(z, value)) return report(entry.where, z, value, *why);
    }
    return true;
}

}  // namespace

bool check_drawing_values(const FunctionEntry& d, const FunctionEntry& e, const FunctionEntry& e4,
                          std::span<const double> stations, std::span<const double> grid, ConfigSink& sink) {
    const DrawingFunction& diameter = *d.function;
    const Rule diameter_rule = [](double, double v) -> std::optional<std::string> {
        if (!(v > 0)) return "a diameter must be positive";
        if (v > max_diameter_mm) {
            return fmt::format("more than {} mm is not a piston", max_diameter_mm);
        }
        return std::nullopt;
    };
    const Rule ovality_rule = [&](double z, double v) -> std::optional<std::string> {
        if (v < 0) return "the ovality (major minus minor diameter) must be zero or more";
        if (v >= diameter(z)) {
            return fmt::format("the ovality must be less than the major diameter {}", diameter(z));
        }
        return std::nullopt;
    };
    const Rule e4_rule = [&](double z, double v) -> std::optional<std::string> {
        if (std::abs(v) >= 0.5 * diameter(z)) {
            return fmt::format("'e4_mm' must stay below half the major diameter {}", diameter(z));
        }
        return std::nullopt;
    };
    // E and E4 are judged against D, so a bad D is reported alone.
    if (!check_function(d, "major_diameter_mm", stations, grid, diameter_rule, sink)) return false;
    return check_function(e, "ovality_mm", stations, grid, ovality_rule, sink) &&
           (!e4.function || check_function(e4, "e4_mm", stations, grid, e4_rule, sink));
}

//! The section stays a section: its radius finite and positive everywhere on the grid.
bool check_section(const PistonProfile& profile, std::span<const double> grid, const toml::source_region& shape_where,
                   ConfigSink& sink) {
    for (double z : grid) {
        for (int phi = 0; phi < 360; ++phi) {
            const double r = profile.radius_mm(phi, z);
            if (std::isfinite(r) && r > 0) continue;
            sink.error(shape_where, "config-value",
                       fmt::format("the section's radius is {} mm at Z {} mm, PHI {}°; it must "
                                   "be a positive number",
                                   r, z, phi));
            return false;
        }
    }
    return true;
}

//! The servo can follow the profile: the oval's radial range fits its stroke, and the
//! acceleration at the job's rpm its limit.
void check_servo_demand(const ProfileDemand& demand, double rpm, const FastServoSpec& servo,
                        const toml::source_region& ovality_where, const toml::source_region& rpm_where,
                        ConfigSink& sink) {
    if (demand.stroke_mm > servo.stroke_mm) {
        sink.error(ovality_where, "servo-stroke",
                   fmt::format("the profile needs {:.4f} mm of stroke (radial range over a turn) "
                               "at Z {} mm, more than the servo's 'stroke_mm' = {}",
                               demand.stroke_mm, demand.stroke_z_mm, servo.stroke_mm));
    }
    const double needed = demand.acceleration_mm_s2(rpm);
    if (needed > servo.max_acceleration_mm_s2()) {
        sink.error(
            rpm_where, "servo-acceleration",
            fmt::format("at {} rpm the profile needs {:.0f} mm/s² ({:.2f} g) at Z {} mm, "
                        "PHI {}°, more than the servo's 'max_acceleration_g' = {}; at most "
                        "{:.0f} rpm",
                        rpm, needed, needed / standard_gravity_mm_s2, demand.curvature_z_mm, demand.curvature_theta_deg,
                        servo.max_acceleration_g, std::floor(demand.max_rpm(servo.max_acceleration_mm_s2()))));
    }
}

}  // namespace nckit::piston_detail
