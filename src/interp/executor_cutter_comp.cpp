// G40/G41/G42 (and G41.1/G42.1) in the executor: the checks a block passes, the radius its D
// word gives, and the hand-over of the block's moves to the CutterCompensator, which holds one
// planar move back until the next one settles the corner between them.
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"

namespace nckit::interp {

namespace {

bool starts_comp(GCode code) {
    return code == g(41) || code == g(42) || code == g(41, 1) || code == g(42, 1);
}

Diagnostic to_diagnostic(const CompError& e) {
    return error_at(e.where, e.code, e.message);
}

//! Where a lathe tool's imaginary tip (the point its X and Z offsets measure) lies from its nose
//! centre, by Fanuc's tip orientation: X+ away from the spindle axis, Z+ away from the chuck.
//! 3 is an outside turning tool (tip below and towards the chuck), 2 a boring bar; 0 and 9 are
//! the nose centre itself.
AxisVector tip_shift(int orientation, double radius_mm) {
    static constexpr int x_side[10] = {0, 1, 1, -1, -1, 0, 1, 0, -1, 0};
    static constexpr int z_side[10] = {0, 1, -1, -1, 1, 1, 0, -1, 0, 0};
    AxisVector shift;
    if (orientation < 0 || orientation > 9) return shift;
    shift[Axis::X] = x_side[orientation] * radius_mm;
    shift[Axis::Z] = z_side[orientation] * radius_mm;
    return shift;
}

}  // namespace

bool Executor::block_starts_comp() const {
    return starts_comp(words_.group(ModalGroup::cutter_comp));
}

std::optional<double> Executor::tool_radius_mm(int d_number) const {
    // A lathe's offset memory holds every offset number: one never set has no nose radius.
    if (machine_.gcode_system != GCodeSystem::none && tools_.find(d_number) == nullptr) return 0.0;
    return tools_.radius_mm(d_number);
}

bool Executor::changes_offset_in_offset_mode(GCode code) const {
    // Fanuc's mills change the offset in offset mode; RS-274/NGC and LinuxCNC refuse G41/G42
    // while compensation is on and a D word without G41/G42. Lathes keep the G40-first rule.
    if (machine_.dialect != Dialect::fanuc || machine_.gcode_system != GCodeSystem::none) return false;
    if (code == g(41) || code == g(42)) return true;
    return code < 0 && words_.has('D') && words_.group(ModalGroup::spindle_mode) != g(96);
}

std::optional<Diagnostic> Executor::check_cutter_comp() {
    const GCode code = words_.group(ModalGroup::cutter_comp);
    const std::uint32_t code_column = words_.group_column(ModalGroup::cutter_comp);
    comp_change_ = false;
    if (modal_.cutter_comp != 0) {
        // What LinuxCNC refuses while compensation is on, and what would break the contour.
        auto refuse = [&](std::uint32_t column, const std::string& what) {
            return error(column, "cutter-comp", fmt::format("{} with cutter compensation on: give G40 first", what));
        };
        comp_change_ = changes_offset_in_offset_mode(code);
        if (starts_comp(code) && !comp_change_) return refuse(code_column, fmt::format("G{:g}", code / 10.0));
        if (GCode p = words_.group(ModalGroup::plane); p >= 0) {
            Plane plane = p == g(17) ? Plane::xy : p == g(18) ? Plane::zx : Plane::yz;
            if (plane != modal_.plane) return refuse(words_.group_column(ModalGroup::plane), "changing the plane");
        }
        const GCode non_modal = words_.group(ModalGroup::non_modal);
        const std::uint32_t nm_column = words_.group_column(ModalGroup::non_modal);
        if (non_modal == g(28) || non_modal == g(30)) return refuse(nm_column, fmt::format("G{}", non_modal / 10));
        if (non_modal == g(31)) return refuse(nm_column, "G31 probing");
        for (std::size_t i = 0; i < words_.mcode_count; ++i) {
            if (words_.mcodes[i].code == 6) return refuse(words_.mcodes[i].column, "M6 tool change");
        }
        if (is_drilling_cycle(motion_) && block_has_axis_words()) return refuse(motion_column(), "a drilling cycle");
        if (non_modal == g(53)) return refuse(nm_column, "G53");
        if (non_modal == g(92) || non_modal == g(92, 1) || non_modal == g(52) || non_modal == g(10) ||
            (non_modal == g(50) && block_has_axis_words())) {
            return refuse(nm_column, "changing coordinate offsets");
        }
        if (GCode w = words_.group(ModalGroup::work_system);
            w >= 0 && static_cast<std::size_t>(w / 10 - 54) != modal_.work_system) {
            return refuse(words_.group_column(ModalGroup::work_system), "changing the work coordinate system");
        }
    }
    if (comp_change_) return check_offset_change(code, code_column);
    if (!starts_comp(code)) return std::nullopt;

    comp_side_ = (code == g(41) || code == g(41, 1)) ? CompSide::left : CompSide::right;
    comp_tip_shift_ = AxisVector{};
    const Word* d = words_.word('D');
    if (code == g(41, 1) || code == g(42, 1)) {
        if (d == nullptr) {
            return error(code_column, "missing-word", fmt::format("G{:g} needs D, the tool diameter", code / 10.0));
        }
        comp_radius_mm_ = offset_value(*d) / 2.0;
    } else {
        int number = modal_.tool.d_number;
        if (d != nullptr) {
            if (d->value != std::floor(d->value) || d->value < 0 || d->value > 99999999) {
                return error(d->column, "bad-value", "D must be a tool offset number: a whole number, 0 or more");
            }
            number = static_cast<int>(d->value);
        }
        if (number == 0 && machine_.gcode_system != GCodeSystem::none) {
            // A lathe's T0100 (or T0000): offset 00 has no nose radius, so nothing is compensated.
            comp_radius_mm_ = 0;
            return std::nullopt;
        }
        if (number == 0) {
            return error(d != nullptr ? d->column : code_column, "cutter-comp",
                         fmt::format("G{:g} with D0: D0 is no offset, give the tool's offset number", code / 10.0));
        }
        if (auto e = read_comp_radius(number, d != nullptr ? d->column : code_column)) return e;
        const ToolEntry* entry = tools_.find(number);
        if (machine_.gcode_system != GCodeSystem::none && entry != nullptr) {
            comp_tip_shift_ = tip_shift(entry->orientation, std::abs(comp_radius_mm_));
        }
    }
    // A negative offset cuts on the other side, as on Fanuc and LinuxCNC controls.
    if (comp_radius_mm_ < 0) {
        comp_radius_mm_ = -comp_radius_mm_;
        comp_side_ = comp_side_ == CompSide::left ? CompSide::right : CompSide::left;
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::read_comp_radius(int number, std::uint32_t column) {
    auto radius = tool_radius_mm(number);
    if (!radius) {
        return error(column, "unknown-tool",
                     tools_.empty() ? fmt::format("D{} needs a tool table (--tools FILE or tools = \"FILE\")", number)
                                    : fmt::format("D{} has no entry in the tool table", number));
    }
    comp_radius_mm_ = *radius;
    return std::nullopt;
}

std::optional<Diagnostic> Executor::check_offset_change(GCode code, std::uint32_t code_column) {
    // G41/G42 again, or a D word alone, while compensation is on (Fanuc mills): the new offset
    // must keep the side the tool cuts on (changing sides in offset mode is not modelled).
    const Word* d = words_.word('D');
    const std::string what = starts_comp(code) ? fmt::format("G{:g}", code / 10.0) : std::string("D");
    const std::uint32_t column = d != nullptr ? d->column : code_column;
    const double radius_before_mm = comp_radius_mm_;
    int number = modal_.tool.d_number;
    if (d != nullptr) {
        if (d->value != std::floor(d->value) || d->value < 0 || d->value > 99999999) {
            return error(d->column, "bad-value", "D must be a tool offset number: a whole number, 0 or more");
        }
        number = static_cast<int>(d->value);
    }
    if (number == 0) {
        return error(column, "cutter-comp",
                     fmt::format("{} with D0 in offset mode: D0 is no offset, give G40 to end the compensation", what));
    }
    if (auto e = read_comp_radius(number, column)) return e;
    const bool left = starts_comp(code) ? code == g(41) : modal_.cutter_comp == 41;
    CompSide side = left ? CompSide::left : CompSide::right;
    if (comp_radius_mm_ < 0) side = side == CompSide::left ? CompSide::right : CompSide::left;
    comp_radius_mm_ = std::abs(comp_radius_mm_);
    if (side != comp_side_) {
        return error(starts_comp(code) ? code_column : column, "cutter-comp",
                     fmt::format("{} changes the side of cutter compensation in offset mode: give G40 first", what));
    }
    if (comp_radius_mm_ == 0 && comp_.on()) {
        return error(column, "cutter-comp",
                     fmt::format("D{} has radius 0: give G40 to end the compensation instead", number));
    }
    // A D repeated with its own value (posts that write D on every block) changes nothing.
    if (!starts_comp(code) && comp_radius_mm_ == radius_before_mm) comp_change_ = false;
    return std::nullopt;
}

std::optional<Diagnostic> Executor::compensate(std::vector<Move>& out, std::size_t first, bool program_end) {
    const GCode code = words_.group(ModalGroup::cutter_comp);
    if (code < 0 && !comp_.engaged() && !comp_change_) {
        if (program_end) modal_.cutter_comp = 0;
        return std::nullopt;
    }
    std::vector<Move> block_moves(std::make_move_iterator(out.begin() + static_cast<std::ptrdiff_t>(first)),
                                  std::make_move_iterator(out.end()));
    out.resize(first);
    comp_.set_inch_units(inch_units());
    if (code == g(40)) {
        modal_.cutter_comp = 0;
        if (auto e = comp_.cancel(out)) return to_diagnostic(*e);
    } else if (comp_change_) {
        // Fanuc: a new offset in offset mode (check_offset_change() kept the side).
        if (starts_comp(code)) modal_.cutter_comp = code / 10;
        if (comp_.on()) {
            comp_.change_offset(comp_radius_mm_, starts_comp(code));
        } else if (comp_radius_mm_ > 0) {
            comp_.start(comp_side_, comp_radius_mm_, modal_.plane);  // from a zero radius: a start-up
        }
    } else if (starts_comp(code)) {
        modal_.cutter_comp = code / 10;
        // A zero radius compensates nothing: the moves go out as programmed.
        if (comp_radius_mm_ > 0) {
            // The imaginary tip shift applies in the lathe plane only (G18), as on the controls.
            comp_.start(comp_side_, comp_radius_mm_, modal_.plane,
                        modal_.plane == Plane::zx ? comp_tip_shift_ : AxisVector{});
        }
    }
    for (Move& move : block_moves) {
        if (auto e = comp_.add(std::move(move), out)) return to_diagnostic(*e);
    }
    if (program_end) return end_program(out);
    return std::nullopt;
}

std::optional<Diagnostic> Executor::end_program(std::vector<Move>& out) {
    // M2/M30 and the end of the program reset to G40, as a control's reset does.
    modal_.cutter_comp = 0;
    if (auto e = comp_.finish(out)) return to_diagnostic(*e);
    return std::nullopt;
}

}  // namespace nckit::interp
