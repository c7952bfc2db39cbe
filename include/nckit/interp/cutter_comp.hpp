#pragma once
// Cutter radius compensation (G40/G41/G42): turns the programmed contour into the path of the
// tool's centre, r to the left or right of it. Moves go in as the interpreter makes them and
// come out compensated, one planar move late: where a move ends depends on the next one (the
// corner between them), so the last planar move and everything after it (moves off the plane,
// I/O, dwells) are held until the next planar move settles the corner.
#include <optional>
#include <string>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/core/vec2.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

namespace interp::comp {
struct Segment;
}

enum class CompSide { left, right };  // G41, G42: the tool's side looking along the motion

//! Why the compensated path cannot be made; `where` is the block it is about.
struct CompError {
    SourceLocation where;
    std::string code;     //!< "cutter-comp" or "cutter-gouge"
    std::string message;  //!< one sentence, lower case
};

class CutterCompensator {
public:
    //! `linuxcnc`: LinuxCNC's rules (docs/gcode-linuxcnc.md): a start-up move one radius long
    //! runs, a start-up on an arc runs, its corners (cutter_comp_linuxcnc.cpp) and its gouge
    //! checks, none beyond the corner.
    explicit CutterCompensator(CompStartup startup = CompStartup::type_b, bool linuxcnc = false)
        : startup_(startup), linuxcnc_(linuxcnc) {}

    //! Something is on, held, or the move after G40 is still to come: moves must go through add().
    [[nodiscard]] bool engaged() const { return mode_ != Mode::off; }
    //! G41/G42 is in effect (from the G41/G42 block to the G40 block).
    [[nodiscard]] bool on() const { return mode_ == Mode::waiting || mode_ == Mode::on; }
    //! The program's length units (G20/G21): LinuxCNC's gouge tolerances depend on them.
    void set_inch_units(bool inch) { inch_ = inch; }

    //! G41/G42 with radius r (> 0, mm): the next move in `plane` starts the compensation.
    //! `tip_shift` (a lathe tool's imaginary tip less its nose centre, mm) moves the compensated
    //! path, whose points are nose centres, onto the point the offsets measure.
    void start(CompSide side, double radius_mm, Plane plane, const AxisVector& tip_shift = AxisVector{});
    //! A new radius in offset mode with no G40 between (the Fanuc dialect: G41/G42 again on the
    //! same side, or a D word alone). The corner before the next planar move is still made with
    //! the old radius; that move ends with the new one, as Fanuc's controls change the offset
    //! vector over the block. `restart` (G41/G42 given again): the held move ends square to its
    //! own end, as before a G40, and the next move runs from there with no corner between them.
    //! That next move must be a line (checked in add()).
    void change_offset(double radius_mm, bool restart);
    //! G40: the held move ends r from the contour, perpendicular to its end, and goes out; the
    //! next move runs straight from there to its programmed end point (it must be a line).
    [[nodiscard]] std::optional<CompError> cancel(std::vector<Move>& out);
    //! One programmed move (or event): what is settled is appended to `out`.
    [[nodiscard]] std::optional<CompError> add(Move move, std::vector<Move>& out);
    //! LinuxCNC reads the machine's position back after a tool change: when the move after G40
    //! is still to come, the tool stays where the compensated path left it and that move runs
    //! from there as an ordinary one. Returns where the tool is then (nothing when no exit move
    //! waits), and no exit move waits any more.
    [[nodiscard]] std::optional<AxisVector> take_exit_position();
    //! End of program: as G40, then nothing is left waiting for an exit move.
    [[nodiscard]] std::optional<CompError> finish(std::vector<Move>& out);

private:
    enum class Mode { off, waiting, on, exiting };

    //! The held planar move as programmed in the plane (for the corner with the next move).
    struct Programmed {
        bool arc = false;
        double start[2]{};
        double end[2]{};
        double center[2]{};
        int turn = 0;          //!< arcs: +1 counter-clockwise (G3), -1 clockwise (G2)
        double sweep_rad = 0;  //!< arcs: programmed sweep, turns included
        bool rapid = false;

