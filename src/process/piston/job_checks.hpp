#pragma once
// Private to nckit_cam: the checks of a piston job that need more than one key: the drawing's
// values along Z, the section it makes, and what that section asks of the fast tool servo.
#include <span>

#include <toml++/toml.h>

#include "job_functions.hpp"
#include "nckit/process/piston/piston_job.hpp"

namespace nckit::piston_detail {

//! D > 0 (and not absurd), 0 <= E < D, |E4| < D/2 at every station (reported where the table
//! writes the value) and on `grid` between them (reported at the key).
[[nodiscard]] bool check_drawing_values(const FunctionEntry& d, const FunctionEntry& e, const FunctionEntry& e4,
                                        std::span<const double> stations, std::span<const double> grid,
                                        ConfigSink& sink);

//! The radius stays finite and positive at every whole degree on `grid` (reported at the shape).
[[nodiscard]] bool check_section(const PistonProfile& profile, std::span<const double> grid,
                                 const toml::source_region& shape_where, ConfigSink& sink);

//! The oval's radial range fits the stroke (reported at the ovality), and the acceleration at
//! the job's rpm the servo's limit (reported at the rpm).
void check_servo_demand(const ProfileDemand& demand, double rpm, const FastServoSpec& servo,
                        const toml::source_region& ovality_where, const toml::source_region& rpm_where,
                        ConfigSink& sink);

}  // namespace nckit::piston_detail
