#pragma once
// The state a restart rebuilds (docs/restart.md): what the moves before the target left behind
// (spindle, tool and coolant, the modal state, where the last motion ended and the side each
// axis came from), the approach back onto the path, and the targets a restart refuses. `nckit
// restart` writes it as a program; the LinuxCNC plug-in issues it as canonical calls when
// LinuxCNC runs a program from a line (docs/linuxcnc-plugin.md).
#include <array>
#include <optional>
#include <vector>

#include "nckit/core/axes.hpp"
#include "nckit/core/diagnostic.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/interp/modal_view.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

//! The spindle, tool and I/O state the events before the target left, which a restart program
//! must switch on again before it moves.
struct RestartIo {
    int tool_selected = 0;    //!< last T word, 0 for none
    int tool_in_spindle = 0;  //!< the T last put in by M6, 0 for none
    bool speed_set = false;   //!< an S word ran
    double speed = 0;         //!< rpm, or m/min under G96
    bool constant_surface_speed = false;
    double rpm_clamp = 0;       //!< G96's clamp (G50 S / D), rpm; 0 = none
    int spindle_mcode = 5;      //!< 3, 4 or 5
    double spindle_rpm = 0;     //!< the rpm the M3/M4 event carried
    bool mist = false;          //!< M7
    bool flood = false;         //!< M8
    std::vector<int> laser_on;  //!< laser on-codes in force (the machine's laser_on_mcodes)
};

//! How the tool comes back: retract, rapid over the point, take up backlash, feed down.
struct RestartApproach {
    Axis retract_axis = Axis::Z;
    double safe_mm = 0;                  //!< retract axis, machine coordinate
    AxisVector point;                    //!< where the target block starts, machine mm / deg
    std::array<int, axis_count> side{};  //!< +1 / -1: the direction the original path last moved each axis
    double takeup_mm = 0;                //!< how far before the point each axis turns
    double clearance_mm = 0;             //!< the retract axis's rapid stops this far before the point
    double feed_mm_min = 0;              //!< the last, fed move
    bool moves = false;                  //!< false when nothing moves from the target on
};

//! One straight move of the approach; `retract_axis_only`: only the retract axis moves in it
//! (the retract, the rapid down to the clearance, the feed onto the point), else only the others.
struct ApproachStep {
    Line line;
    bool retract_axis_only = false;
};

//! The approach from `from` (machine coordinates): retract to the safe height, rapid over the
//! point less the take-up on the side the path came from, rapid over the point, rapid down to
//! the clearance, feed onto the point; each step ends at rest (exact stop). `nckit restart` writes
//! these as blocks.
[[nodiscard]] std::vector<ApproachStep> approach_steps(const RestartApproach& a, const MachineConfig& machine,
                                                       const AxisVector& from);

//! Folds the moves before a restart target into what the restart must rebuild.
class RestartState {
public:
    RestartState(const MachineConfig& machine, const ModalView& start) : machine_(&machine), modes_(start) {}

    //! One move before the target, made under `view` (the modes of its block).
    void note(const Move& move, const ModalView& view);

    //! Why the target, whose first move is `target` under `view`, cannot be restarted: inside
    //! cutter compensation (`restart-cutter-comp`) or in the middle of a thread pass
    //! (`restart-mid-thread`, naming the pass's first block). Nothing when it can.
    [[nodiscard]] std::optional<Diagnostic> refuse(const Move& target, const ModalView& view) const;

    //! How the tool comes back to where `target` starts (the end of the last motion before it).
    [[nodiscard]] RestartApproach approach(const Move& target) const;

    [[nodiscard]] const RestartIo& io() const { return io_; }
    //! The modal state in force before the target block.
    [[nodiscard]] const ModalView& modes() const { return modes_; }

private:
    const MachineConfig* machine_;
    ModalView modes_;
    RestartIo io_;
    std::optional<AxisVector> position_;  // where the last motion before the target ended
    std::array<int, axis_count> side_{};
    bool compensating_ = false;         // the last move was made under G41/G42
    std::optional<Move> thread_start_;  // first move of the run of G32/G33 moves just made
};

}  // namespace nckit
