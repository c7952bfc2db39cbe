// The parameters LinuxCNC keeps current from the machine state (positions, offsets, tool, modes)
// and its persistent parameter file (`NUMBER<tab>VALUE` per line, as its .var files are).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "ngc_runner.hpp"

namespace nckit::interp::ngc {

namespace {

constexpr std::string_view axis_letters = "XYZABCUVW";  // LinuxCNC's parameter order
constexpr std::int64_t work_offset_base = 5221;         // G54 X; 20 per system
constexpr std::int64_t work_offset_stride = 20;
constexpr std::int64_t fanuc_systems = 6;  // G54-G59; G59.1-G59.3 are kept as values

//! Parameters LinuxCNC always writes to its file, whether or not the file had them.
bool required_in_file(std::int64_t n) {
    if (n >= 5161 && n <= 5166) return true;                 // G28
    if (n >= 5181 && n <= 5186) return true;                 // G30
    if (n >= 5210 && n <= 5216) return true;                 // G92: applied, X-C
    if (n == 5220) return true;                              // coordinate system
    if (n >= 5221 && n <= 5386) return (n - 5221) % 20 < 6;  // G54-G59.3 X Y Z A B C
    return false;
}

}  // namespace

double NgcRunner::to_program_units(double mm) const {
    return mm / executor_.modal_view().length_factor_mm;
}

std::optional<double> NgcRunner::axis_position(char letter) const {
    // While a lathe cycle reads its shape, LinuxCNC's position follows the shape.
    if (profile_ && letter == 'X') return profile_->at.imag();
    if (profile_ && letter == 'Z') return profile_->at.real();
    for (std::size_t i = 0; i < machine_.axes.size(); ++i) {
        if (axis_from_letter(letter) == machine_.axes[i].axis) {
            auto v = executor_.read_system(5001 + static_cast<std::int64_t>(i));
            if (v && !v->vacant) return v->number;
        }
    }
    return std::nullopt;
}

void NgcRunner::connect_live_parameters() {
    NgcParameters::Live live;
    live.numbered = [this](std::int64_t n) { return live_numbered(n); };
    live.named = [this](const std::string& name) { return live_named(name); };
    parameters_.set_live(std::move(live));
}

std::optional<double> NgcRunner::live_numbered(std::int64_t n) const {
    const ModalView view = executor_.modal_view();
    auto axis_of = [&](std::int64_t base) -> std::optional<Axis> {
        return axis_from_letter(axis_letters[static_cast<std::size_t>(n - base)]);
    };
    if (n >= 5161 && n <= 5169) {
        auto axis = axis_of(5161);
        const AxisConfig* config = axis ? machine_.find(*axis) : nullptr;
        if (config == nullptr) return std::nullopt;
        return config->kind == AxisKind::rotary ? config->home : to_program_units(config->home);
    }
    if (n >= 5211 && n <= 5219 && g92_kept_) return (*g92_kept_)[static_cast<std::size_t>(n - 5211)];
    if (n >= 5211 && n <= 5219) {
        auto axis = axis_of(5211);
        if (!axis) return std::nullopt;
        double mm = view.g92_offset[*axis] + view.g52_offset[*axis];
        const AxisConfig* config = machine_.find(*axis);
        return config != nullptr && config->kind == AxisKind::rotary ? mm : to_program_units(mm);
    }
    if (n == 5220) return static_cast<double>(view.work_system + 1);
    if (n >= work_offset_base && n < work_offset_base + fanuc_systems * work_offset_stride &&
        (n - work_offset_base) % work_offset_stride < 6) {
        auto v = executor_.read_system(n);
        if (v && !v->vacant) return v->number;
        return std::nullopt;
    }
    if (n == 5400) return static_cast<double>(view.tool);
    if (n >= 5420 && n <= 5428) return axis_position(axis_letters[static_cast<std::size_t>(n - 5420)]).value_or(0.0);
    return std::nullopt;
}

std::optional<double> NgcRunner::live_named(const std::string& name) const {
    const ModalView view = executor_.modal_view();
    if (name.size() == 2 && axis_letters.find(static_cast<char>(name[1] - 'a' + 'A')) != std::string_view::npos) {
        return axis_position(static_cast<char>(name[1] - 'a' + 'A')).value_or(0.0);
    }
    const bool metric = view.length_factor_mm == 1.0;
    if (name == "_current_tool" || name == "_selected_tool") return static_cast<double>(view.tool);
    if (name == "_current_pocket" || name == "_selected_pocket") return 0.0;
    if (name == "_metric") return metric ? 1.0 : 0.0;
    if (name == "_imperial") return metric ? 0.0 : 1.0;
    if (name == "_metric_machine") return 1.0;
    if (name == "_imperial_machine") return 0.0;
    if (name == "_feed") return view.feed / view.length_factor_mm;
    if (name == "_rpm") return view.spindle_rpm;
    if (name == "_motion_mode") return static_cast<double>(view.motion_code);
    if (name == "_plane") return view.plane == Plane::xy ? 170.0 : view.plane == Plane::zx ? 180.0 : 190.0;
    if (name == "_absolute") return view.incremental ? 0.0 : 1.0;
    if (name == "_incremental") return view.incremental ? 1.0 : 0.0;
    if (name == "_inverse_time") return 0.0;
    if (name == "_units_per_minute") return view.feed_mode == FeedMode::per_minute ? 1.0 : 0.0;
    if (name == "_units_per_rev") return view.feed_mode == FeedMode::per_revolution ? 1.0 : 0.0;
    if (name == "_coord_system") return 540.0 + 10.0 * static_cast<double>(view.work_system);
    if (name == "_spindle_on") return view.spindle_direction != 0 ? 1.0 : 0.0;
    if (name == "_spindle_cw") return view.spindle_direction >= 0 ? 1.0 : 0.0;
    if (name == "_call_level") return static_cast<double>(frames_.size() - 1);
    // LinuxCNC's preview and rs274 run outside the task: programs test this to skip probing.
    if (name == "_task") return 0.0;
    for (const char* zero : {"_mist", "_flood", "_speed_override", "_feed_override", "_adaptive_feed", "_feed_hold",
                             "_remap_level", "_line", "_tool_offset", "_retract_r_plane", "_retract_old_z"}) {
        if (name == zero) return 0.0;
    }
    if (name == "_ccomp") return 400.0;
    return std::nullopt;
}

std::string NgcRunner::substitute_parameters(const std::string& text) const {
    std::string out;
    std::string format = "{:.6f}";  // C's %lf
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '%' && i + 1 < text.size()) {
            char f = text[i + 1];
            if (f == 'd') {
                format = "{:.0f}";
                ++i;
                continue;
            }
            if (f == 'f') {
                format = "{:.4f}";
                ++i;
                continue;
            }
            if (f == '.' && i + 3 < text.size() + 1 && i + 2 < text.size() &&
                std::isdigit(static_cast<unsigned char>(text[i + 2])) && i + 3 < text.size() && text[i + 3] == 'f') {
                format = fmt::format("{{:.{}f}}", text[i + 2]);
                i += 3;
                continue;
            }
            out += c;
            continue;
        }
        if (c != '#') {
            out += c;
            continue;
        }
        std::optional<double> value;
        std::size_t j = i + 1;
        if (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) {
            std::int64_t n = 0;
            while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) && n < 100000) {
                n = n * 10 + (text[j++] - '0');
            }
            if (parameters_.in_range(n)) value = parameters_.read(n);
        } else if (j < text.size() && text[j] == '<') {
            std::size_t close = text.find('>', j);
            if (close == std::string::npos) {
                out += text.substr(i);
                break;
            }
            value = parameters_.read_named(normal_name(text.substr(j + 1, close - j - 1)));
            j = close + 1;
        } else {
            out += c;
            continue;
        }
        out += value ? fmt::format(fmt::runtime(format), *value) : std::string("######");
        i = j - 1;
    }
    return out;
}

