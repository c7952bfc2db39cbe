// Machine TOML: every file is either a machine whose limits are finite, positive and plausible
// or FILE:LINE:COL diagnostics; never a crash.
#include <cmath>

#include "fuzz_support.hpp"
#include "nckit/core/machine.hpp"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
    using namespace nckit;
    if (size > 64 * 1024) return 0;
    Result<MachineConfig> machine = parse_machine_config(fuzz::text_of(data, size), "fuzz.toml");
    if (!machine) {
        fuzz::require(!machine.diagnostics().empty(), "a refused machine without a diagnostic");
        return 0;
    }
    fuzz::require(!machine->axes.empty(), "a machine without axes");
    for (const AxisConfig& axis : machine->axes) {
        for (double limit : {axis.max_velocity, axis.max_acceleration, axis.max_jerk, axis.steps_per_unit}) {
            fuzz::require(std::isfinite(limit) && limit > 0, "an axis limit that is not finite and positive");
            fuzz::require(limit >= 1e-3 && limit <= 1e12, "an implausible axis limit was accepted");
        }
        fuzz::require(axis.min < axis.max, "travel min >= max accepted");
    }
    fuzz::require(machine->servo_period_s > 0 && machine->servo_period_s <= 1, "implausible servo period");
    return 0;
}
