// LinuxCNC's polar words in G17: `@` a radius and `^` an angle in degrees from +X, about the
// program origin under G90 and added to the tool's own radius and angle under G91. A drilling
// cycle under G91 repeated with L turns (or stretches) again on every repeat, so each repeat
// becomes a block of its own with its X/Y increment.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "ngc_block_words.hpp"
#include "ngc_runner.hpp"

namespace nckit::interp::ngc {

namespace {

constexpr double rad_per_deg = std::numbers::pi / 180.0;

bool is_cycle_code(double code) {
    return std::abs(code - 73) < 1e-9 || (code >= 81 && code <= 89 && code == std::floor(code));
}

bool is_motion_code(double code) {
    for (double c : {0.0, 1.0, 2.0, 3.0, 33.0, 73.0, 76.0, 80.0}) {
        if (std::abs(code - c) < 1e-9) return true;
    }
    return is_cycle_code(code) || (code >= 38.15 && code <= 38.55);
}

}  // namespace

std::optional<Diagnostic> NgcRunner::translate_polar(std::vector<Block>& repeats) {
    const Word* at = nullptr;
    const Word* caret = nullptr;
    bool cycle = false;
    bool motion_given = false;
    for (const Word& w : block_.words) {
        if (w.letter == '@') at = &w;
        if (w.letter == '^') caret = &w;
        if (w.letter == 'G' && is_motion_code(w.value)) {
            motion_given = true;
            cycle = is_cycle_code(w.value);
        }
    }
    if (at == nullptr && caret == nullptr) return std::nullopt;
    const std::uint32_t column = at != nullptr ? at->column : caret->column;
    const ModalView view = executor_.modal_view();
    if (!motion_given) cycle = view.motion_code == 730 || (view.motion_code >= 810 && view.motion_code <= 890);
    // The block's own G17-G19 and G90/G91 count: they take effect before its move.
    const bool xy_plane = has_g(block_, 17) || (view.plane == Plane::xy && !has_g(block_, 18) && !has_g(block_, 19));
    const bool incremental = has_g(block_, 91) || (view.incremental && !has_g(block_, 90));
    if (!xy_plane) return fail(column, "cannot use polar coordinate except in G17 plane");
    if (has_g(block_, 53)) return fail(column, "cannot use polar coordinates with G53");
    if (find_word(block_, 'X') != nullptr) return fail(column, "cannot specify both polar coordinate and X word");
    if (find_word(block_, 'Y') != nullptr) return fail(column, "cannot specify both polar coordinate and Y word");
    const std::optional<double> at_x = axis_position('X');
    const std::optional<double> at_y = axis_position('Y');
    if (!at_x || !at_y) return fail(column, "cannot use polar coordinate on a machine lacking X or Y axes");
    const double radius_word = at != nullptr ? at->value : 0.0;
    const double angle_rad = caret != nullptr ? caret->value * rad_per_deg : 0.0;
    double x = *at_x;
    double y = *at_y;
    const bool has_radius = at != nullptr;
    const bool has_angle = caret != nullptr;
    std::erase_if(block_.words, [](const Word& w) { return w.letter == '@' || w.letter == '^'; });

    if (!incremental) {
        if (!cycle && has_radius && !has_angle && x == 0 && y == 0) {
            return fail(column, "must specify angle in polar coordinate if at the origin");
        }
        const double radius = has_radius ? radius_word : std::hypot(y, x);
        const double theta = has_angle ? angle_rad : std::atan2(y, x);
        block_.words.push_back(Word{'X', radius * std::cos(theta), true, column, -1});
        block_.words.push_back(Word{'Y', radius * std::sin(theta), true, column, -1});
        return std::nullopt;
    }
    // One step: the radius grown by @, then the angle turned by ^, from where the tool is.
    auto step = [&](double& px, double& py) -> std::optional<Diagnostic> {
        if (has_radius) {
            if (px == 0 && py == 0) {
                return fail(column, "incremental motion with polar coordinates is indeterminate when at the origin");
            }
            const double theta = std::atan2(py, px);
            const double radius = std::hypot(py, px) + radius_word;
            px = radius * std::cos(theta);
            py = radius * std::sin(theta);
        }
        if (has_angle) {
            if (px == 0 && py == 0) {
                return fail(column, "G91 motion with polar coordinates is indeterminate when at the origin");
            }
            const double theta = std::atan2(py, px) + angle_rad;
            const double radius = std::hypot(py, px);
            px = radius * std::cos(theta);
            py = radius * std::sin(theta);
        }
        return std::nullopt;
    };
    int count = 1;
    if (Word* l = find_word(block_, 'L'); cycle && l != nullptr) {
        if (l->value < 1 || l->value != std::floor(l->value) || l->value > max_polar_repeats) {
            return fail(l->column, fmt::format("L must be a whole number from 1 to {}", max_polar_repeats));
        }
        count = static_cast<int>(l->value);
        std::erase_if(block_.words, [](const Word& w) { return w.letter == 'L'; });
    }
    Block pattern = block_;  // a repeat moves and cycles only: no second tool, spindle or M-code event
    std::erase_if(pattern.words, [](const Word& w) {
        return w.letter == 'M' || w.letter == 'S' || w.letter == 'T' || w.letter == 'D' || w.letter == 'H';
    });
    for (int i = 0; i < count; ++i) {
        const double from_x = x;
        const double from_y = y;
        if (auto error = step(x, y)) return error;
        Block& target = i == 0 ? block_ : repeats.emplace_back(pattern);
        target.words.push_back(Word{'X', x - from_x, true, column, -1});
        target.words.push_back(Word{'Y', y - from_y, true, column, -1});
    }
    return std::nullopt;
}

}  // namespace nckit::interp::ngc