std::optional<Diagnostic> NgcRunner::load_parameter_file() {
    auto file = std::make_shared<const std::string>(options_.retained_file.string());
    std::map<std::int64_t, double> values;
    if (options_.retained_start) {
        // A restart from a run journal: the persistent values as the interrupted run found them.
        for (const RetainedVariable& v : *options_.retained_start) {
            if (parameters_.in_range(v.number)) values[v.number] = v.value;
        }
        return apply_parameters(values, make_location(file, 1, 1));
    }
    if (options_.retained_file.empty()) return std::nullopt;
    std::ifstream in(options_.retained_file);
    if (!in) return std::nullopt;  // LinuxCNC starts without one and writes it at the end
    std::string text;
    std::uint32_t line_number = 0;
    std::int64_t previous = 0;
    while (std::getline(in, text) && line_number < 100000) {
        ++line_number;
        std::istringstream words(text);
        std::int64_t n = 0;
        double value = 0;
        if (!(words >> n)) continue;  // blank or comment line
        if (!(words >> value) || !parameters_.in_range(n)) {
            return error_at(make_location(file, line_number, 1), "parameter-file",
                            "expected 'NUMBER VALUE' with NUMBER 1-5601");
        }
        if (n <= previous) {
            return error_at(make_location(file, line_number, 1), "parameter-file",
                            "parameter numbers out of order: they must increase down the file");
        }
        previous = n;
        values[n] = value;
    }
    return apply_parameters(values, make_location(file, 1, 1));
}

