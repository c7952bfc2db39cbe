// Numbers and comments as nckit writes them into G-code: exact decimals that read back to the same
// double, rounded decimals without "-0", comment text that cannot end its comment early.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "nckit/core/format_exact.hpp"

namespace nckit {
namespace {

std::string exact(double value) {
    std::string out;
    append_exact(out, value);
    return out;
}

TEST(FormatExact, ReadsBackAsTheSameDoubleWithoutAnExponent) {
    std::mt19937_64 random(20261126);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 10000; ++i) {
        const double value = unit(random) * std::pow(10.0, (i % 17) - 8);
        const std::string text = exact(value);
        EXPECT_EQ(text.find_first_of("eE"), std::string::npos) << text;
        EXPECT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
    }
    EXPECT_EQ(exact(5.0), "5.0");
    EXPECT_EQ(exact(-0.0), "0.0");
    EXPECT_EQ(exact(0.00000123), "0.00000123");
}

TEST(FormatExact, RoundedValuesNeverReadMinusZeroAndReportTheirError) {
    std::string out;
    const double error = append_rounded(out, -0.000004, 5);
    EXPECT_EQ(out, "0.00000");
    EXPECT_DOUBLE_EQ(error, 0.000004);
    out.clear();
    EXPECT_NEAR(append_rounded(out, 12.345678, 3), 0.000322, 1e-12);
    EXPECT_EQ(out, "12.346");
    out.clear();
    append_rounded(out, 5.0, 0);
    EXPECT_EQ(out, "5.");  // the point keeps it 5 mm on a control without calculator-type input
}

TEST(FormatExact, CommentTextCannotCloseItsCommentOrBreakTheLine) {
    EXPECT_EQ(comment_text("part(2).nc"), "part[2].nc");
    EXPECT_EQ(comment_text("piston\r\nA"), "piston  A");
    EXPECT_EQ(comment_text("plain"), "plain");
}

}  // namespace
}  // namespace nckit
