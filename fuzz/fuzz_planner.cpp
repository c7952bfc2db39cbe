// The planner checks its own invariants on programs built from the input: up to 48 moves
// (rapids, feeds, arcs by radius, dwells, exact stops) with coordinates inside the travel. The
// trajectory must have a finite duration, keep every sampled |v|, |a| and (S-curve) |j| of every
// axis within the machine's limits, and end where the last move ends.
#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "fuzz_support.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/plan/planner.hpp"

namespace {

//! Reads the input a byte at a time; zeros once it is used up.
struct Bytes {
    const unsigned char* data;
    std::size_t size;
    std::size_t at = 0;
    unsigned next() { return at < size ? data[at++] : 0u; }
    double coordinate() { return (static_cast<double>(next()) - 127.5) * 0.8; }  // -102 .. 102 mm
};

std::string program_from(Bytes& in) {
    std::string text = in.next() & 1 ? "G64 P0.05\n" : "G61\n";
    const int moves = static_cast<int>(in.next() % 48) + 1;
    for (int i = 0; i < moves; ++i) {
        const double x = in.coordinate();
        const double y = in.coordinate();
        const double z = in.coordinate() / 4;
        const double feed = 1 + in.next() * 40.0;  // mm/min
        switch (in.next() % 6) {
            case 0:
                text += fmt::format("G0 X{:.3f} Y{:.3f} Z{:.3f}\n", x, y, z);
                break;
            case 1:
            case 2:
                text += fmt::format("G1 X{:.3f} Y{:.3f} Z{:.3f} F{:.1f}\n", x, y, z, feed);
                break;
            case 3:
                text += fmt::format("G{} X{:.3f} Y{:.3f} R{:.3f} F{:.1f}\n", in.next() & 1 ? 2 : 3, x, y,
                                    10 + in.next() * 0.5, feed);
                break;
            case 4:
                text += fmt::format("G4 P{}\n", in.next());
                break;
            default:
                text += fmt::format("G9 G1 X{:.3f} F{:.1f}\n", x, feed);
                break;
        }
    }
    return text + "M30\n";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
    using namespace nckit;
    Bytes in{data, size};
    MachineConfig machine = default_mill();
    machine.profile = in.next() & 1 ? ProfileKind::trapezoid : ProfileKind::scurve;
    std::vector<Move> moves;
    Interpreter interpreter(machine, ProgramSource::from_string(program_from(in), "fuzz.nc"));
    for (;;) {
        InterpResult result = interpreter.next();
        if (std::holds_alternative<Diagnostic>(result)) return 0;  // an arc off its circle, ...
        if (std::holds_alternative<ProgramEnd>(result)) break;
        moves.push_back(std::get<Move>(std::move(result)));
    }
    PlanResult plan = plan_moves(moves, machine);
    if (!plan.diagnostics.empty()) return 0;
    const double duration = plan.trajectory.duration_s();
    fuzz::require(std::isfinite(duration) && duration >= 0, "the cycle time is not finite");
    constexpr double rel = 1e-6;
    const bool jerk_limited = machine.profile == ProfileKind::scurve;
    for (const TrajectoryPiece& piece : plan.trajectory.pieces) {
        fuzz::require(std::isfinite(piece.duration_s) && piece.duration_s >= 0, "a piece's duration is not finite");
        for (int k = 0; k <= 16; ++k) {
            const TrajectorySample s = sample(piece, piece.start_time_s + piece.duration_s * k / 16.0);
            for (const AxisConfig& axis : machine.axes) {
                const std::size_t i = index(axis.axis);
                fuzz::require(std::abs(s.velocity[i]) <= axis.max_velocity * (1 + rel), "an axis exceeds its velocity");
                fuzz::require(std::abs(s.acceleration[i]) <= axis.max_acceleration * (1 + rel),
                              "an axis exceeds its acceleration");
                if (jerk_limited) {
                    fuzz::require(std::abs(s.jerk[i]) <= axis.max_jerk * (1 + rel), "an axis exceeds its jerk");
                }
            }
        }
    }
    // The end: where the last motion move ends.
    const AxisVector* last_end = nullptr;
    for (const Move& move : moves) {
        if (const auto* line = std::get_if<Line>(&move.what)) last_end = &line->to;
        if (const auto* arc = std::get_if<Arc>(&move.what)) last_end = &arc->to;
    }
    if (last_end != nullptr && !plan.trajectory.pieces.empty()) {
        const TrajectorySample end = plan.trajectory.sample(duration);
        for (const AxisConfig& axis : machine.axes) {
            const std::size_t i = index(axis.axis);
            fuzz::require(std::abs(end.position[i] - (*last_end)[i]) <= 1e-6, "the trajectory ends off the last move");
        }
    }
    return 0;
}