std::optional<Diagnostic> NgcRunner::apply_parameters(const std::map<std::int64_t, double>& values,
                                                      const SourceLocation& where) {
    std::map<std::int64_t, double> restored;
    for (const auto& [n, value] : values) {
        if (n >= 5210 && n <= 5220) restored[n] = value;  // read live later: kept aside here
        parameters_.write(n, value);
        in_file_.insert(n);
        if (n >= work_offset_base && n < work_offset_base + fanuc_systems * work_offset_stride &&
            (n - work_offset_base) % work_offset_stride < 3) {
            (void)executor_.write_system(n, value);
        }
    }
    // As LinuxCNC starts: #5220 picks the work system (1 = G54; G59.1-G59.3, 7-9, are not among
    // nckit's six), then the G92 offset comes back when #5210 says it was applied. Both run as
    // blocks (G55; G92 X..) so the Executor keeps its own rules for them.
    auto run = [&](std::vector<Word> words) -> std::optional<Diagnostic> {
        Block block;
        block.location = where;
        block.words = std::move(words);
        std::vector<Move> events;
        bool program_end = false;
        return executor_.run(block, events, program_end);
    };
    if (restored.contains(5220)) {
        const double system = std::round(restored[5220]);
        if (system >= 1 && system <= static_cast<double>(fanuc_systems)) {
            if (auto e = run({Word{'G', 53.0 + system, true, 1, -1}})) return e;
        }
    }
    if (restored.contains(5210) && restored[5210] == 1.0) {
        std::vector<Word> words{Word{'G', 92.0, true, 1, -1}};
        for (std::int64_t n = 5211; n <= 5219; ++n) {
            const char letter = axis_letters[static_cast<std::size_t>(n - 5211)];
            auto here = axis_position(letter);  // the work position, program units
            if (!here || !restored.contains(n)) continue;
            words.push_back(Word{letter, *here - restored[n], true, 1, -1});
        }
        if (words.size() > 1) {
            if (auto e = run(std::move(words))) return e;
        }
    }
    return std::nullopt;
}