        //! The same element as the corner geometry takes it.
        [[nodiscard]] interp::comp::Segment segment() const;
        //! A straight move from `start` to `end` in the plane (the start-up, restart and contour lines).
        [[nodiscard]] static Programmed straight(Vec2 start, Vec2 end, bool rapid);
    };

    std::optional<CompError> start_up(Move move, std::vector<Move>& out);
    //! LinuxCNC's start-up on an arc (cutter_comp_arc_entry.cpp).
    std::optional<CompError> start_up_on_arc(Move move);
    std::optional<CompError> next_planar(Move move, std::vector<Move>& out);
    //! next_planar() in the LinuxCNC dialect: its corners, its gouge checks (cutter_comp_linuxcnc.cpp).
    std::optional<CompError> next_planar_linuxcnc(Move move, std::vector<Move>& out);
    std::optional<CompError> next_line_linuxcnc(Move move, std::vector<Move>& out);
    std::optional<CompError> next_arc_linuxcnc(Move move, std::vector<Move>& out);
    //! The held moves end at `to` in the plane and go out, after LinuxCNC's checks that the held
    //! move still runs forward; `where` is the block that settles it.
    std::optional<CompError> settle_linuxcnc(Vec2 to, const SourceLocation& where, std::vector<Move>& out);
    //! The held moves go out as they are (a corner that moves no end point).
    void pass_linuxcnc(std::vector<Move>& out);
    //! Holds the next planar move, from where the tool is to `end` in the plane.
    void hold_linuxcnc(Move move, Vec2 end);
    //! The path around an outside corner at the programmed point `corner`: an arc, or for a
    //! rapid a straight traverse; it ends at `to` and carries the next block's other axes.
    void go_around(const Move& next, Vec2 corner, Vec2 to, std::vector<Move>& out);
    //! next_planar() for the first planar move after change_offset() (cutter_comp_change.cpp).
    std::optional<CompError> next_with_new_offset(Move move, std::vector<Move>& out);
    void hold_restarted(Move move);
    std::optional<CompError> release(std::vector<Move>& out);  //!< held move keeps its end
    std::optional<CompError> check_held(const SourceLocation& next) const;
    std::optional<CompError> check_clearance(const interp::comp::Segment& element, const SourceLocation& where,
                                             const char* which) const;
    void hold_off_plane(Move move);
    //! Sends the held moves out, moved by the tip shift (the start-up move's start stays).
    void emit_held(std::vector<Move>& out);
    void emit(Move move, bool keep_start, std::vector<Move>& out) const;
    [[nodiscard]] bool moves_in_plane(const Move& move) const;
    [[nodiscard]] CompError error(const SourceLocation& where, std::string code, std::string message) const;

    CompStartup startup_;
    bool linuxcnc_ = false;
    Mode mode_ = Mode::off;
    int side_ = 1;  //!< +1 left (G41), -1 right (G42)
    double radius_mm_ = 0;
    Plane plane_ = Plane::xy;
    AxisVector tool_;                          //!< where the tool is after everything held (nose centre), mm / deg
    AxisVector tip_shift_;                     //!< imaginary tip less nose centre of a lathe tool, mm
    Programmed programmed_;                    //!< the held planar move as programmed
    Programmed before_;                        //!< the planar move before it, as programmed
    bool has_before_ = false;                  //!< before_ is a contour move (not the start-up move)
    bool held_start_up_ = false;               //!< the held move is the start-up block
    bool held_restart_ = false;                //!< the held move starts square to the move before (G41 again)
    double held_from_radius_mm_ = 0;           //!< the radius at the held move's start (differs after a change)
    std::optional<double> pending_radius_mm_;  //!< change_offset() waiting for the next planar move
    bool pending_restart_ = false;
    bool leave_from_tool_ = false;  //!< G41/G42 came before the exit move after G40
    bool inch_ = false;             //!< G20 is in effect
    // LinuxCNC dialect: where the held planar move starts, and whether its gouge check applies
    // (not after a start-up on an arc); a held line's direction as LinuxCNC checks it.
    Vec2 endpoint_;
    bool endpoint_valid_ = false;
    Vec2 held_direction_;
    std::vector<Move> held_;  //!< [0]: the held planar move, compensated; then what followed it
};

}  // namespace nckit
