#include "executor.hpp"
#include "lathe_codes.hpp"

#include <cmath>

#include <fmt/format.h>

namespace nckit::interp {

namespace {
constexpr double mm_per_inch = 25.4;
constexpr double m_per_foot = 0.3048;
// Fanuc's least input increment: 0.001 mm, 0.0001 in, 0.001 deg.
constexpr double least_increment_metric = 0.001;
constexpr double least_increment_inch = 0.0001;
}  // namespace

Executor::Executor(const MachineConfig& machine, const InterpreterOptions& options)
    : machine_(machine),
      options_(options),
      tools_(machine.tools),
      comp_(machine.cutter_comp_startup, machine.dialect == Dialect::linuxcnc) {
    for (const AxisConfig& axis : machine.axes) {
        configured_.insert(axis.axis);
        rotary_[index(axis.axis)] = axis.kind == AxisKind::rotary;
        position_[axis.axis] = axis.home;
    }
    skip_position_ = position_;  // #5061- before any G31: where the machine starts
    modal_.diameter_mode = machine.diameter_mode;
    // A lathe (X and Z, no Y) starts in its only useful plane, as Fanuc lathe controls do.
    if (configured_.contains(Axis::X) && configured_.contains(Axis::Z) && !configured_.contains(Axis::Y)) {
        modal_.plane = Plane::zx;
    }
}

Diagnostic Executor::error(std::uint32_t column, std::string code, std::string message) const {
    return error_at(block_->at_column(column), std::move(code), std::move(message));
}

void Executor::warn(std::uint32_t column, std::string code, std::string message) const {
    if (!options_.on_warning) return;
    Diagnostic warning = error(column, std::move(code), std::move(message));
    warning.severity = Severity::warning;
    options_.on_warning(warning);
}

std::uint32_t Executor::column_of(char letter) const {
    const Word* word = words_.word(letter);
    return word != nullptr ? word->column : 1;
}

//! Where a motion error points: the block's G0..G33 word, or column 1 when the mode is modal.
std::uint32_t Executor::motion_column() const {
    std::uint32_t column = words_.group_column(ModalGroup::motion);
    return column != 0 ? column : 1;
}

void Executor::push(std::vector<Move>& out, decltype(Move::what) what) const {
    std::int64_t n = -1;
    if (const Word* word = words_.word('N')) n = static_cast<std::int64_t>(word->value);
    out.push_back(Move{std::move(what), block_->location, n});
}

bool Executor::axis_is_linear(Axis axis) const {
    return !rotary_[index(axis)];
}

double Executor::axis_value(Axis axis, const Word& word) const {
    bool linear = axis_is_linear(axis);
    double value = word.value;
    if (!word.has_decimal_point && machine_.decimal_point_input == DecimalPointInput::least_increment) {
        bool inch = modal_.length_factor_mm != 1.0;
        value *= (linear && inch) ? least_increment_inch : least_increment_metric;
    }
    if (linear) value *= modal_.length_factor_mm;
    if (axis == Axis::X && modal_.diameter_mode) value /= 2.0;
    return value;
}

double Executor::offset_value(const Word& word) const {
    double value = word.value;
    if (!word.has_decimal_point && machine_.decimal_point_input == DecimalPointInput::least_increment) {
        value *= modal_.length_factor_mm != 1.0 ? least_increment_inch : least_increment_metric;
    }
    return value * modal_.length_factor_mm;
}

std::optional<Diagnostic> Executor::run(const Block& block, std::vector<Move>& out, bool& program_end) {
    block_ = &block;
    if (auto e = collect_words(block, words_, machine_.gcode_system, machine_.dialect)) return e;
    if (auto e = check_words()) return e;
    warn_overridden_codes();
    if (auto e = check_cutter_comp()) return e;
    if (auto e = check_corner()) return e;

    // Everything below may change state, so work on copies and commit at the end: an error
    // leaves the interpreter as it was before the block.
    ModalState saved_modal = modal_;
    // Only G10, G28, G52, G92 and the like change offsets: most blocks need no copy of them.
    const bool may_set_offsets = words_.group(ModalGroup::non_modal) >= 0;
    std::optional<Offsets> saved_offsets;
    if (may_set_offsets) saved_offsets = offsets_;
    const bool corner_involved = corner_.has_value() || block.corner.letter != 0;
    std::optional<HeldCorner> saved_corner;
    if (corner_involved) saved_corner = corner_;
    std::optional<CutterCompensator> saved_comp;
    if (comp_.engaged() || comp_change_ || words_.group(ModalGroup::cutter_comp) >= 0) saved_comp = comp_;
    AxisVector saved_position = position_;
    const ProgramTransform saved_transform = transform_;
    const AxisVector saved_programmed = programmed_;
    std::size_t saved_size = out.size();
    auto fail = [&](Diagnostic d) {
        transform_ = saved_transform;
        programmed_ = saved_programmed;
        modal_ = saved_modal;
        if (saved_offsets) offsets_ = *saved_offsets;
        position_ = saved_position;
        if (saved_comp) comp_ = *saved_comp;
        if (corner_involved) corner_ = saved_corner;
        out.resize(saved_size);
        return std::optional<Diagnostic>(std::move(d));
    };

    if (auto e = set_modes()) return fail(*e);
    if (auto e = set_feed_and_spindle(out)) return fail(*e);
    if (auto e = emit_mcodes(out, false)) return fail(*e);
    if (auto e = dwell(out)) return fail(*e);
    if (auto e = set_coordinates()) return fail(*e);
    if (auto e = set_transform()) return fail(*e);
    if (auto e = transformed_move(out)) return fail(*e);
    if (auto e = emit_mcodes(out, true)) return fail(*e);
    program_end = words_.has_m(2) || words_.has_m(30);
    if (corner_involved) {
        if (auto e = apply_corner(out, saved_size, program_end)) return fail(*e);
    }
    if (auto e = compensate(out, saved_size, program_end)) return fail(*e);
    if (program_end) parts_done_ += 1;
    if (words_.mcode_count > 0) last_mcode_ = words_.mcodes[words_.mcode_count - 1].code;
    for (std::size_t i = saved_size; i < out.size(); ++i) elapsed_s_ += duration_s(out[i]);
    return std::nullopt;
}

std::optional<Diagnostic> Executor::set_modes() {
    auto code = [&](ModalGroup group) { return words_.group(group); };
    if (GCode c = code(ModalGroup::diameter); c >= 0) modal_.diameter_mode = c == g(7);
    if (GCode c = code(ModalGroup::units); c >= 0) modal_.length_factor_mm = c == g(20) ? mm_per_inch : 1.0;
    if (auto e = set_tool_length()) return e;
    if (GCode c = code(ModalGroup::return_mode); c >= 0) modal_.cycle.return_to_initial = c == g(98);
    if (GCode c = code(ModalGroup::arc_distance); c >= 0) modal_.arc_centers_absolute = c == g(90, 1);
    if (GCode c = code(ModalGroup::feed_mode); c >= 0) {
        modal_.feed_mode = c == g(95) ? FeedMode::per_revolution : FeedMode::per_minute;
    }
    if (GCode c = code(ModalGroup::plane); c >= 0) {
        modal_.plane = c == g(17) ? Plane::xy : c == g(18) ? Plane::zx : Plane::yz;
    }
    if (GCode c = code(ModalGroup::work_system); c >= 0) {
        modal_.work_system = static_cast<std::size_t>(c / 10 - 54);
    }
    if (GCode c = code(ModalGroup::path_control); c >= 0) {
        modal_.path.exact_stop = c == g(61);
        modal_.path.tolerance_mm = 0;
        if (c == g(64) && words_.has('P')) {
            const Word& p = *words_.word('P');
            if (p.value < 0) return error(p.column, "bad-value", "G64 P tolerance must not be negative");
            modal_.path.tolerance_mm = offset_value(p);
        }
    }
    if (GCode c = code(ModalGroup::distance); c >= 0) modal_.incremental = c == g(91);
    GCode c = code(ModalGroup::motion);
    // Fanuc: G80 alone brings back the group-01 code that was modal before the cycle.
    if (c < 0 && words_.cancels_cycle && is_drilling_cycle(modal_.motion)) c = modal_.motion_before_cycle;
    if (c >= 0) {
        // Any other group-1 code (G80 included) ends a drilling cycle and forgets its words.
        if (c != modal_.motion && is_drilling_cycle(modal_.motion) && !is_drilling_cycle(c)) {
            bool keep_return = modal_.cycle.return_to_initial;
            modal_.cycle = CycleState{};
            modal_.cycle.return_to_initial = keep_return;
        }
        if (is_drilling_cycle(c) && !is_drilling_cycle(modal_.motion)) modal_.motion_before_cycle = modal_.motion;
        modal_.motion = c;
    }
    return std::nullopt;
}

void Executor::warn_overridden_codes() const {
    if (words_.overridden.empty() || !options_.on_warning) return;
    for (const OverriddenGCode& o : words_.overridden) {
        const SourceLocation at = block_->at_column(o.column);
        if (!overrides_warned_.emplace(at.file_name(), at.line, at.column).second) continue;
        const std::string ignored = lathe_code_name(machine_.gcode_system, o.ignored);
        const std::string valid = lathe_code_name(machine_.gcode_system, o.valid);
        // A group-01 code beside a drilling cycle wins whichever comes first (it cancels the
        // cycle); within one group the code written last is valid.
        const bool cycle_beside_motion =
            is_drilling_cycle(o.ignored) && !is_drilling_cycle(o.valid) && o.valid != g(80);
        warn(o.column, "gcode-overridden",
             cycle_beside_motion
                 ? fmt::format("{} is ignored: {} in the same block cancels the drilling cycle", ignored, valid)
                 : fmt::format("{} is ignored: {} of the same modal group, written later in the "
                               "block, is valid",
                               ignored, valid));
    }
}

std::optional<Diagnostic> Executor::set_feed_and_spindle(std::vector<Move>& out) {
    // F is the lead under G32/G33 and the threading cycles, not the feed rate.
    const bool thread_lead = motion_ == g(32) || motion_ == g(33) || motion_ == lathe_threading_cycle ||
                             words_.group(ModalGroup::non_modal) == lathe_thread_repeat;
    if (const Word* f = words_.word('F'); f != nullptr && !thread_lead) {
        modal_.feed = f->value * modal_.length_factor_mm;
        modal_.feed_set = true;
    }
    SpindleState& spindle = modal_.spindle;
    if (GCode c = words_.group(ModalGroup::spindle_mode); c >= 0) spindle.constant_surface_speed = c == g(96);
    if (const Word* d = words_.word('D'); d != nullptr && words_.group(ModalGroup::spindle_mode) == g(96)) {
        if (d->value <= 0) return error(d->column, "bad-value", "G96 D (maximum rpm) must be positive");
        spindle.rpm_clamp = d->value;
    }
    bool clamp_block = words_.group(ModalGroup::non_modal) == g(50);
    if (const Word* s = words_.word('S')) {
        if (s->value < 0) return error(s->column, "bad-value", "spindle speed S must not be negative");
        if (clamp_block) {
            spindle.rpm_clamp = s->value;
        } else if (spindle.constant_surface_speed) {
            bool inch = modal_.length_factor_mm != 1.0;
            spindle.surface_speed_m_min = inch ? s->value * m_per_foot : s->value;
        } else {
            if (s->value > machine_.spindle.max_rpm) {
                return error(s->column, "spindle-limit",
                             fmt::format("S{} exceeds the spindle's {} rpm", s->value, machine_.spindle.max_rpm));
            }
            spindle.rpm = s->value;
        }
    }
    // Any change of the spindle's speed, mode or clamp is an event, with or without an S word:
    // the stages after this one (and `nckit expand`) know the spindle only from the events.
    bool mode_given = words_.group(ModalGroup::spindle_mode) >= 0;
    bool clamp_given = ((clamp_block && words_.has('S')) || words_.has('D')) && spindle.constant_surface_speed;
    if ((words_.has('S') && !clamp_block) || mode_given || clamp_given) {
        Io io{IoKind::spindle_speed, 0, spindle.constant_surface_speed ? spindle.surface_speed_m_min : spindle.rpm};
        io.constant_surface_speed = spindle.constant_surface_speed;
        io.rpm_clamp = spindle.rpm_clamp;
        push(out, io);
    }
    if (const Word* t = words_.word('T'); t != nullptr && machine_.gcode_system != GCodeSystem::none) {
        if (auto e = select_lathe_tool(*t)) return e;
        // The event keeps the T word as written (T0101 is 101): `nckit expand` writes it back.
        push(out, Io{IoKind::tool_select, static_cast<int>(t->value), 0});
    } else if (t != nullptr) {
        modal_.tool.selected = static_cast<int>(t->value);
        push(out, Io{IoKind::tool_select, modal_.tool.selected, 0});
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::emit_mcodes(std::vector<Move>& out, bool stopping) {
    // RS-274/NGC's order whatever the order written (`M8 M3` starts the spindle first): tool
    // change, spindle, coolant, the other codes; the stops after the motion.
    std::array<std::size_t, 5> order{};
    std::size_t count = 0;
    for (MGroup group : {MGroup::tool_change, MGroup::spindle, MGroup::coolant, MGroup::other, MGroup::stopping}) {
        for (std::size_t i = 0; i < words_.mcode_count; ++i) {
            if (m_group_of(words_.mcodes[i].code) == group) order[count++] = i;
        }
    }
    for (std::size_t k = 0; k < count; ++k) {
        int code = words_.mcodes[order[k]].code;
        bool is_stop = code == 0 || code == 1 || code == 2 || code == 30 || code == 60;
        if (is_stop != stopping) continue;
        Io io{IoKind::mcode, code, 0};
        io.waits = is_stop || code == 6 || machine_.is_exact_stop_mcode(code);
        SpindleState& spindle = modal_.spindle;
        if (code == 3 || code == 4) {
            spindle.direction = code == 3 ? 1 : -1;
            io.value = spindle.constant_surface_speed ? spindle.surface_speed_m_min : spindle.rpm;
            io.constant_surface_speed = spindle.constant_surface_speed;
            io.rpm_clamp = spindle.rpm_clamp;
        } else if (code == 5 || code == 2 || code == 30) {
            spindle.direction = 0;
        } else if (code == 6) {
            if (auto e = change_tool(out)) return e;
        }
        push(out, io);
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::dwell(std::vector<Move>& out) {
    if (words_.group(ModalGroup::non_modal) != g(4)) return std::nullopt;
    const Word* time = words_.has('P') ? words_.word('P') : words_.word('X');
    if (time == nullptr) {
        return error(words_.group_column(ModalGroup::non_modal), "missing-word", "G4 needs P (ms) or X (s)");
    }
    double seconds = time->value;
    // Fanuc: P is milliseconds (LinuxCNC reads seconds). X is seconds, but an X without a decimal
    // point counts least increments like any X word, and the time increment is 1 ms.
    bool milliseconds = time->letter == 'P' || (!time->has_decimal_point &&
                                                machine_.decimal_point_input == DecimalPointInput::least_increment);
    if (milliseconds) seconds /= 1000.0;
    if (seconds < 0) return error(time->column, "bad-value", "dwell time is negative");
    if (time->letter == 'P' && time->has_decimal_point && time->value != std::floor(time->value) &&
        options_.on_warning) {
        // A Fanuc control reads P as a whole count of milliseconds: P1.5 is most likely meant as
        // 1.5 seconds (LinuxCNC's reading), which is X1.5 or P1500.
        warn(time->column, "dwell-decimal",
             fmt::format("G4 P{}: P counts milliseconds, so this dwells {} ms; for {} s "
                         "write X{} or P{}",
                         time->value, time->value, time->value, time->value, time->value * 1000.0));
    }
    push(out, Dwell{seconds});
    return std::nullopt;
}

std::optional<Diagnostic> Executor::set_coordinates() {
    GCode code = words_.group(ModalGroup::non_modal);
    auto each_axis_word = [&](auto&& apply) {
        for (const AxisConfig& axis : machine_.axes) {
            if (const Word* w = words_.word(letter(axis.axis))) apply(axis.axis, axis_value(axis.axis, *w));
        }
    };
    if (is_lathe_offset_write()) {
        write_lathe_offset();
    } else if (code == g(10) && words_.word('L')->value != 2 && words_.word('L')->value != 20) {
        write_tool_table();
    } else if (code == g(10)) {
        const Word* p = words_.word('P');
        auto l = static_cast<int>(words_.word('L')->value);
        auto number = static_cast<int>(p->value);
        std::size_t system = number == 0 ? modal_.work_system : static_cast<std::size_t>(number - 1);
        AxisVector& work = offsets_.work[system];
        each_axis_word([&](Axis a, double v) {
            if (l == 20) {
                work[a] = position_[a] - offsets_.g92[a] - offsets_.g52[a] - modal_.tool_offset[a] - v;
            } else {
                work[a] = modal_.incremental ? work[a] + v : v;
            }
        });
    } else if (code == g(92) || (code == g(50) && block_has_axis_words())) {
        each_axis_word([&](Axis a, double v) {
            offsets_.g92[a] =
                position_[a] - offsets_.work[modal_.work_system][a] - offsets_.g52[a] - modal_.tool_offset[a] - v;
        });
    } else if (code == g(92, 1)) {
        offsets_.g92 = AxisVector{};
    } else if (code == g(52)) {
        each_axis_word([&](Axis a, double v) { offsets_.g52[a] = v; });
    }
    return std::nullopt;
}

}  // namespace nckit::interp
