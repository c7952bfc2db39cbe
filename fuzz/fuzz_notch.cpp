// The notch job: a program on the notching machine through nckit notch's rewrite, planning and
// speed measurement. Every cut it reports has finite figures.
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "fuzz_support.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/process/notch/notch.hpp"

namespace {
nckit::MachineConfig notcher() {
    nckit::MachineConfig machine = nckit::default_mill();
    machine.laser_on_mcodes = {27};
    machine.laser_off_mcodes = {28, 128};
    machine.exact_stop_mcodes = {27, 28};
    return machine;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
    using namespace nckit;
    if (size > 8 * 1024) return 0;
    static const MachineConfig machine = notcher();
    InterpreterOptions options;
    options.max_blocks = 2000;
    Interpreter interpreter(machine, ProgramSource::from_string(std::string(fuzz::text_of(data, size)), "fuzz.nc"),
                            options);
    std::vector<Move> moves;
    for (;;) {
        InterpResult result = interpreter.next();
        if (!std::holds_alternative<Move>(result)) {
            if (std::holds_alternative<Diagnostic>(result)) return 0;
            break;
        }
        moves.push_back(std::get<Move>(std::move(result)));
        if (moves.size() > 64) return 0;
    }
    NotchOptions notch_options;
    Result<NotchJob> job = notch_program(moves, machine, "fuzz.nc", notch_options);
    if (!job) return 0;
    for (const NotchCut& cut : job->cuts) {
        for (const CutSpeed* speed : {&cut.before, &cut.after}) {
            fuzz::require(std::isfinite(speed->min_mm_min) && std::isfinite(speed->max_mm_min) &&
                              std::isfinite(speed->mean_mm_min),
                          "notch: a non-finite cut speed");
            fuzz::require(speed->profile.size() <= notch_options.profile_points, "notch: profile beyond its points");
        }
    }
    return 0;
}
