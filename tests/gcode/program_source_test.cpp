#include "nckit/gcode/program_source.hpp"

#include <gtest/gtest.h>

#include "source_support.hpp"

namespace nckit::test {
namespace {

// ---- string input -----------------------------------------------------------------------

TEST(ProgramSourceString, SplitsLinesWithNumbersAndOffsets) {
    ProgramSource source = ProgramSource::from_string("G0 X1\nG1 Y2\nM30\n", "a.ngc");
    EXPECT_EQ(next_line(source), (Got{"G0 X1", 1, 0}));
    EXPECT_EQ(next_line(source), (Got{"G1 Y2", 2, 6}));
    EXPECT_EQ(next_line(source), (Got{"M30", 3, 12}));
    EXPECT_TRUE(at_end(source));
    EXPECT_TRUE(at_end(source)) << "the end repeats";
}

TEST(ProgramSourceString, KeepsTheNameItWasGiven) {
    ProgramSource source = ProgramSource::from_string("G0\n", "part.ngc");
    ASSERT_NE(source.file(), nullptr);
    EXPECT_EQ(*source.file(), "part.ngc");
}

TEST(ProgramSourceString, DropsTheCarriageReturnOfCrLf) {
    ProgramSource source = ProgramSource::from_string("G0 X1\r\nG1 Y2\r\n\r\nM30", "a.ngc");
    EXPECT_EQ(all_lines(source), (std::vector<Got>{{"G0 X1", 1, 0}, {"G1 Y2", 2, 7}, {"", 3, 14}, {"M30", 4, 16}}));
}

TEST(ProgramSourceString, KeepsACarriageReturnInsideALine) {
    ProgramSource source = ProgramSource::from_string("G0\rX1\n", "a.ngc");
    EXPECT_EQ(next_line(source), (Got{"G0\rX1", 1, 0}));
}

TEST(ProgramSourceString, ReadsALastLineWithoutNewline) {
    ProgramSource source = ProgramSource::from_string("G0\nM30", "a.ngc");
    EXPECT_EQ(all_lines(source), (std::vector<Got>{{"G0", 1, 0}, {"M30", 2, 3}}));
}

TEST(ProgramSourceString, ReturnsEmptyLines) {
    ProgramSource source = ProgramSource::from_string("\n\nG0\n\n", "a.ngc");
    EXPECT_EQ(all_lines(source), (std::vector<Got>{{"", 1, 0}, {"", 2, 1}, {"G0", 3, 2}, {"", 4, 5}}));
}

TEST(ProgramSourceString, EmptyTextHasNoLines) {
    ProgramSource source = ProgramSource::from_string("", "a.ngc");
    EXPECT_TRUE(at_end(source));
}

TEST(ProgramSourceString, SeeksBackAndRereads) {
    ProgramSource source = ProgramSource::from_string("A\nBB\nCCC\nDDDD\n", "a.ngc");
    next_line(source);
    Got second = next_line(source);
    next_line(source);
    next_line(source);
    EXPECT_TRUE(at_end(source));
    source.seek(second.offset, second.number);
    EXPECT_EQ(next_line(source), (Got{"BB", 2, 2}));
    EXPECT_EQ(next_line(source), (Got{"CCC", 3, 5}));
    source.seek(0, 1);
    EXPECT_EQ(next_line(source), (Got{"A", 1, 0}));
}

TEST(ProgramSourceString, LineOfExactlyTheLimitIsAccepted) {
    std::string longest(ProgramSource::max_line_bytes, 'X');
    ProgramSource source = ProgramSource::from_string("G0\n" + longest + "\nM30\n", "a.ngc");
    next_line(source);
    EXPECT_EQ(next_line(source).text.size(), ProgramSource::max_line_bytes);
    EXPECT_EQ(next_line(source), (Got{"M30", 3, 4 + ProgramSource::max_line_bytes}));
}

TEST(ProgramSourceString, LineLongerThanTheLimitIsAnErrorWithItsNumber) {
    std::string too_long(ProgramSource::max_line_bytes + 1, 'X');
    ProgramSource source = ProgramSource::from_string("G0\nG1\n" + too_long + "\nM30\n", "a.ngc");
    next_line(source);
    next_line(source);
    auto line = source.next();
    ASSERT_FALSE(line.ok());
    const Diagnostic& d = line.diagnostics().front();
    EXPECT_EQ(d.code, "line-too-long");
    EXPECT_EQ(d.location.line, 3U);
    EXPECT_EQ(d.location.column, 1U);
    EXPECT_EQ(d.location.file_name(), "a.ngc");
}

// ---- file input -------------------------------------------------------------------------

TEST(ProgramSourceFile, ReadsLinesOfASmallFile) {
    TempDir dir;
    ProgramSource source = open_file(dir.write("p.ngc", "G0 X1\r\n\nG1 Y2 F100\nM30"));
    EXPECT_EQ(all_lines(source), (std::vector<Got>{{"G0 X1", 1, 0}, {"", 2, 7}, {"G1 Y2 F100", 3, 8}, {"M30", 4, 19}}));
    EXPECT_EQ(*source.file(), (dir.path() / "p.ngc").string());
}

TEST(ProgramSourceFile, EmptyFileHasNoLines) {
    TempDir dir;
    ProgramSource source = open_file(dir.write("p.ngc", ""));
    EXPECT_TRUE(at_end(source));
}

TEST(ProgramSourceFile, NonexistentFileIsAnError) {
    TempDir dir;
    auto source = ProgramSource::open(dir.path() / "missing.ngc");
    ASSERT_FALSE(source.ok());
    const Diagnostic& d = source.diagnostics().front();
    EXPECT_EQ(d.code, "file");
    EXPECT_EQ(d.location.file_name(), (dir.path() / "missing.ngc").string());
    EXPECT_EQ(d.location.line, 0U);
    EXPECT_NE(d.message.find("No such file"), std::string::npos) << d.message;
}

TEST(ProgramSourceFile, DirectoryIsAnError) {
    TempDir dir;
    auto source = ProgramSource::open(dir.path());
    ASSERT_FALSE(source.ok());
    EXPECT_EQ(source.diagnostics().front().code, "file");
    EXPECT_EQ(source.diagnostics().front().message, "is a directory, not a program");
}

TEST(ProgramSourceFile, LineLongerThanTheLimitIsAnErrorWithItsNumber) {
    TempDir dir;
    std::string text = "G0\nG1 X1\n";
    text += std::string(ProgramSource::max_line_bytes + 100, 'X') + "\nM30\n";
    ProgramSource source = open_file(dir.write("p.ngc", text));
    next_line(source);
    next_line(source);
    auto line = source.next();
    ASSERT_FALSE(line.ok());
    EXPECT_EQ(line.diagnostics().front().code, "line-too-long");
    EXPECT_EQ(line.diagnostics().front().location.line, 3U);
}

TEST(ProgramSourceFile, SeeksBackWithinTheBuffer) {
    TempDir dir;
    ProgramSource source = open_file(dir.write("p.ngc", "O100\nG0 X1\nG1 X2 F100\nM99\nM30\n"));
    next_line(source);
    Got loop = next_line(source);
    next_line(source);
    next_line(source);
    source.seek(loop.offset, loop.number);
    EXPECT_EQ(next_line(source), (Got{"G0 X1", 2, 5}));
    EXPECT_EQ(next_line(source), (Got{"G1 X2 F100", 3, 11}));
}

TEST(ProgramSourceFile, SeeksBackAfterTheEnd) {
    TempDir dir;
    ProgramSource source = open_file(dir.write("p.ngc", "G0\nG1 X1\nM30"));
    all_lines(source);
    source.seek(3, 2);
    EXPECT_EQ(all_lines(source), (std::vector<Got>{{"G1 X1", 2, 3}, {"M30", 3, 9}}));
}

TEST(ProgramSourceFile, MovedSourceKeepsReading) {
    TempDir dir;
    ProgramSource source = open_file(dir.write("p.ngc", "G0\nG1 X1\n"));
    next_line(source);
    ProgramSource moved = std::move(source);
    EXPECT_EQ(next_line(moved), (Got{"G1 X1", 2, 3}));
    EXPECT_TRUE(at_end(moved));
}

}  // namespace
}  // namespace nckit::test
