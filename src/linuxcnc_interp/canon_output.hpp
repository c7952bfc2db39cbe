#pragma once
// Hands nckit's moves to LinuxCNC as canonical calls (canon.hh). Moves carry absolute machine
// coordinates in mm; LinuxCNC's canon wants program coordinates in the program's units with the
// work offsets set beside them, so each call is preceded by whatever changed among units, G5x and
// G92 offsets, plane, feed mode and rate, path mode and spindle mode. The calls are not linked
// into the plug-in: they resolve against the host (rs274 or LinuxCNC's task).
#include <optional>

#include "nckit/core/machine.hpp"
#include "nckit/interp/modal_view.hpp"
#include "nckit/interp/move.hpp"

namespace nckit::lcnc {

//! What the interpreter loop does after a move's calls: go on reading, or let the motion queue
//! run empty first (a tool change: LinuxCNC's own interpreter stops reading there too).
enum class AfterMove { go_on, wait_for_motion };

class CanonOutput {
public:
    //! `exact_path`: continuous-path blocks (G64) go out as LinuxCNC's exact path mode, so its
    //! planner blends no corner and the machine stays on the programmed path.
    CanonOutput(const MachineConfig& machine, double g64_tolerance_mm, bool exact_path, bool line_comments);

    //! The calls for one move. `view` holds the modes of the block that made it.
    AfterMove emit(const Move& move, const ModalView& view);

    //! M2/M30 or the end of the file: spindle and coolant off, per-minute feed, PROGRAM_END.
    void emit_program_end();
    //! An operator message ((MSG, text), #3006): LinuxCNC's MESSAGE, shown by its GUI.
    void message(const std::string& text);

    [[nodiscard]] bool mist() const { return mist_; }
    [[nodiscard]] bool flood() const { return flood_; }
    [[nodiscard]] int spindle_direction() const { return spindle_direction_; }
    //! The work offset plus the G92 shift LinuxCNC was last given, mm / deg (its program
    //! coordinates are machine coordinates less this); nothing before the first move.
    [[nodiscard]] std::optional<AxisVector> offset_mm() const {
        if (!work_offset_ || !g92_offset_) return std::nullopt;
        return *work_offset_ + *g92_offset_;
    }

private:
    void set_frame(const ModalView& view);
    void set_path(const PathControl& path);
    void set_feed(const Feed& feed);
    void mark_line(const Move& move);
    void straight(const Line& line, int source_line);
    void arc(const Arc& arc, int source_line);
    void sync(const SyncMove& move, int source_line);
    AfterMove io(const Io& io);
    void spindle_speed(double value, bool constant_surface_speed, double rpm_clamp);

    //! A machine position in program coordinates and units, for axis `i`.
    [[nodiscard]] double program(std::size_t i, double machine_value) const;

    const MachineConfig& machine_;
    double g64_tolerance_mm_;
    bool exact_path_;
    bool line_comments_;

    // What LinuxCNC was last told; empty: not yet (everything goes out before the first move).
    std::optional<double> length_factor_mm_;
    std::optional<std::size_t> work_system_;
    std::optional<AxisVector> work_offset_;  // mm / deg
    std::optional<AxisVector> g92_offset_;   // G92 + G52, mm / deg
    std::optional<Plane> plane_;
    std::optional<FeedMode> feed_mode_;
    std::optional<double> feed_rate_;  // program units per minute or per revolution
    std::optional<PathControl> path_;
    std::optional<double> css_maximum_rpm_;  // 0: spindle in rpm (G97)
    std::optional<double> spindle_value_;    // rpm, or surface speed under G96
    std::uint32_t last_line_ = 0;
    int tool_ = 0;
    bool mist_ = false;
    bool flood_ = false;
    int spindle_direction_ = 0;
};

}  // namespace nckit::lcnc
