#include "nckit/gcode/parser.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

namespace nckit {
namespace {

//! A word as the tests compare it.
struct W {
    char letter = 0;
    double value = 0;
    bool point = false;
    std::uint32_t column = 0;
    friend bool operator==(const W&, const W&) = default;
};

std::ostream& operator<<(std::ostream& os, const W& w) {
    return os << w.letter << w.value << (w.point ? " (point)" : "") << " @" << w.column;
}

Block fresh_block() {
    Block block;
    block.location = make_location(std::make_shared<const std::string>("p.ngc"), 7, 1);
    return block;
}

//! The words of `line`; fails the test on a syntax error.
std::vector<W> words(std::string_view line) {
    Block block = fresh_block();
    if (auto error = parse_block(line, block)) {
        ADD_FAILURE() << "'" << line << "': " << format_diagnostic(*error);
        return {};
    }
    std::vector<W> out;
    for (const Word& w : block.words) out.push_back(W{w.letter, w.value, w.has_decimal_point, w.column});
    return out;
}

//! The single word of `line`.
W word(std::string_view line) {
    std::vector<W> all = words(line);
    if (all.size() != 1) {
        ADD_FAILURE() << "'" << line << "' has " << all.size() << " words";
        return {};
    }
    return all.front();
}

//! The syntax error of `line` as "code COL: message"; the line is always 7 (from the block).
std::string error(std::string_view line) {
    Block block = fresh_block();
    auto d = parse_block(line, block);
    if (!d) {
        ADD_FAILURE() << "'" << line << "' parsed without error";
        return "";
    }
    EXPECT_EQ(d->location.line, 7U);
    EXPECT_EQ(d->location.file_name(), "p.ngc");
    EXPECT_EQ(d->severity, Severity::error);
    return d->code + " " + std::to_string(d->location.column) + ": " + d->message;
}

// ---- words and numbers ------------------------------------------------------------------

TEST(Parser, ReadsWordsWithColumns) {
    EXPECT_EQ(words("G1 X10 Y-2.5 F300"),
              (std::vector<W>{{'G', 1, false, 1}, {'X', 10, false, 4}, {'Y', -2.5, true, 8}, {'F', 300, false, 14}}));
}

TEST(Parser, LettersInEitherCaseAreUpperCase) {
    EXPECT_EQ(words("g1x2.Y3z4"),
              (std::vector<W>{{'G', 1, false, 1}, {'X', 2, true, 3}, {'Y', 3, false, 6}, {'Z', 4, false, 8}}));
}

TEST(Parser, EveryLetterIsAnAddress) {
    std::vector<W> all = words("a1b2c3d4e5f6g7h8i9j1k2l3m4n5o6p7q8r9s1t2u3v4w5x6y7z8");
    ASSERT_EQ(all.size(), 26U);
    for (std::size_t i = 0; i < all.size(); ++i) {
        EXPECT_EQ(all[i].letter, static_cast<char>('A' + i));
        EXPECT_EQ(all[i].column, 2 * i + 1);
    }
}

TEST(Parser, BlanksInsideWordsAndNumbers) {
    EXPECT_EQ(words("G 1 X 1 0.5"), (std::vector<W>{{'G', 1, false, 1}, {'X', 10.5, true, 5}}));
    EXPECT_EQ(words("\tX -\t1 . 2 5"), (std::vector<W>{{'X', -1.25, true, 2}}));
}

TEST(Parser, NumberForms) {
    EXPECT_EQ(word("X.5"), (W{'X', 0.5, true, 1}));
    EXPECT_EQ(word("X5."), (W{'X', 5, true, 1}));
    EXPECT_EQ(word("X-.5"), (W{'X', -0.5, true, 1}));
    EXPECT_EQ(word("X+3"), (W{'X', 3, false, 1}));
    EXPECT_EQ(word("X-0"), (W{'X', 0, false, 1}));
    EXPECT_EQ(word("X007"), (W{'X', 7, false, 1}));
    EXPECT_EQ(word("X123456.789"), (W{'X', 123456.789, true, 1}));
}

TEST(Parser, HasDecimalPointTellsX10FromX10Point) {
    EXPECT_FALSE(word("X10").point);
    EXPECT_TRUE(word("X10.").point);
    EXPECT_TRUE(word("X10.0").point);
    EXPECT_TRUE(word("X.1").point);
}

TEST(Parser, DecimalCodeKeepsItsFraction) {
    EXPECT_EQ(word("G92.1"), (W{'G', 92.1, true, 1}));
}

TEST(Parser, NAndOWordsAreWords) {
    EXPECT_EQ(words("N10 G0"), (std::vector<W>{{'N', 10, false, 1}, {'G', 0, false, 5}}));
    EXPECT_EQ(words("O1000"), (std::vector<W>{{'O', 1000, false, 1}}));
}

TEST(Parser, EmptyAndBlankLinesHaveNoWords) {
    EXPECT_TRUE(words("").empty());
    EXPECT_TRUE(words("  \t \r").empty());
}

TEST(Parser, ReusedBlockIsCleared) {
    Block block = fresh_block();
    ASSERT_FALSE(parse_block("/G1 X1", block));
    EXPECT_TRUE(block.block_delete);
    ASSERT_FALSE(parse_block("%", block));
    EXPECT_TRUE(block.tape_mark);
    EXPECT_FALSE(block.block_delete);
    ASSERT_FALSE(parse_block("G0", block));
    EXPECT_FALSE(block.tape_mark);
    ASSERT_EQ(block.words.size(), 1U);
    EXPECT_EQ(block.words[0].letter, 'G');
}

// ---- comments, block delete, tape mark ----------------------------------------------------

TEST(Parser, ParenthesisCommentsAreSkipped) {
    EXPECT_EQ(words("(start) G1 (move) X1(end)"), (std::vector<W>{{'G', 1, false, 9}, {'X', 1, false, 19}}));
    EXPECT_TRUE(words("(only a comment; with a semicolon)").empty());
}

TEST(Parser, SemicolonCommentRunsToTheEnd) {
    EXPECT_EQ(words("G0 X1 ; rest (is ignored #1 $"), (std::vector<W>{{'G', 0, false, 1}, {'X', 1, false, 4}}));
    EXPECT_TRUE(words(";G1 X1").empty());
}

TEST(Parser, CommentEndsANumber) {
    EXPECT_EQ(words("X1(c)Y2"), (std::vector<W>{{'X', 1, false, 1}, {'Y', 2, false, 6}}));
}

TEST(Parser, UnclosedCommentIsAnErrorAtItsParenthesis) {
    EXPECT_EQ(error("G1 X1 (no end"), "syntax 7: comment is not closed: '(' without ')'");
}

TEST(Parser, NestedCommentEndsAtTheParenthesisThatClosesIt) {
    // Haas's manual prints `(0.01" finish pass (K) on sides)` in its example programs.
    Block block = fresh_block();
    ASSERT_FALSE(parse_block("G1 (a (b) c) X2 (d)", block));
    EXPECT_EQ(block.comment, "a (b) c");
    ASSERT_EQ(block.words.size(), 2U);
    EXPECT_EQ(block.words[1].letter, 'X');
    EXPECT_EQ(block.words[1].column, 14U);
}

TEST(Parser, DeeplyNestedCommentIsOneComment) {
    EXPECT_EQ(words("X1((tan(60)) = 1.732)Y2"), (std::vector<W>{{'X', 1, false, 1}, {'Y', 2, false, 22}}));
}

TEST(Parser, NestedCommentNotClosedIsAnErrorAtTheInnerParenthesis) {
    EXPECT_EQ(error("G1 (a (b (c) d"),
              "syntax 7: comment is not closed: the '(' here, inside the comment opened at column 4, has no "
              "')' (parentheses inside a comment come in pairs)");
}

TEST(Parser, ClosingParenthesisAloneIsAnError) {
    EXPECT_EQ(error("G1 X1 )"), "syntax 7: unexpected character ')'");
}

TEST(Parser, BlockDeleteSlash) {
    Block block = fresh_block();
    ASSERT_FALSE(parse_block("  /G0 X1", block));
    EXPECT_TRUE(block.block_delete);
    ASSERT_EQ(block.words.size(), 2U);
    EXPECT_EQ(block.words[0].column, 4U);
    ASSERT_FALSE(parse_block("G0 X1", block));
    EXPECT_FALSE(block.block_delete);
}

TEST(Parser, SlashInsideTheBlockIsAnError) {
    EXPECT_EQ(error("G0 / X1"), "syntax 4: unexpected character '/'");
}

TEST(Parser, PercentLineIsATapeMark) {
    for (std::string_view line : {"%", "  %  ", "% (tape)", "%;x", "%\r"}) {
        Block block = fresh_block();
        ASSERT_FALSE(parse_block(line, block)) << line;
        EXPECT_TRUE(block.tape_mark) << line;
        EXPECT_TRUE(block.words.empty()) << line;
    }
}

TEST(Parser, PercentAfterWordsIsAnError) {
    EXPECT_EQ(error("G0 %"), "syntax 4: unexpected character '%'");
}

// ---- errors -------------------------------------------------------------------------------

TEST(Parser, BadCharacterIsAnErrorAtItsColumn) {
    EXPECT_EQ(error("G1 X1 $"), "syntax 7: unexpected character '$'");
    EXPECT_EQ(error("G1 X1=2"), "syntax 6: unexpected character '='");
    EXPECT_EQ(error("12"), "syntax 1: unexpected character '1'");
    EXPECT_EQ(error("G1 -X1"), "syntax 4: unexpected character '-'");
}

TEST(Parser, ControlAndNonAsciiBytesAreNamedInHex) {
    EXPECT_EQ(error("G1\x01X1"), "syntax 3: unexpected byte 0x01");
    EXPECT_EQ(error("G1 X1 \xc3\xa9"), "syntax 7: unexpected byte 0xc3");
    EXPECT_EQ(error("G1\x7f"), "syntax 3: unexpected byte 0x7f");
}

TEST(Parser, AddressWithoutNumberIsAnErrorAtTheLetter) {
    EXPECT_EQ(error("G1 X"), "syntax 4: address X has no number after it");
    EXPECT_EQ(error("G1 X Y2"), "syntax 4: address X has no number after it");
    EXPECT_EQ(error("G1 x-"), "syntax 4: address X has no number after it");
    EXPECT_EQ(error("G1 X."), "syntax 4: address X has no number after it");
    EXPECT_EQ(error("G1 X-+1"), "syntax 4: address X has no number after it");
}

TEST(Parser, TwoDecimalPointsIsAnErrorAtTheSecond) {
    EXPECT_EQ(error("X1.2.3"), "syntax 5: number has two decimal points");
    EXPECT_EQ(error("G0 X 1 . 2 . 3"), "syntax 12: number has two decimal points");
}

TEST(Parser, OverlongNumberIsAnError) {
    EXPECT_EQ(error("G0 X" + std::string(70, '1')), "syntax 4: number has too many digits");
}

TEST(Parser, StrayBracketIsAMacroFormatError) {
    EXPECT_EQ(error("G1 X1 [2]"), "macro-format 7: '[' out of place");
    EXPECT_EQ(error("G1 X1 ]"), "macro-format 7: ']' out of place");
}

TEST(Parser, ErrorKeepsTheBlocksFileAndLine) {
    Block block;
    block.location = make_location(std::make_shared<const std::string>("q.ngc"), 42, 1);
    auto d = parse_block("G1 X1 $", block);
    ASSERT_TRUE(d);
    EXPECT_EQ(format_diagnostic(*d), "q.ngc:42:7: error: unexpected character '$'");
}

}  // namespace
}  // namespace nckit
