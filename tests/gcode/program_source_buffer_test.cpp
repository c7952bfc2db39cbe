// Files longer than the 1 MiB read buffer: lines across its end, and seeks out of it.
#include "nckit/gcode/program_source.hpp"

#include <gtest/gtest.h>

#include "source_support.hpp"

namespace nckit::test {
namespace {

TEST(ProgramSourceBuffer, ReadsEveryLineOfAFileLongerThanTheBuffer) {
    TempDir dir;
    const std::string text = long_program(3 * buffer_bytes + 12345);
    ProgramSource source = open_file(dir.write("long.ngc", text));
    EXPECT_EQ(all_lines(source), expected_lines(text));
}

TEST(ProgramSourceBuffer, LineStraddlingTheBufferEndIsWhole) {
    TempDir dir;
    // "G1 X..." starts 10 bytes before the buffer ends and runs 12 bytes into the next fill.
    const std::string text = filler(buffer_bytes - 10) + "G1 X123456789 Y1234567\nM30\n";
    const std::vector<Got> expected = expected_lines(text);
    ASSERT_EQ(expected[expected.size() - 2],
              (Got{"G1 X123456789 Y1234567", expected.back().number - 1, buffer_bytes - 10}));
    ProgramSource source = open_file(dir.write("p.ngc", text));
    EXPECT_EQ(all_lines(source), expected);
}

TEST(ProgramSourceBuffer, CrLfSplitByTheBufferEndIsOneLineEnd) {
    TempDir dir;
    // '\r' is the buffer's last byte, '\n' the next fill's first.
    const std::string head = filler(buffer_bytes - 6);
    const std::string text = head + "G0 Y7\r\nG0 X1\r\n";
    ASSERT_EQ(text[buffer_bytes - 1], '\r');
    std::vector<Got> expected = expected_lines(head);
    const std::uint32_t n = expected.back().number;
    expected.push_back(Got{"G0 Y7", n + 1, buffer_bytes - 6});
    expected.push_back(Got{"G0 X1", n + 2, buffer_bytes + 1});
    ProgramSource source = open_file(dir.write("p.ngc", text));
    EXPECT_EQ(all_lines(source), expected);
}

TEST(ProgramSourceBuffer, LineStartingExactlyAtTheBufferEnd) {
    TempDir dir;
    const std::string text = filler(buffer_bytes) + "G0 X1\nM30";
    const std::vector<Got> expected = expected_lines(text);
    ASSERT_EQ(expected[expected.size() - 2].offset, buffer_bytes);
    ProgramSource source = open_file(dir.write("p.ngc", text));
    EXPECT_EQ(all_lines(source), expected);
}

TEST(ProgramSourceBuffer, FileOfExactlyOneBufferEndingInNewline) {
    TempDir dir;
    const std::string text = filler(buffer_bytes - 3) + "M2\n";
    ASSERT_EQ(text.size(), buffer_bytes);
    ProgramSource source = open_file(dir.write("p.ngc", text));
    EXPECT_EQ(all_lines(source), expected_lines(text));
}

TEST(ProgramSourceBuffer, LastLineWithoutNewlineStraddlingTheBuffer) {
    TempDir dir;
    const std::string text = filler(buffer_bytes - 2) + "G0 X12345";
    const std::vector<Got> expected = expected_lines(text);
    ASSERT_EQ(expected.back().offset, buffer_bytes - 2);
    ProgramSource source = open_file(dir.write("p.ngc", text));
    EXPECT_EQ(all_lines(source), expected);
}

TEST(ProgramSourceBuffer, TooLongLineAcrossTheBufferEndIsAnError) {
    TempDir dir;
    // The long line starts well inside the first buffer and ends in the second.
    const std::string head = filler(buffer_bytes - 1000);
    const std::string text = head + std::string(ProgramSource::max_line_bytes + 1, 'X') + "\n";
    const std::size_t head_lines = expected_lines(head).size();
    ProgramSource source = open_file(dir.write("p.ngc", text));
    for (std::size_t i = 0; i < head_lines; ++i) next_line(source);
    auto line = source.next();
    ASSERT_FALSE(line.ok());
    EXPECT_EQ(line.diagnostics().front().code, "line-too-long");
    EXPECT_EQ(line.diagnostics().front().location.line, head_lines + 1);
}

TEST(ProgramSourceBuffer, SeeksBackToALineBeforeTheBuffer) {
    TempDir dir;
    const std::string text = long_program(2 * buffer_bytes + 500);
    const std::vector<Got> expected = expected_lines(text);
    ProgramSource source = open_file(dir.write("long.ngc", text));
    std::vector<Got> first_pass = all_lines(source);
    ASSERT_EQ(first_pass, expected);
    // Line 3 lies two buffer fills back; reading on from there gives the same lines again.
    source.seek(expected[2].offset, expected[2].number);
    std::vector<Got> second_pass = all_lines(source);
    EXPECT_EQ(second_pass, std::vector<Got>(expected.begin() + 2, expected.end()));
}

TEST(ProgramSourceBuffer, SeeksBackWithinTheSecondBuffer) {
    TempDir dir;
    const std::string text = long_program(2 * buffer_bytes + 500);
    const std::vector<Got> expected = expected_lines(text);
    ProgramSource source = open_file(dir.write("long.ngc", text));
    std::size_t i = 0;
    while (expected[i].offset < buffer_bytes + 1000) EXPECT_EQ(next_line(source), expected[i++]);
    const std::size_t mark = i;
    for (int k = 0; k < 50; ++k) EXPECT_EQ(next_line(source), expected[i++]);
    source.seek(expected[mark].offset, expected[mark].number);
    for (std::size_t k = mark; k < mark + 60; ++k) EXPECT_EQ(next_line(source), expected[k]);
}

TEST(ProgramSourceBuffer, SeeksToALineThatStraddledTheBuffer) {
    TempDir dir;
    const std::string head = filler(buffer_bytes - 10);
    const std::string text = head + "G1 X123456789 Y1234567\nG0 X2\nM30\n";
    ProgramSource source = open_file(dir.write("p.ngc", text));
    const std::size_t head_lines = expected_lines(head).size();
    for (std::size_t i = 0; i < head_lines; ++i) next_line(source);
    Got straddling = next_line(source);
    ASSERT_EQ(straddling.offset, buffer_bytes - 10);
    next_line(source);
    next_line(source);
    source.seek(straddling.offset, straddling.number);
    EXPECT_EQ(next_line(source), straddling);
    EXPECT_EQ(next_line(source), (Got{"G0 X2", straddling.number + 1, straddling.offset + straddling.text.size() + 1}));
}

TEST(ProgramSourceBuffer, SeeksForwardPastTheBuffer) {
    TempDir dir;
    const std::string text = long_program(2 * buffer_bytes + 500);
    const std::vector<Got> expected = expected_lines(text);
    ProgramSource source = open_file(dir.write("long.ngc", text));
    next_line(source);
    const Got& far = expected[expected.size() - 3];
    ASSERT_GT(far.offset, 2 * buffer_bytes);
    source.seek(far.offset, far.number);
    EXPECT_EQ(all_lines(source), std::vector<Got>(expected.end() - 3, expected.end()));
}

}  // namespace
}  // namespace nckit::test
