// Custom Macro B expressions as the interpreter evaluates them: operators and their precedence,
// every function (degrees, ATAN quadrants, rounding), argument alarms, and how a value becomes
// an address (least-increment rounding, the integer part of G and M).
#include <gtest/gtest.h>

#include "macro_support.hpp"

namespace nckit::test {
namespace {

//! The value of `expression` as an X word takes it: rounded to 0.001 mm, negatives allowed.
double x_of(std::string_view expression) {
    std::vector<double> all = xs("#1=" + std::string(expression) + "\nG1 X#1 F100\n");
    if (all.size() != 1) {
        ADD_FAILURE() << expression << " gave " << all.size() << " moves";
        return -999999;
    }
    return all.front();
}

TEST(MacroExpressions, Arithmetic) {
    EXPECT_EQ(value_of("1+2"), 3.0);
    EXPECT_EQ(value_of("7-2.5"), 4.5);
    EXPECT_EQ(value_of("1.5*4"), 6.0);
    EXPECT_EQ(value_of("10/4"), 2.5);
    EXPECT_EQ(value_of("-2+5"), 3.0);
    EXPECT_EQ(x_of("2-5"), -3.0);
    EXPECT_EQ(x_of("-[2+5]"), -7.0);
}

TEST(MacroExpressions, FanucPrecedence) {
    EXPECT_EQ(value_of("1+2*3"), 7.0);
    EXPECT_EQ(value_of("[1+2]*3"), 9.0);
    EXPECT_EQ(value_of("10-4-3"), 3.0);
    EXPECT_EQ(value_of("12/3/2"), 2.0);
    EXPECT_EQ(value_of("2+3*4 MOD 5"), 4.0);   // (3*4) MOD 5 = 2, then 2 + 2
    EXPECT_EQ(value_of("1 OR 2 AND 3"), 3.0);  // 2 AND 3 = 2 first, then 1 OR 2
    EXPECT_EQ(value_of("6 AND 3 + 1"), 3.0);   // (6 AND 3) + 1
    EXPECT_EQ(value_of("2+SQRT[9]*2"), 8.0);   // functions first
    EXPECT_EQ(value_of("8/2*4"), 16.0);        // left to right, not 8/(2*4)
    EXPECT_EQ(value_of("[[[[[2]]]]]*3"), 6.0);
}

TEST(MacroExpressions, ModRoundsItsOperandsAndKeepsTheDividendsSign) {
    EXPECT_EQ(value_of("17 MOD 5"), 2.0);
    EXPECT_EQ(value_of("17.4 MOD 4.6"), 2.0);  // 17 MOD 5
    EXPECT_EQ(value_of("10 MOD 5"), 0.0);
    EXPECT_EQ(x_of("-17 MOD 5"), -2.0);
}

TEST(MacroExpressions, BitwiseOperatorsOnIntegers) {
    EXPECT_EQ(value_of("12 AND 10"), 8.0);
    EXPECT_EQ(value_of("12 OR 3"), 15.0);
    EXPECT_EQ(value_of("12 XOR 10"), 6.0);
    EXPECT_EQ(value_of("[1 EQ 1] AND [2 GT 1]"), 1.0);
    EXPECT_EQ(value_of("[1 EQ 1] AND [2 LT 1]"), 0.0);
}

TEST(MacroExpressions, TrigonometryInDegrees) {
    EXPECT_NEAR(*value_of("SIN[30]"), 0.5, 1e-12);
    EXPECT_NEAR(*value_of("SIN[90]"), 1.0, 1e-15);
    EXPECT_NEAR(*value_of("COS[60]"), 0.5, 1e-12);
    EXPECT_EQ(x_of("COS[180]"), -1.0);
    EXPECT_NEAR(*value_of("TAN[45]"), 1.0, 1e-12);
    EXPECT_NEAR(*value_of("ASIN[0.5]"), 30.0, 1e-12);
    EXPECT_NEAR(*value_of("ACOS[0.5]"), 60.0, 1e-12);
    EXPECT_NEAR(*value_of("ACOS[-1]"), 180.0, 1e-12);
    EXPECT_EQ(x_of("ASIN[-1]"), -90.0);
}

TEST(MacroExpressions, AtanOfTwoArgumentsCoversTheFullCircle) {
    EXPECT_NEAR(*value_of("ATAN[1,1]"), 45.0, 1e-12);
    EXPECT_NEAR(*value_of("ATAN[1,-1]"), 135.0, 1e-12);
    EXPECT_NEAR(*value_of("ATAN[-1,-1]"), 225.0, 1e-12);
    EXPECT_NEAR(*value_of("ATAN[-1,1]"), 315.0, 1e-12);
    EXPECT_EQ(value_of("ATAN[0,1]"), 0.0);
    EXPECT_NEAR(*value_of("ATAN[1,0]"), 90.0, 1e-12);
    EXPECT_NEAR(*value_of("ATAN[0,-1]"), 180.0, 1e-12);
    EXPECT_NEAR(*value_of("ATAN[-1,0]"), 270.0, 1e-12);
    // The 0i form ATAN[a]/[b] is the same function.
    EXPECT_NEAR(*value_of("ATAN[1]/[-1]"), 135.0, 1e-12);
    EXPECT_NEAR(*value_of("ATAN[-2]/[-2]"), 225.0, 1e-12);
    EXPECT_NEAR(*value_of("ATAN[SQRT[3]]/[1]"), 60.0, 1e-12);
}

TEST(MacroExpressions, AtanOfOneArgumentIsThePrincipalValue) {
    EXPECT_NEAR(*value_of("ATAN[1]"), 45.0, 1e-12);
    EXPECT_EQ(x_of("ATAN[-1]"), -45.0);
    EXPECT_NEAR(*value_of("ATAN[1]/2"), 22.5, 1e-12);  // an unbracketed divisor divides
}

TEST(MacroExpressions, RoundingFunctions) {
    EXPECT_EQ(value_of("ROUND[2.5]"), 3.0);
    EXPECT_EQ(x_of("ROUND[-2.5]"), -3.0);
    EXPECT_EQ(value_of("ROUND[2.4999]"), 2.0);
    EXPECT_EQ(value_of("FIX[1.7]"), 1.0);
    EXPECT_EQ(x_of("FIX[-1.2]"), -1.0);
    EXPECT_EQ(value_of("FUP[1.2]"), 2.0);
    EXPECT_EQ(x_of("FUP[-1.2]"), -2.0);
    EXPECT_EQ(value_of("FUP[2]"), 2.0);
    EXPECT_EQ(value_of("ABS[-3.5]"), 3.5);
    EXPECT_EQ(value_of("ABS[3.5]"), 3.5);
}

TEST(MacroExpressions, RootsPowersAndLogarithms) {
    EXPECT_EQ(value_of("SQRT[16]"), 4.0);
    EXPECT_EQ(value_of("SQRT[0]"), 0.0);
    EXPECT_EQ(value_of("EXP[0]"), 1.0);
    EXPECT_EQ(value_of("LN[1]"), 0.0);
    EXPECT_NEAR(*value_of("LN[EXP[2]]"), 2.0, 1e-12);
    EXPECT_EQ(value_of("POW[2,10]"), 1024.0);
    EXPECT_EQ(value_of("POW[9,0.5]"), 3.0);
    EXPECT_EQ(value_of("POW[2,-1]"), 0.5);
}

TEST(MacroExpressions, CodeConversions) {
    EXPECT_EQ(value_of("BCD[1234]"), 4660.0);  // 0x1234
    EXPECT_EQ(value_of("BIN[4660]"), 1234.0);
    EXPECT_EQ(value_of("BIN[18]"), 12.0);  // 0x12
    EXPECT_EQ(value_of("BCD[0]"), 0.0);
    EXPECT_EQ(value_of("BIN[BCD[9876]]"), 9876.0);
}

TEST(MacroExpressions, AdpIsIdentityWhereNumbersAreReadWithAPoint) {
    EXPECT_EQ(value_of("ADP[10]"), 10.0);
    EXPECT_EQ(value_of("ADP[2.5]"), 2.5);
}

TEST(MacroExpressions, DivisionByZeroIsAlarm112AtTheOperator) {
    EXPECT_EQ(alarm_of("G1 F100\n#1=1/0\n"), "112 2:5");
    EXPECT_EQ(alarm_of("#1=1/#0\n"), "112 1:5");  // vacant counts as 0
    EXPECT_EQ(alarm_of("#1=5 MOD 0\n"), "112 1:6");
    EXPECT_EQ(alarm_of("#1=5 MOD 0.4\n"), "112 1:6");  // rounds to 0
    EXPECT_EQ(alarm_of("G1 X[1/#5] F100\n"), "112 1:7");
    Diagnostic d = error_of("#1=1/0\n", wide_mill());
    EXPECT_EQ(d.code, "macro-alarm");
    EXPECT_EQ(format_diagnostic(d), "test.ngc:1:5: error: alarm 112: division by zero");
}

TEST(MacroExpressions, ArgumentOutOfRangeIsAlarm119AtTheFunction) {
    EXPECT_EQ(alarm_of("#1=SQRT[-1]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=2+ASIN[2]\n"), "119 1:6");
    EXPECT_EQ(alarm_of("#1=ACOS[-1.5]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=LN[0]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=LN[-2]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=BCD[-1]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=BIN[-1]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=BIN[26]\n"), "119 1:4");  // 0x1A is no binary-coded decimal
    EXPECT_EQ(alarm_of("#1=TAN[90]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=POW[-8,0.5]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=POW[0,-1]\n"), "119 1:4");
    EXPECT_EQ(alarm_of("#1=EXP[1000]\n"), "119 1:4");
}

TEST(MacroExpressions, IntegerOperationsRefuseValuesBeyondExactIntegers) {
    // 1e20 has no exact 64-bit integer: an alarm rather than a made-up remainder.
    EXPECT_EQ(alarm_of("#1=POW[10,20] MOD 7\n"), "119 1:15");
    EXPECT_EQ(alarm_of("#1=1 AND POW[2,60]\n"), "119 1:6");
    EXPECT_EQ(alarm_of("#1=BCD[POW[2,60]]\n"), "119 1:4");
    EXPECT_EQ(value_of("POW[2,52] OR 1"), 4503599627370497.0);
}

TEST(MacroExpressions, ParseAlarmsStopTheProgramAtTheirLine) {
    EXPECT_EQ(alarm_of("G1 X1 F100\n#1=[[[[[[1]]]]]]\n"), "118 2:9");
    EXPECT_EQ(alarm_of("G1 X1 F100\n#1=#-1\n"), "114 2:4");
    EXPECT_EQ(alarm_of("G1 X#-1 F100\n"), "114 1:5");
    RunResult r = run_program("G1 X1 F100\n#1=1+\nG1 X2\n", wide_mill());
    EXPECT_EQ(r.moves.size(), 1U);  // the block before runs, nothing after
}

TEST(MacroExpressions, NegatedVariableInAnAddress) {
    EXPECT_EQ(xs("#1=5\nG1 X-#1 F100\nX-[#1*2]\n"), (std::vector<double>{-5, -10}));
}

TEST(MacroExpressions, AddressValueIsRoundedToTheLeastIncrement) {
    EXPECT_EQ(xs("#1=1.23456\nG1 X#1 F100\n"), (std::vector<double>{1.235}));
    EXPECT_EQ(xs("#1=-1.23456\nG1 X#1 F100\n"), (std::vector<double>{-1.235}));
    EXPECT_EQ(xs("#1=1.2344\nG1 X#1 F100\n"), (std::vector<double>{1.234}));
    // Inch: 0.0001 in.
    std::vector<double> inch = xs("G20\n#1=1.23456\nG1 X#1 F10\n");
    ASSERT_EQ(inch.size(), 1U);
    EXPECT_DOUBLE_EQ(inch[0], 1.2346 * 25.4);
    // A rotary axis rounds to 0.001 deg, also in inch.
    MachineConfig a_axis = mill_with_a();
    std::vector<Line> lines = only<Line>(moves_of("G20\n#1=10.12345\nG0 A#1\n", a_axis));
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_DOUBLE_EQ(lines[0].to[Axis::A], 10.123);
}

TEST(MacroExpressions, RoundingAppliesToArcCentres) {
    std::vector<Arc> arcs = only<Arc>(moves_of("#1=0.0004\nG0 X10\nG2 X-10 I-10 J#1 F100\n", wide_mill()));
    ASSERT_EQ(arcs.size(), 1U);
    EXPECT_EQ(arcs[0].center[Axis::X], 0.0);
    EXPECT_EQ(arcs[0].center[Axis::Y], 0.0);  // J0.0004 is J0.000
}

TEST(MacroExpressions, AddressValueIsTheSameNumberAsTheWrittenOne) {
    // X#1 must move exactly where X<the rounded value> moves: the same double, bit for bit.
    for (const char* v : {"0.009", "0.013", "1.051", "123.456", "-7.071", "499.999"}) {
        std::string x = v;
        EXPECT_EQ(xs("#1=" + x + "4\nG1 X#1 F100\n"), xs("G1 X" + x + " F100\n")) << v;
    }
    for (const char* v : {"0.0003", "0.0009", "1.0051", "-3.1416"}) {
        std::string x = v;
        EXPECT_EQ(xs("G20\n#1=" + x + "4\nG1 X#1 F10\n"), xs("G20\nG1 X" + x + " F10\n")) << v;
    }
}

TEST(MacroExpressions, GTakesTheIntegerPart) {
    std::vector<Line> lines = only<Line>(moves_of("#10=1.7\nG#10 X5 F100\n#10=0.9\nG#10 X6\n", wide_mill()));
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_FALSE(lines[0].rapid);
    EXPECT_TRUE(lines[1].rapid);
}

TEST(MacroExpressions, WholeNumberAddressesRound) {
    // M S T have a least increment of 1: the value is rounded, half away from zero.
    EXPECT_EQ(texts("#1=3.6\nS1000 M#1\n"), (Texts{"S1000", "M4"}));
    EXPECT_EQ(texts("#1=3.4\nS1000 M#1\n"), (Texts{"S1000", "M3"}));
    EXPECT_EQ(texts("#1=999.5\nS#1 M3\n"), (Texts{"S1000", "M3"}));
    EXPECT_EQ(texts("#1=5.5\nT#1 M6\n"), (Texts{"T6", "M6"}));
    EXPECT_EQ(xs("#1=2.5\nM98 P100 L#1\nM30\nO100\nG91 G1 X1 F100\nG90\nM99\n"), (std::vector<double>{1, 2, 3}));
}

TEST(MacroExpressions, VariablesInAnyAddress) {
    EXPECT_EQ(xs("#1=100\n#2=2\nM98 P#1 L#2\nM30\nO100\nG91 G1 X1 F100\nG90\nM99\n"), (std::vector<double>{1, 2}));
    EXPECT_EQ(texts("#1=250\nG4 P#1\n"), (Texts{"G4 P0.2500"}));
    // G10 L20 P2 X5 at X0: G55 is set so that here reads X5.
    EXPECT_EQ(xs("#1=2\n#2=5\n#4=20\nG10 L#4 P#1 X#2\nG55 G0 X0\n"), (std::vector<double>{-5}));
    EXPECT_EQ(xs("#1=2\n#2=5\nG10 L2 P#1 X#2\nG55 G0 X0\n"), (std::vector<double>{5}));
}

TEST(MacroExpressions, FeedKeepsItsValue) {
    std::vector<Line> lines = only<Line>(moves_of("#1=123.4567\nG1 X1 F#1\n", wide_mill()));
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_DOUBLE_EQ(lines[0].feed.mm_per_min, 123.4567);
}

TEST(MacroExpressions, ComparisonsToleranceKeepsSteppedCountersExact) {
    // 0.1 added ten times is not exactly 1 in binary; EQ still holds, as on a control.
    EXPECT_EQ(value_after("#2=0\nWHILE [#2 LT 1] DO1\n#2=#2+0.1\nEND1\n#1=0\nIF [#2 EQ 1] THEN #1=1"), 1.0);
    EXPECT_EQ(value_after("#2=0\n#3=0\nWHILE [#2 LE 1] DO1\n#2=#2+0.1\n#3=#3+1\nEND1\n#1=#3"), 11.0);
}

}  // namespace
}  // namespace nckit::test
