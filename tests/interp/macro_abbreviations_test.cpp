// Fanuc's two-letter abbreviations of Macro B keywords, functions and operators: each gives what
// the full word gives, full names still win over a shorter one, and an abbreviation where none
// is accepted (POW) is a format error.
#include <cmath>

#include <gtest/gtest.h>

#include "macro_support.hpp"

namespace nckit::test {
namespace {

TEST(MacroAbbreviations, FunctionsReadFromTheirFirstTwoLetters) {
    const std::pair<const char*, const char*> pairs[] = {
        {"SI[30]", "SIN[30]"},     {"CO[60]", "COS[60]"},    {"TA[45]", "TAN[45]"},   {"AT[1]/[2]", "ATAN[1]/[2]"},
        {"AS[0.5]", "ASIN[0.5]"},  {"AC[0.5]", "ACOS[0.5]"}, {"SQ[16]", "SQRT[16]"},  {"AB[-3]", "ABS[-3]"},
        {"RO[2.5]", "ROUND[2.5]"}, {"FI[1.7]", "FIX[1.7]"},  {"FU[1.2]", "FUP[1.2]"}, {"EX[1]", "EXP[1]"},
        {"BI[18]", "BIN[18]"},     {"BC[12]", "BCD[12]"},
    };
    for (const auto& [short_form, full] : pairs) {
        const auto got = value_of(short_form);
        const auto want = value_of(full);
        ASSERT_TRUE(got.has_value()) << short_form;
        ASSERT_TRUE(want.has_value()) << full;
        EXPECT_DOUBLE_EQ(*got, *want) << short_form;
    }
    EXPECT_NEAR(*value_of("SI[30]"), 0.5, 1e-12);
    EXPECT_EQ(*value_of("SQ[16]+AB[-3]"), 7.0);
}

TEST(MacroAbbreviations, OperatorsReadFromTheirFirstTwoLetters) {
    EXPECT_EQ(value_of("12 AN 10"), 8.0);
    EXPECT_EQ(value_of("12 XO 10"), 6.0);
    EXPECT_EQ(value_of("17 MO 5"), 2.0);
    EXPECT_EQ(value_of("[1 EQ 1] AN [2 GT 1]"), 1.0);
}

TEST(MacroAbbreviations, StatementsReadFromTheirFirstTwoLetters) {
    // GO = GOTO, EN = END, TH = THEN, WH = WHILE: the loop runs three times, the jump skips X99.
    const std::vector<double> x =
        xs("#1=0\nWH [#1 LT 3] DO1\n#1=#1+1\nIF [#1 EQ 2] TH #2=5\nG1 X#1 F100\nEN1\n"
           "GO 10\nG1 X99\nN10 G1 X#2\nIF [#2 EQ 5] GO20\nG1 X98\nN20 M30\n");
    EXPECT_EQ(x, (std::vector<double>{1, 2, 3, 5}));
}

TEST(MacroAbbreviations, FullNamesWinAndPowHasNone) {
    EXPECT_EQ(value_of("SQRT[9]"), 3.0);   // not SQ followed by RT
    EXPECT_EQ(value_of("ASIN[1]"), 90.0);  // not AS + IN
    EXPECT_EQ(value_of("POW[2,3]"), 8.0);
    EXPECT_EQ(alarm_of("#1=PO[2,3]\n"), "114 1:4");  // no abbreviation for POW
    EXPECT_EQ(alarm_of("#1=SI 30\n"), "114 1:4");    // an abbreviation needs its '['
}

}  // namespace
}  // namespace nckit::test
