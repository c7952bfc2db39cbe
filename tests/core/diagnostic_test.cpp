#include "nckit/core/diagnostic.hpp"

#include <gtest/gtest.h>

namespace nckit {
namespace {

TEST(Diagnostic, FormatsLikeACompiler) {
    auto file = std::make_shared<const std::string>("part.nc");
    Diagnostic d = error_at(make_location(file, 12, 5), "modal-conflict", "G0 and G1 in one block");
    EXPECT_EQ(format_diagnostic(d), "part.nc:12:5: error: G0 and G1 in one block");
}

TEST(Diagnostic, NamesTheAlarmNumber) {
    auto file = std::make_shared<const std::string>("m.nc");
    Diagnostic d = error_at(make_location(file, 3, 1), "division-by-zero", "division by zero");
    d.alarm = 112;
    EXPECT_EQ(format_diagnostic(d), "m.nc:3:1: error: alarm 112: division by zero");
}

TEST(Diagnostic, BuiltInInputHasAPlaceholderName) {
    Diagnostic d = error_at(SourceLocation{}, "x", "y");
    EXPECT_EQ(format_diagnostic(d), "<input>:0:0: error: y");
}

}  // namespace
}  // namespace nckit
