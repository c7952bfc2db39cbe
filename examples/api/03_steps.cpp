// 03: from a trajectory to motor steps.
//
// StepGenerator finds, for every axis, the exact instants the position crosses a half step
// ((k + ½) / steps_per_unit) and hands out StepEvents {t_ns, axis, direction} in time order.
// It streams like the planner: add() pieces as they come, pop() the events that are final.
#include <array>
#include <cstdint>
#include <cstdio>
#include <variant>

#include "nckit/core/machine.hpp"
#include "nckit/drive/step_generator.hpp"
#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/plan/planner.hpp"

// A short move, a half circle and back, with exact stops (G61) so every corner is reached:
// 800 steps/mm on the built-in mill.
constexpr const char* program = R"nc(G21 G90 G17 G94 G61
G1 X2 Y1 F600
G2 X4 Y1 R1
G1 X0 Y0
M30
)nc";

struct AxisTally {
    std::int64_t forward = 0;   // steps with direction +1
    std::int64_t backward = 0;  // steps with direction -1
    std::int64_t last_ns = -1;  // time of the axis's last step
};

int main() {
    const nckit::MachineConfig machine = nckit::default_mill();
    nckit::Interpreter interpreter(machine, nckit::ProgramSource::from_string(program, "steps.nc"));
    nckit::Planner planner(machine);
    nckit::StepGenerator steps(machine);

    std::array<AxisTally, 3> tally{};
    long printed = 0;
    auto drain_steps = [&] {
        nckit::StepEvent event;
        while (steps.pop(event)) {
            if (printed++ < 5) {  // the first few events, as `nckit steps --text` prints them
                std::printf("%lld %d %d\n", static_cast<long long>(event.t_ns), event.axis, event.direction);
            }
            AxisTally& axis = tally.at(event.axis);
            (event.direction > 0 ? axis.forward : axis.backward) += 1;
            axis.last_ns = event.t_ns;
        }
    };

    nckit::TrajectoryPiece piece;
    auto drain_pieces = [&] {
        while (planner.pop(piece)) {
            steps.add(piece);
            drain_steps();
        }
    };
    for (;;) {
        nckit::InterpResult result = interpreter.next();
        if (std::holds_alternative<nckit::ProgramEnd>(result)) break;
        if (const auto* error = std::get_if<nckit::Diagnostic>(&result)) {
            std::fprintf(stderr, "%s\n", nckit::format_diagnostic(*error).c_str());
            return 2;
        }
        planner.push(std::get<nckit::Move>(result));
        drain_pieces();
    }
    planner.finish();
    drain_pieces();
    if (!planner.diagnostics().empty()) return 2;
    steps.finish();  // no more pieces: the last events become final
    drain_steps();

    // The motor count always equals round(position × steps_per_unit): the program ends at
    // X0 Y0, so every axis made as many steps back as forward.
    for (std::size_t i = 0; i < machine.axes.size(); ++i) {
        std::printf("%c: +%lld -%lld count %lld last_ns %lld\n", nckit::letter(machine.axes[i].axis),
                    static_cast<long long>(tally[i].forward), static_cast<long long>(tally[i].backward),
                    static_cast<long long>(steps.commanded_count(i)), static_cast<long long>(tally[i].last_ns));
    }
    return 0;
}
