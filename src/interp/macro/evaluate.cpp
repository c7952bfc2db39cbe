#include "evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "nckit/gcode/macro_alarms.hpp"

namespace nckit::interp {

namespace {

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;

class Evaluator {
public:
    Evaluator(const Block& block, const Variables& variables, const EvalSettings& settings)
        : block_(block), variables_(variables), settings_(settings) {}

    std::optional<Diagnostic> error;

    MacroValue eval(std::int32_t index) {
        const ExprNode& node = block_.exprs[static_cast<std::size_t>(index)];
        switch (node.op) {
            case ExprOp::number:
                return MacroValue::of(node.value);
            case ExprOp::variable:
                return read(index);
            case ExprOp::negate:
                return MacroValue::of(-eval(node.a).or_zero());
            case ExprOp::function:
                return function(node);
            default:
                return binary(node);
        }
    }

    MacroValue read(std::int32_t index) {
        std::int64_t number = 0;
        if (!number_of(index, number)) return {};
        std::optional<MacroValue> value = variables_.read(number);
        if (!value) {
            fail(block_.exprs[static_cast<std::size_t>(index)].column, alarm::illegal_variable,
                 fmt::format("#{} is not a variable", number));
            return {};
        }
        return *value;
    }

    bool number_of(std::int32_t index, std::int64_t& number) {
        const ExprNode& node = block_.exprs[static_cast<std::size_t>(index)];
        double raw = node.value;
        if (node.a >= 0) {
            MacroValue inner = eval(node.a);
            if (error) return false;
            raw = round_half_away(inner.or_zero());
        }
        if (raw < 0 || raw > 1e9) {
            fail(node.column, alarm::illegal_variable, fmt::format("#{} is not a variable", raw));
            return false;
        }
        number = static_cast<std::int64_t>(raw);
        return true;
    }

private:
    void fail(std::uint32_t column, int alarm, std::string message) {
        if (error) return;
        Diagnostic d = error_at(block_.at_column(column), "macro-alarm", std::move(message));
        d.alarm = alarm;
        error = std::move(d);
    }

    bool near(double a, double b) const {
        return std::abs(a - b) <= settings_.comparison_tolerance * std::max({1.0, std::abs(a), std::abs(b)});
    }

    //! MOD AND OR XOR BIN BCD work on whole numbers: the operand is rounded, and must lie where a
    //! double still holds every integer (2^53); beyond, the conversion would be undefined.
    bool integer(double value, const ExprNode& node, std::int64_t& out) {
        constexpr double largest_exact = 9007199254740992.0;
        double rounded = round_half_away(value);
        if (!(std::abs(rounded) <= largest_exact)) {
            fail(node.column, alarm::argument_range, "value too large for MOD, AND, OR, XOR, BIN or BCD");
            return false;
        }
        out = static_cast<std::int64_t>(rounded);
        return true;
    }

    MacroValue integer_operation(const ExprNode& node, double l, double r) {
        std::int64_t a = 0;
        std::int64_t b = 0;
        if (!integer(l, node, a) || !integer(r, node, b)) return {};
        switch (node.op) {
            case ExprOp::mod:
                if (b == 0) {
                    fail(node.column, alarm::division_by_zero, "MOD by zero");
                    return {};
                }
                return MacroValue::of(static_cast<double>(a % b));
            case ExprOp::bit_and:
                return MacroValue::of(static_cast<double>(a & b));
            case ExprOp::bit_or:
                return MacroValue::of(static_cast<double>(a | b));
            default:
                return MacroValue::of(static_cast<double>(a ^ b));
        }
    }

    MacroValue binary(const ExprNode& node) {
        MacroValue left = eval(node.a);
        MacroValue right = eval(node.b);
        if (error) return {};
        double l = left.or_zero();
        double r = right.or_zero();
        auto truth = [](bool b) { return MacroValue::of(b ? 1.0 : 0.0); };
        switch (node.op) {
            case ExprOp::add:
                return MacroValue::of(l + r);
            case ExprOp::subtract:
                return MacroValue::of(l - r);
            case ExprOp::multiply:
                return MacroValue::of(l * r);
            case ExprOp::divide:
                if (r == 0) {
                    fail(node.column, alarm::division_by_zero, "division by zero");
                    return {};
                }
                return MacroValue::of(l / r);
            case ExprOp::mod:
            case ExprOp::bit_and:
            case ExprOp::bit_or:
            case ExprOp::bit_xor:
                return integer_operation(node, l, r);
            // EQ and NE tell vacant from 0; the ordering comparisons read vacant as 0.
            case ExprOp::eq:
                return truth(left.vacant || right.vacant ? left.vacant == right.vacant : near(l, r));
            case ExprOp::ne:
                return truth(left.vacant || right.vacant ? left.vacant != right.vacant : !near(l, r));
            case ExprOp::gt:
                return truth(l > r && !near(l, r));
            case ExprOp::ge:
                return truth(l > r || near(l, r));
            case ExprOp::lt:
                return truth(l < r && !near(l, r));
            case ExprOp::le:
                return truth(l < r || near(l, r));
            default:
                break;
        }
        fail(node.column, alarm::format, "bad expression");
        return {};
    }