std::vector<RetainedVariable> NgcRunner::persistent_values() const {
    if (persistent_numbers_.empty()) {  // the file's numbers are known once it is read
        for (std::int64_t n = 1; n <= max_parameter; ++n) {
            if (in_file_.contains(n) || required_in_file(n)) persistent_numbers_.push_back(n);
        }
    }
    std::vector<RetainedVariable> out;
    out.reserve(persistent_numbers_.size());
    for (std::int64_t n : persistent_numbers_) out.push_back({static_cast<int>(n), parameters_.read(n)});
    return out;
}

std::uint64_t NgcRunner::persistent_changes() const {
    // Compared with the values seen last: a G10, G92 or G5x block changes them as much as an
    // assignment does, so counting writes would miss changes.
    std::vector<RetainedVariable> now = persistent_values();
    if (now != persistent_seen_) {
        persistent_seen_ = std::move(now);
        ++persistent_changes_;
    }
    return persistent_changes_;
}

std::optional<Diagnostic> NgcRunner::save_parameters() const {
    // A restart's search starts from a journal's values: the file is not its to write.
    if (options_.retained_file.empty() || !options_.save_retained || options_.retained_start) return std::nullopt;
    std::string out;
    for (std::int64_t n = 1; n <= max_parameter; ++n) {
        if (!in_file_.contains(n) && !required_in_file(n)) continue;
        out += fmt::format("{}\t{:.6f}\n", n, parameters_.read(n));
    }
    std::ofstream file(options_.retained_file, std::ios::trunc);
    file << out;
    if (!file) {
        return error_at(make_location(std::make_shared<const std::string>(options_.retained_file.string()), 0, 0),
                        "parameter-file", "cannot write the parameter file");
    }
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::translate_g92_kept() {
    // LinuxCNC's G52 and G92 share one offset. G92.2 sets it to zero but keeps #5211-#5219;
    // G92.3 sets it back from them. nckit's Executor keeps G52 and G92 apart: G92.2 clears both
    // (G92.1, and G52 at zero in a block of its own), G92.3 becomes a G92 to the kept values.
    Word* keep = nullptr;
    Word* restore = nullptr;
    for (Word& w : block_.words) {
        if (w.letter != 'G') continue;
        if (std::abs(w.value - 92.2) < 1e-9) keep = &w;
        if (std::abs(w.value - 92.3) < 1e-9) restore = &w;
        if (w.value == 92 || std::abs(w.value - 92.1) < 1e-9 || w.value == 52) g92_kept_.reset();
    }
    if (keep != nullptr) {
        std::array<double, 9> kept{};
        for (std::size_t i = 0; i < kept.size(); ++i)
            kept[i] = live_numbered(5211 + static_cast<std::int64_t>(i)).value_or(0.0);
        Block zero_g52;
        zero_g52.location = block_.location;
        zero_g52.words.push_back(Word{'G', 52.0, true, keep->column, -1});
        for (const AxisConfig& a : machine_.axes)
            zero_g52.words.push_back(Word{letter(a.axis), 0.0, true, keep->column, -1});
        std::vector<Move> events;
        bool program_end = false;
        if (auto error = executor_.run(zero_g52, events, program_end)) return error;
        keep->value = 92.1;
        g92_kept_ = kept;
        return std::nullopt;
    }
    if (restore == nullptr) return std::nullopt;
    if (!g92_kept_) {
        // The offsets already are what the parameters say: nothing changes.
        std::erase_if(block_.words, [](const Word& w) { return w.letter == 'G' && std::abs(w.value - 92.3) < 1e-9; });
        return std::nullopt;
    }
    const std::array<double, 9> kept = *g92_kept_;
    g92_kept_.reset();
    restore->value = 92;
    const std::uint32_t column = restore->column;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        const char axis = axis_letters[i];
        const std::optional<double> here = axis_position(axis);
        if (!here) continue;
        block_.words.push_back(Word{axis, *here - kept[i], true, column, -1});
    }
    return std::nullopt;
}

}  // namespace nckit::interp::ngc
