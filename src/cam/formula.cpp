#include "nckit/cam/formula.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <muParser.h>

namespace nckit::cam {

namespace {

constexpr std::size_t max_variables = 4;

double sin_deg(double x) {
    return std::sin(x * (std::numbers::pi / 180.0));
}
double cos_deg(double x) {
    return std::cos(x * (std::numbers::pi / 180.0));
}

//! muparser says `Unexpected token "Q" found at position 6.`; the diagnostic gives the
//! position as a column of its own, so the message keeps only the what.
std::string tidy_message(std::string message) {
    for (const char* tail : {" found at position", " at position"}) {
        const std::size_t at = message.find(tail);
        if (at != std::string::npos) message.erase(at);
    }
    while (!message.empty() && (message.back() == '.' || message.back() == ' ')) message.pop_back();
    if (!message.empty()) {
        message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
    }
    return message;
}

}  // namespace

struct Formula::Engine {
    mu::Parser parser;
    //! muparser reads the variables through pointers, so they live beside it, never moved.
    std::array<double, max_variables> values{};

    //! Throws mu::Parser::exception_type when the text does not compile.
    Engine(const std::string& text, const std::vector<std::string>& variables) {
        parser.DefineFun("sind", sin_deg);
        parser.DefineFun("cosd", cos_deg);
        for (std::size_t i = 0; i < variables.size(); ++i) {
            parser.DefineVar(variables[i], &values[i]);
        }
        parser.SetExpr(text);
        // muparser parses on the first evaluation; do it now so errors surface here.
        (void)parser.Eval();
    }
};

Formula::Formula(std::string text, std::vector<std::string> variables, std::unique_ptr<Engine> engine)
    : text_(std::move(text)), variables_(std::move(variables)), engine_(std::move(engine)) {}

std::variant<Formula, FormulaError> Formula::compile(std::string text, std::vector<std::string> variables) {
    if (variables.size() > max_variables) {
        throw std::invalid_argument("a Formula takes at most 4 variables");
    }
    std::unique_ptr<Engine> engine;
    try {
        engine = std::make_unique<Engine>(text, variables);
    } catch (const mu::Parser::exception_type& error) {
        const int position = error.GetPos();
        // muparser reports -1 for an empty formula and one past the end for a missing ')'.
        const std::size_t at = position < 0 ? 0 : std::min(static_cast<std::size_t>(position), text.size());
        return FormulaError{at, tidy_message(error.GetMsg())};
    }
    if (engine->parser.GetNumResults() != 1) {
        const std::size_t comma = text.find(',');
        return FormulaError{comma == std::string::npos ? 0 : comma,
                            "formula must give one value, not a comma-separated list"};
    }
    return Formula(std::move(text), std::move(variables), std::move(engine));
}

Formula::Formula(const Formula& other)
    : text_(other.text_),
      variables_(other.variables_),
      engine_(std::make_unique<Engine>(other.text_, other.variables_)) {}

Formula& Formula::operator=(const Formula& other) {
    if (this != &other) *this = Formula(other);
    return *this;
}

Formula::Formula(Formula&&) noexcept = default;
Formula& Formula::operator=(Formula&&) noexcept = default;
Formula::~Formula() = default;

double Formula::evaluate(std::span<const double> values) const {
    if (values.size() != variables_.size()) {
        throw std::invalid_argument("Formula::evaluate needs one value per variable");
    }
    for (std::size_t i = 0; i < values.size(); ++i) engine_->values[i] = values[i];
    return engine_->parser.Eval();
}

}  // namespace nckit::cam
