#include "nckit/core/machine.hpp"

namespace nckit {

namespace {

// A small hobby-to-light-industrial mill: values a stepper machine reaches comfortably, so
// programs checked against it are plausible on most real mills.
AxisConfig default_linear_axis(Axis axis) {
    AxisConfig config;
    config.axis = axis;
    config.kind = AxisKind::linear;
    config.max_velocity = 100.0;      // mm/s (6 m/min)
    config.max_acceleration = 500.0;  // mm/s^2
    config.max_jerk = 50000.0;        // mm/s^3
    config.min = -500.0;              // mm
    config.max = 500.0;               // mm
    config.steps_per_unit = 800.0;    // steps/mm: 200-step motor, 16x microstep, 4 mm pitch
    config.backlash = 0.0;            // mm
    config.home = 0.0;                // mm
    return config;
}

}  // namespace

MachineConfig default_mill() {
    MachineConfig config;
    config.name = "default-mill";
    config.servo_period_s = 0.001;
    config.diameter_mode = false;
    config.decimal_point_input = DecimalPointInput::calculator;
    config.profile = ProfileKind::scurve;
    config.axes = {default_linear_axis(Axis::X), default_linear_axis(Axis::Y), default_linear_axis(Axis::Z)};
    config.spindle.max_rpm = 6000.0;
    config.spindle.encoder_counts = 4096;
    return config;
}

}  // namespace nckit
