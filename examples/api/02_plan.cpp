// 02: from moves to a trajectory.
//
// The planner takes the interpreter's moves one at a time (push), looks ahead over them, and
// hands out TrajectoryPieces (pop) as soon as their timing is final. A piece is exact: sample()
// gives every axis's position, velocity, acceleration and jerk at any time, within the machine's
// limits. Here the pieces are collected into a Trajectory and sampled every 2 ms.
#include <cstdio>
#include <variant>

#include "nckit/core/machine.hpp"
#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/plan/planner.hpp"
#include "nckit/plan/trajectory.hpp"

constexpr const char* program = R"nc(G21 G90 G17 G94
G0 X0 Y0 Z5
G1 Z-1 F300
G1 X10 F600
G3 X15 Y5 R5
G1 Y10
G1 X0
G1 Y0
G0 Z5
M30
)nc";

int main() {
    const nckit::MachineConfig machine = nckit::default_mill();  // 100 mm/s, 500 mm/s², S-curve
    nckit::Interpreter interpreter(machine, nckit::ProgramSource::from_string(program, "outline.nc"));
    nckit::Planner planner(machine);
    nckit::Trajectory trajectory;

    // The streaming loop: memory stays bounded however long the program is.
    nckit::TrajectoryPiece piece;
    for (;;) {
        nckit::InterpResult result = interpreter.next();
        if (std::holds_alternative<nckit::ProgramEnd>(result)) break;
        if (const auto* error = std::get_if<nckit::Diagnostic>(&result)) {
            std::fprintf(stderr, "%s\n", nckit::format_diagnostic(*error).c_str());
            return 2;
        }
        planner.push(std::get<nckit::Move>(result));
        while (planner.pop(piece)) trajectory.pieces.push_back(piece);
    }
    planner.finish();  // the end of the program: the last pieces come to rest
    while (planner.pop(piece)) trajectory.pieces.push_back(piece);
    // A move the planner cannot time (no feed, an axis the machine lacks) is a diagnostic too.
    for (const nckit::Diagnostic& error : planner.diagnostics()) {
        std::fprintf(stderr, "%s\n", nckit::format_diagnostic(error).c_str());
        return 2;
    }

    std::printf("cycle time: %.6f s\npieces: %zu\n", trajectory.duration_s(), trajectory.pieces.size());
    std::printf("t_s,x_mm,y_mm,z_mm,vx_mm_s,vy_mm_s,vz_mm_s\n");
    const double period_s = 0.002;
    const auto samples = static_cast<long>(trajectory.duration_s() / period_s);
    for (long i = 0; i <= samples; ++i) {
        const double t = static_cast<double>(i) * period_s;
        const nckit::TrajectorySample s = trajectory.sample(t);
        using nckit::Axis;
        std::printf("%.3f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", t, s.position[Axis::X], s.position[Axis::Y],
                    s.position[Axis::Z], s.velocity[Axis::X], s.velocity[Axis::Y], s.velocity[Axis::Z]);
    }
    return 0;
}
