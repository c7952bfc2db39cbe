// Values of RS-274/NGC expressions with LinuxCNC's rules: degrees for angles, comparisons equal
// within 1e-6, logical (not bitwise) AND/OR/XOR, MOD always positive, an undefined named
// parameter an error and an unset numbered one 0.
#include "ngc_evaluate.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace nckit::interp::ngc {

namespace {

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;
constexpr double tolerance_equal = 1e-6;  // LinuxCNC's TOLERANCE_EQUAL

class Evaluator {
public:
    Evaluator(const NgcLine& line, const NgcParameters& parameters) : line_(line), parameters_(parameters) {}
    std::optional<Diagnostic> error;

    double eval(std::int32_t index) {
        if (error) return 0;
        const Node& node = line_.nodes[static_cast<std::size_t>(index)];
        switch (node.op) {
            case Op::number:
                return node.value;
            case Op::parameter: {
                std::int64_t n = 0;
                if (!number_of(node, n)) return 0;
                return parameters_.read(n);
            }
            case Op::named: {
                const std::string& name = line_.names[static_cast<std::size_t>(node.name)];
                std::optional<double> v = parameters_.read_named(name);
                if (!v) fail(node.column, fmt::format("named parameter #<{}> not defined", name));
                return v.value_or(0.0);
            }
            case Op::exists: {
                const Node& param = line_.nodes[static_cast<std::size_t>(node.a)];
                if (param.op == Op::named) {
                    return parameters_.exists(line_.names[static_cast<std::size_t>(param.name)]) ? 1.0 : 0.0;
                }
                double number = std::round(param.a >= 0 ? eval(param.a) : param.value);
                return number >= 1 && number <= static_cast<double>(max_parameter) ? 1.0 : 0.0;
            }
            case Op::negate:
                return -eval(node.a);
            case Op::function:
                return function(node);
            default:
                return binary(node);
        }
    }

    bool number_of(const Node& node, std::int64_t& n) {
        double raw = node.a >= 0 ? eval(node.a) : node.value;
        if (error) return false;
        // LinuxCNC rounds an index within 0.0001 of a whole number and refuses others.
        double rounded = std::round(raw);
        if (std::abs(raw - rounded) > 0.0001) {
            fail(node.column, fmt::format("parameter number {} is not a whole number", raw));
            return false;
        }
        if (!(rounded >= 1 && rounded <= static_cast<double>(max_parameter))) {
            fail(node.column, fmt::format("parameter number #{} out of range (1-{})", rounded, max_parameter));
            return false;
        }
        n = static_cast<std::int64_t>(rounded);
        return true;
    }

    void fail(std::uint32_t column, std::string message) {
        if (!error) error = error_at(line_.at(column), "ngc-value", std::move(message));
    }

private:
    double binary(const Node& node) {
        double l = eval(node.a);
        double r = eval(node.b);
        if (error) return 0;
        switch (node.op) {
            case Op::power:
                if (l < 0 && std::floor(r) != r) {
                    fail(node.column, "attempt to raise a negative number to a non-integral power");
                    return 0;
                }
                return std::pow(l, r);
            case Op::multiply:
                return l * r;
            case Op::divide:
                if (r == 0) {
                    fail(node.column, "attempt to divide by zero");
                    return 0;
                }
                return l / r;
            case Op::mod: {
                if (r == 0) {
                    fail(node.column, "attempt to divide by zero (MOD 0)");
                    return 0;
                }
                double m = std::fmod(l, r);
                return m < 0 ? m + std::abs(r) : m;
            }
            case Op::add:
                return l + r;
            case Op::subtract:
                return l - r;
            case Op::eq:
                return std::abs(l - r) < tolerance_equal ? 1 : 0;
            case Op::ne:
                return std::abs(l - r) >= tolerance_equal ? 1 : 0;
            case Op::gt:
                return l > r ? 1 : 0;
            // LinuxCNC 2.9 (the rs274 nckit is compared with) compares GE and LE exactly; only EQ
            // and NE take its tolerance. A loop `while [#6 LE #3]` stepping #6 by 0.0005 to 0.0375
            // ends one step early when the sum overshoots by a rounding error, as there.
            case Op::ge:
                return l >= r ? 1 : 0;
            case Op::lt:
                return l < r ? 1 : 0;
            case Op::le:
                return l <= r ? 1 : 0;
            case Op::logical_and:
                return (l == 0 || r == 0) ? 0 : 1;
            case Op::logical_or:
                return (l != 0 || r != 0) ? 1 : 0;
            case Op::logical_xor:
                return ((l == 0) != (r == 0)) ? 1 : 0;
            default:
                break;
        }
        fail(node.column, "bad expression");
        return 0;
    }

    double function(const Node& node) {
        double x = eval(node.a);
        double y = node.b >= 0 ? eval(node.b) : 0.0;
        if (error) return 0;
        switch (node.function) {
            case Function::abs:
                return std::abs(x);
            case Function::acos:
                if (x < -1 || x > 1) fail(node.column, "argument to ACOS out of range");
                return std::acos(x) * degrees_per_radian;
            case Function::asin:
                if (x < -1 || x > 1) fail(node.column, "argument to ASIN out of range");
                return std::asin(x) * degrees_per_radian;
            case Function::atan:
                return std::atan2(x, y) * degrees_per_radian;
            case Function::cos:
                return std::cos(x / degrees_per_radian);
            case Function::exp:
                return std::exp(x);
            case Function::fix:
                return std::floor(x);
            case Function::fup:
                return std::ceil(x);
            case Function::ln:
                if (x <= 0) fail(node.column, "attempt to take the natural log of zero or a negative number");
                return x > 0 ? std::log(x) : 0;
            case Function::round:
                return std::round(x);
            case Function::sin:
                return std::sin(x / degrees_per_radian);
            case Function::sqrt:
                if (x < 0) fail(node.column, "attempt to take the square root of a negative number");
                return x >= 0 ? std::sqrt(x) : 0;
            case Function::tan:
                return std::tan(x / degrees_per_radian);
        }
        return 0;
    }

    const NgcLine& line_;
    const NgcParameters& parameters_;
};

}  // namespace

std::optional<Diagnostic> evaluate(const NgcLine& line, std::int32_t root, const NgcParameters& parameters,
                                   double& out) {
    Evaluator evaluator(line, parameters);
    out = evaluator.eval(root);
    if (!evaluator.error && !std::isfinite(out)) {
        evaluator.fail(line.nodes[static_cast<std::size_t>(root)].column, "expression has no finite value");
    }
    return evaluator.error;
}

std::optional<Diagnostic> parameter_number(const NgcLine& line, std::int32_t node, const NgcParameters& parameters,
                                           std::int64_t& out) {
    Evaluator evaluator(line, parameters);
    evaluator.number_of(line.nodes[static_cast<std::size_t>(node)], out);
    return evaluator.error;
}

}  // namespace nckit::interp::ngc
