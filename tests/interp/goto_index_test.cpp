// GOTO through the index of sequence numbers (src/interp/sequence_index.hpp): the same targets
// as a search (forward first, then from the program's start; the first of repeated numbers),
// loops left forward and backward, and the lines between a GOTO and its target read once per
// program, not once per jump.
#include <gtest/gtest.h>

#include <string>

#include "macro_support.hpp"

namespace nckit::test {
namespace {

TEST(GotoIndex, FindsTheNextLineWithTheNumberThenTheFirstFromTheStart) {
    const std::string program =
        "#1=0\n"
        "N7 #1=#1+1\n"  // the first N7 of the program
        "N7 G1 X#1 F100\n"
        "IF [#1 GE 3] GOTO 9\n"
        "GOTO 7\n"  // forward: the N7 below, not the ones above
        "G1 X100\n"
        "N7 G1 X[#1*10]\n"
        "GOTO 7\n"  // nothing forward: the first N7 from the start
        "N9 G1 X-1\n";
    EXPECT_EQ(xs(program), (std::vector<double>{1, 10, 2, 20, 3, -1}));
}

TEST(GotoIndex, JumpsOutOfLoopsForwardAndBackward) {
    // Forward out of the inner loop past its END2: DO2 is over, DO1 goes on.
    EXPECT_EQ(xs("#1=0\n"
                 "WHILE [#1 LT 2] DO1\n"
                 "#1=#1+1\n"
                 "WHILE [1 EQ 1] DO2\n"
                 "G1 X#1 F100\n"
                 "GOTO 5\n"
                 "END2\n"
                 "N5 G1 Y#1\n"
                 "END1\n"
                 "G1 X9\n"),
              (std::vector<double>{1, 1, 2, 2, 9}));
    // Back before a DO: that loop is left and starts afresh, so DO1 may be used again.
    EXPECT_EQ(xs("#1=0\n"
                 "N1 #1=#1+1\n"
                 "WHILE [1 EQ 1] DO1\n"
                 "G1 X#1 F100\n"
                 "IF [#1 LT 3] GOTO 1\n"
                 "GOTO 2\n"
                 "END1\n"
                 "N2 G1 X0\n"),
              (std::vector<double>{1, 2, 3, 0}));
}

TEST(GotoIndex, MissingNumberIsAlarm128) {
    EXPECT_EQ(alarm_of("G1 X1 F100\nGOTO 5\nN6 G1 X2\n"), "128 2:6");
}

// Before the index, each jump re-read the 10,000 lines between N2 and N1 and each line read
// counted against the budget: 200 round trips read 4,000,000 lines, far beyond a budget of
// 30,000. Now the program is read once for the index and each jump costs one block.
TEST(GotoIndex, LinesBetweenJumpsAreReadOncePerProgram) {
    const std::string program =
        "#1=0\n"
        "N1 #1=#1+1\n"
        "IF [#1 GE 200] GOTO 3\n"
        "GOTO 2\n" +
        std::string(10000, '\n') +
        "N2 GOTO 1\n"
        "N3 G1 X#1 F100\n";
    InterpreterOptions options;
    options.max_blocks = 30000;
    EXPECT_EQ(xs(program, options), (std::vector<double>{200}));
    // The runaway of two GOTOs still ends in alarm 100 once the budget is spent.
    options.max_blocks = 5000;
    EXPECT_EQ(alarm_of("N1 GOTO 2\n" + std::string(10000, '\n') + "N2 GOTO 1\n", options).substr(0, 3), "100");
}

}  // namespace
}  // namespace nckit::test