    MacroValue function(const ExprNode& node) {
        double x = eval(node.a).or_zero();
        double y = node.b >= 0 ? eval(node.b).or_zero() : 0.0;
        if (error) return {};
        auto out_of_range = [&](const char* why) {
            fail(node.column, alarm::argument_range, why);
            return MacroValue{};
        };
        switch (node.function) {
            case ExprFunction::sin:
                return MacroValue::of(std::sin(x / degrees_per_radian));
            case ExprFunction::cos:
                return MacroValue::of(std::cos(x / degrees_per_radian));
            case ExprFunction::tan: {
                double c = std::cos(x / degrees_per_radian);
                if (std::abs(c) < 1e-15) return out_of_range("TAN of an odd multiple of 90 degrees");
                return MacroValue::of(std::sin(x / degrees_per_radian) / c);
            }
            case ExprFunction::asin:
                if (x < -1 || x > 1) return out_of_range("ASIN argument outside -1..1");
                return MacroValue::of(std::asin(x) * degrees_per_radian);
            case ExprFunction::acos:
                if (x < -1 || x > 1) return out_of_range("ACOS argument outside -1..1");
                return MacroValue::of(std::acos(x) * degrees_per_radian);
            case ExprFunction::atan: {
                if (node.b < 0) return MacroValue::of(std::atan(x) * degrees_per_radian);
                // ATAN[a,b] is the angle of the vector (b, a), 0 to 360 degrees.
                double angle = std::atan2(x, y) * degrees_per_radian;
                return MacroValue::of(angle < 0 ? angle + 360.0 : angle);
            }
            case ExprFunction::sqrt:
                if (x < 0) return out_of_range("SQRT of a negative number");
                return MacroValue::of(std::sqrt(x));
            case ExprFunction::abs:
                return MacroValue::of(std::abs(x));
            case ExprFunction::round:
                return MacroValue::of(round_half_away(x));
            case ExprFunction::fix:
                return MacroValue::of(std::trunc(x));
            case ExprFunction::fup:
                return MacroValue::of(x < 0 ? std::floor(x) : std::ceil(x));
            case ExprFunction::ln:
                if (x <= 0) return out_of_range("LN of zero or a negative number");
                return MacroValue::of(std::log(x));
            case ExprFunction::exp: {
                double e = std::exp(x);
                if (!std::isfinite(e)) return out_of_range("EXP result is not a finite number");
                return MacroValue::of(e);
            }
            case ExprFunction::pow: {
                double p = std::pow(x, y);
                if (!std::isfinite(p)) return out_of_range("POW result is not a finite number");
                return MacroValue::of(p);
            }
            case ExprFunction::adp:
                return MacroValue::of(settings_.least_increment_input ? x * 1000.0 : x);
            case ExprFunction::bin:
                return bin(x, node);
            case ExprFunction::bcd:
                return bcd(x, node);
        }
        return {};
    }

    // BIN: binary-coded decimal to binary; BCD: binary to binary-coded decimal.
    MacroValue bin(double x, const ExprNode& node) {
        std::int64_t code = 0;
        if (!integer(x, node, code)) return {};
        if (code < 0) {
            fail(node.column, alarm::argument_range, "BIN of a negative number");
            return {};
        }
        std::int64_t value = 0;
        std::int64_t scale = 1;
        for (; code > 0; code >>= 4, scale *= 10) {
            std::int64_t digit = code & 0xF;
            if (digit > 9) {
                fail(node.column, alarm::argument_range, "BIN argument is not binary-coded decimal");
                return {};
            }
            value += digit * scale;
        }
        return MacroValue::of(static_cast<double>(value));
    }

    MacroValue bcd(double x, const ExprNode& node) {
        std::int64_t value = 0;
        if (!integer(x, node, value)) return {};
        if (value < 0) {
            fail(node.column, alarm::argument_range, "BCD of a negative number");
            return {};
        }
        std::int64_t code = 0;
        for (int shift = 0; value > 0; value /= 10, shift += 4) code |= (value % 10) << shift;
        return MacroValue::of(static_cast<double>(code));
    }

    const Block& block_;
    const Variables& variables_;
    const EvalSettings& settings_;
};

}  // namespace

double round_half_away(double value) {
    return std::round(value);
}

std::optional<Diagnostic> evaluate(const Block& block, std::int32_t root, const Variables& variables,
                                   const EvalSettings& settings, MacroValue& out) {
    Evaluator evaluator(block, variables, settings);
    out = evaluator.eval(root);
    return evaluator.error;
}

std::optional<Diagnostic> variable_number(const Block& block, std::int32_t node, const Variables& variables,
                                          const EvalSettings& settings, std::int64_t& out) {
    Evaluator evaluator(block, variables, settings);
    evaluator.number_of(node, out);
    return evaluator.error;
}

}  // namespace nckit::interp
