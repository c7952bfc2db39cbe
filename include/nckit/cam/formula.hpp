#pragma once
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace nckit::cam {

//! Why a formula does not compile, and where in its text.
struct FormulaError {
    std::size_t position = 0;  //!< 0-based byte offset into the formula text
    std::string message;       //!< lower case, no trailing period, no position in it
};

//! A drawing formula such as "0.4 + 0.004*Z", compiled once by muparser (a maintained
//! expression library) and evaluated many times. Besides muparser's functions and constants
//! (sin, cos, sqrt, abs, min, max, _pi, ...; angles in radians) it offers sind(x) and cosd(x)
//! of x in degrees, since drawings give PHI in degrees.
//! One object is not safe to evaluate from two threads at once; copies are independent.
class Formula {
public:
    //! The formula, or why `text` does not compile with exactly `variables` (at most 4, e.g.
    //! {"Z", "PHI"}) defined. The text must give one value.
    [[nodiscard]] static std::variant<Formula, FormulaError> compile(std::string text,
                                                                     std::vector<std::string> variables);

    Formula(const Formula& other);
    Formula& operator=(const Formula& other);
    Formula(Formula&&) noexcept;
    Formula& operator=(Formula&&) noexcept;
    ~Formula();

    //! The value with the variables set to `values`, in the order compile() named them.
    //! May be inf or nan (e.g. a division by zero): callers check what they need.
    [[nodiscard]] double evaluate(std::span<const double> values) const;

    [[nodiscard]] const std::string& text() const { return text_; }
    [[nodiscard]] const std::vector<std::string>& variables() const { return variables_; }

private:
    struct Engine;
    Formula(std::string text, std::vector<std::string> variables, std::unique_ptr<Engine> engine);

    std::string text_;
    std::vector<std::string> variables_;
    std::unique_ptr<Engine> engine_;  //!< muparser's parser with the variables it points at
};

}  // namespace nckit::cam
