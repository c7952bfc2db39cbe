// Parsing of Custom Macro B: expression trees and their precedence, statements, keywords written
// with blanks or in lower case, where statements may stand, and the columns of format errors.
#include <memory>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "nckit/gcode/macro_alarms.hpp"
#include "nckit/gcode/parser.hpp"

namespace nckit {
namespace {

Block parsed(std::string_view line) {
    Block block;
    block.location = make_location(std::make_shared<const std::string>("m.ngc"), 3, 1);
    if (auto error = parse_block(line, block)) ADD_FAILURE() << "'" << line << "': " << format_diagnostic(*error);
    return block;
}

const char* op_name(ExprOp op) {
    switch (op) {
        case ExprOp::add:
            return "+";
        case ExprOp::subtract:
            return "-";
        case ExprOp::multiply:
            return "*";
        case ExprOp::divide:
            return "/";
        case ExprOp::mod:
            return "MOD";
        case ExprOp::bit_and:
            return "AND";
        case ExprOp::bit_or:
            return "OR";
        case ExprOp::bit_xor:
            return "XOR";
        case ExprOp::eq:
            return "EQ";
        case ExprOp::ne:
            return "NE";
        case ExprOp::gt:
            return "GT";
        case ExprOp::ge:
            return "GE";
        case ExprOp::lt:
            return "LT";
        case ExprOp::le:
            return "LE";
        default:
            return "?";
    }
}

const char* function_name(ExprFunction f) {
    static constexpr const char* names[] = {"SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "ROUND",
                                            "FIX", "FUP", "LN",  "EXP",  "POW",  "ADP",  "BIN",  "BCD"};
    return names[static_cast<int>(f)];
}

//! The tree under `index` in prefix form: `(+ 1 (* 2 #3))`.
std::string tree(const Block& block, std::int32_t index) {
    if (index < 0) return "<none>";
    const ExprNode& n = block.exprs.at(static_cast<std::size_t>(index));
    switch (n.op) {
        case ExprOp::number:
            return fmt::format("{}", n.value);
        case ExprOp::variable:
            return n.a >= 0 ? "#[" + tree(block, n.a) + "]" : fmt::format("#{}", n.value);
        case ExprOp::negate:
            return "(neg " + tree(block, n.a) + ")";
        case ExprOp::function:
            return fmt::format("({} {}{})", function_name(n.function), tree(block, n.a),
                               n.b >= 0 ? " " + tree(block, n.b) : "");
        default:
            return fmt::format("({} {} {})", op_name(n.op), tree(block, n.a), tree(block, n.b));
    }
}

//! The statement of `line` in a compact form.
std::string statement(std::string_view line) {
    Block b = parsed(line);
    const MacroStatement& s = b.statement;
    switch (s.kind) {
        case StatementKind::none:
            return "none";
        case StatementKind::assign:
            return tree(b, s.target) + " = " + tree(b, s.value);
        case StatementKind::go_to:
            return "GOTO " + tree(b, s.value);
        case StatementKind::if_goto:
            return "IF " + tree(b, s.condition) + " GOTO " + tree(b, s.value);
        case StatementKind::if_then:
            return "IF " + tree(b, s.condition) + " THEN " + tree(b, s.target) + " = " + tree(b, s.value);
        case StatementKind::while_do:
            return fmt::format("WHILE {} DO{}", tree(b, s.condition), s.loop);
        case StatementKind::do_loop:
            return fmt::format("DO{}", s.loop);
        case StatementKind::end_loop:
            return fmt::format("END{}", s.loop);
    }
    return "?";
}

//! The value expression assigned to #1 in `#1=<expression>`.
std::string expr(std::string_view expression) {
    std::string s = statement("#1=" + std::string(expression));
    return s.rfind("#1 = ", 0) == 0 ? s.substr(5) : "not an assignment: " + s;
}

//! `ALARM COL` of the format error in `line` (line 3 of m.ngc).
std::string error(std::string_view line) {
    Block block;
    block.location = make_location(std::make_shared<const std::string>("m.ngc"), 3, 1);
    auto d = parse_block(line, block);
    if (!d) {
        ADD_FAILURE() << "'" << line << "' parsed without error";
        return "";
    }
    EXPECT_EQ(d->location.line, 3U);
    EXPECT_EQ(d->location.file_name(), "m.ngc");
    return std::to_string(d->alarm) + " " + std::to_string(d->location.column);
}

// ---- expression trees ---------------------------------------------------------------------

TEST(MacroSyntax, MultiplicationBindsTighterThanAddition) {
    EXPECT_EQ(expr("1+2*3"), "(+ 1 (* 2 3))");
    EXPECT_EQ(expr("1*2+3"), "(+ (* 1 2) 3)");
    EXPECT_EQ(expr("1-6/2"), "(- 1 (/ 6 2))");
}

TEST(MacroSyntax, AndAndModAreMultiplicativeOrAndXorAdditive) {
    EXPECT_EQ(expr("1 OR 2 AND 3"), "(OR 1 (AND 2 3))");
    EXPECT_EQ(expr("1 XOR 2 MOD 3"), "(XOR 1 (MOD 2 3))");
    EXPECT_EQ(expr("1 AND 2 + 3"), "(+ (AND 1 2) 3)");
}

TEST(MacroSyntax, SameLevelGroupsLeftToRight) {
    EXPECT_EQ(expr("8-4-2"), "(- (- 8 4) 2)");
    EXPECT_EQ(expr("8/4/2"), "(/ (/ 8 4) 2)");
    EXPECT_EQ(expr("8/4*2 MOD 3"), "(MOD (* (/ 8 4) 2) 3)");
    EXPECT_EQ(expr("1+2 OR 3-4 XOR 5"), "(XOR (- (OR (+ 1 2) 3) 4) 5)");
}

TEST(MacroSyntax, BracketsGroup) {
    EXPECT_EQ(expr("[1+2]*3"), "(* (+ 1 2) 3)");
    EXPECT_EQ(expr("2*[[1+2]-[3]]"), "(* 2 (- (+ 1 2) 3))");
}

TEST(MacroSyntax, FunctionsBindTightest) {
    EXPECT_EQ(expr("SIN[30]*2"), "(* (SIN 30) 2)");
    EXPECT_EQ(expr("2+SQRT[#2+1]"), "(+ 2 (SQRT (+ #2 1)))");
    EXPECT_EQ(expr("ABS[-#3]"), "(ABS (neg #3))");
}

TEST(MacroSyntax, EveryFunctionName) {
    for (const char* f : {"SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "ROUND", "FIX", "FUP", "LN",
                          "EXP", "ADP", "BIN", "BCD"}) {
        EXPECT_EQ(expr(std::string(f) + "[#5]"), std::string("(") + f + " #5)") << f;
    }
    EXPECT_EQ(expr("POW[2,#5]"), "(POW 2 #5)");
}

TEST(MacroSyntax, AtanHasTwoForms) {
    EXPECT_EQ(expr("ATAN[1]/[2]"), "(ATAN 1 2)");
    EXPECT_EQ(expr("ATAN[#1,#2+1]"), "(ATAN #1 (+ #2 1))");
    EXPECT_EQ(expr("ATAN[1]"), "(ATAN 1)");
    // A division by something that is not bracketed is an ordinary division.
    EXPECT_EQ(expr("ATAN[1]/2"), "(/ (ATAN 1) 2)");
    EXPECT_EQ(expr("ATAN[1]/[2]*3"), "(* (ATAN 1 2) 3)");
}

TEST(MacroSyntax, NegationAndUnaryPlus) {
    EXPECT_EQ(expr("-#2"), "(neg #2)");
    EXPECT_EQ(expr("+#2"), "#2");
    EXPECT_EQ(expr("-2*3"), "(* (neg 2) 3)");
    EXPECT_EQ(expr("2*-3"), "(* 2 (neg 3))");
}

TEST(MacroSyntax, IndirectVariables) {
    EXPECT_EQ(expr("#[#2+100]"), "#[(+ #2 100)]");
    EXPECT_EQ(expr("#[#[#2]]"), "#[#[#2]]");
    EXPECT_EQ(statement("#[#2]=5"), "#[#2] = 5");
}

TEST(MacroSyntax, NumberForms) {
    EXPECT_EQ(expr(".5+5.+1 2.5"), "(+ (+ 0.5 5) 12.5)");
    EXPECT_EQ(expr("# 1 0"), "#10");
}

TEST(MacroSyntax, ComparisonsAreTheLowestLevel) {
    EXPECT_EQ(statement("IF [#1+1 GT 2*3] GOTO 5"), "IF (GT (+ #1 1) (* 2 3)) GOTO 5");
    EXPECT_EQ(statement("IF [[#1 EQ 1] OR [#2 NE #0]] GOTO 5"), "IF (OR (EQ #1 1) (NE #2 #0)) GOTO 5");
    for (const char* op : {"EQ", "NE", "GT", "GE", "LT", "LE"}) {
        EXPECT_EQ(statement(std::string("WHILE [#1 ") + op + " 2] DO1"), std::string("WHILE (") + op + " #1 2) DO1");
    }
}

TEST(MacroSyntax, ExpressionNodesCarryTheirColumns) {
    Block b = parsed("#1=2+SIN[#3]");
    const ExprNode& root = b.exprs.at(static_cast<std::size_t>(b.statement.value));
    EXPECT_EQ(root.column, 5U);  // the operator
    EXPECT_EQ(b.exprs.at(static_cast<std::size_t>(root.a)).column, 4U);
    EXPECT_EQ(b.exprs.at(static_cast<std::size_t>(root.b)).column, 6U);
    EXPECT_EQ(b.exprs.at(static_cast<std::size_t>(b.statement.target)).column, 1U);
    EXPECT_EQ(b.statement.column, 1U);
}

// ---- statements ----------------------------------------------------------------------------

TEST(MacroSyntax, EveryStatementKind) {
    EXPECT_EQ(statement("#5=#4*2"), "#5 = (* #4 2)");
    EXPECT_EQ(statement("GOTO 10"), "GOTO 10");
    EXPECT_EQ(statement("GOTO#10"), "GOTO #10");
    EXPECT_EQ(statement("GOTO[#1+1]"), "GOTO (+ #1 1)");
    EXPECT_EQ(statement("IF [#1 EQ 0] GOTO 20"), "IF (EQ #1 0) GOTO 20");
    EXPECT_EQ(statement("IF [#1 LT 0] THEN #2=-#1"), "IF (LT #1 0) THEN #2 = (neg #1)");
    EXPECT_EQ(statement("WHILE [#1 LE 3] DO2"), "WHILE (LE #1 3) DO2");
    EXPECT_EQ(statement("DO3"), "DO3");
    EXPECT_EQ(statement("END1"), "END1");
    EXPECT_EQ(statement("G1 X1"), "none");
}

TEST(MacroSyntax, KeywordsMayHoldBlanksAndBeLowerCase) {
    EXPECT_EQ(statement("G O T O 10"), "GOTO 10");
    EXPECT_EQ(statement("goto 10"), "GOTO 10");
    EXPECT_EQ(statement("I F[#1 G T 2]G O T O 7"), "IF (GT #1 2) GOTO 7");
    EXPECT_EQ(statement("if [#1 eq 1] then #2 = sqrt[4] mod 3"), "IF (EQ #1 1) THEN #2 = (MOD (SQRT 4) 3)");
    EXPECT_EQ(statement("W H I L E[#1LT3]D O 1"), "WHILE (LT #1 3) DO1");
    EXPECT_EQ(statement("while [1] do2"), "WHILE 1 DO2");
    EXPECT_EQ(statement("E N D 3"), "END3");
    EXPECT_EQ(statement("#1=a tan[1]/[2] x o r 3"), "#1 = (XOR (ATAN 1 2) 3)");
}

TEST(MacroSyntax, StatementAfterASequenceNumber) {
    Block b = parsed("N10 #1=2");
    EXPECT_EQ(b.statement.kind, StatementKind::assign);
    ASSERT_EQ(b.words.size(), 1U);
    EXPECT_EQ(b.words[0].letter, 'N');
    EXPECT_EQ(b.statement.column, 5U);
    EXPECT_EQ(statement("N20 WHILE [#1 LT 2] DO1"), "WHILE (LT #1 2) DO1");
    EXPECT_EQ(statement("/N30 END1"), "END1");
}

TEST(MacroSyntax, CommentAfterAStatementIsKept) {
    Block b = parsed("#3000=1 (SPINDLE NOT READY)");
    EXPECT_EQ(b.statement.kind, StatementKind::assign);
    EXPECT_EQ(b.comment, "SPINDLE NOT READY");
}

TEST(MacroSyntax, StatementMustStandAlone) {
    EXPECT_EQ(error("G1 #1=2"), "114 4");
    EXPECT_EQ(error("#1=2 G1"), "114 6");
    EXPECT_EQ(error("#1=2 #2=3"), "114 6");
    EXPECT_EQ(error("G1 X1 GOTO 5"), "114 7");
    EXPECT_EQ(error("GOTO 5 X1"), "114 8");
    EXPECT_EQ(error("N1 N2 #1=1"), "114 7");
    EXPECT_EQ(error("DO1 END1"), "114 5");
}

// ---- expressions in words ------------------------------------------------------------------

TEST(MacroSyntax, WordValuesMayBeExpressions) {
    Block b = parsed("G#1 X-#2 Y[#3+1] Z-[2]");
    ASSERT_EQ(b.words.size(), 4U);
    EXPECT_EQ(tree(b, b.words[0].expr), "#1");
    EXPECT_EQ(tree(b, b.words[1].expr), "(neg #2)");
    EXPECT_EQ(tree(b, b.words[2].expr), "(+ #3 1)");
    EXPECT_EQ(tree(b, b.words[3].expr), "(neg 2)");
    EXPECT_EQ(b.words[2].column, 10U);
    for (const Word& w : b.words) EXPECT_TRUE(w.has_decimal_point) << w.letter;
    Block plain = parsed("X2");
    EXPECT_EQ(plain.words[0].expr, -1);
}

TEST(MacroSyntax, WordExpressionIsOneOperand) {
    // Fanuc needs brackets around an operation in an address: X#1+2 is a format error.
    EXPECT_EQ(error("X#1+2"), "114 4");
    EXPECT_EQ(error("G1 X-#1*2"), "114 8");
    EXPECT_EQ(error("X[1]/2"), "114 5");
    EXPECT_EQ(error("X2+1"), "0 3");  // a plain number stays a syntax error
    EXPECT_EQ(error("X[#1+2"), "114 7");
}

// ---- format errors and their columns -------------------------------------------------------

TEST(MacroSyntax, NegativeVariableNumberIsAFormatError) {
    EXPECT_EQ(error("#1=#-1"), "114 4");
    EXPECT_EQ(error("X#-1"), "114 2");
    EXPECT_EQ(error("#1.5=2"), "114 1");
    EXPECT_EQ(error("#=2"), "114 1");
}

TEST(MacroSyntax, MalformedExpressions) {
    EXPECT_EQ(error("#1="), "114 4");
    EXPECT_EQ(error("#1=1+"), "114 6");
    EXPECT_EQ(error("#1=[1+2"), "114 8");
    EXPECT_EQ(error("#1=1+2]"), "114 7");
    EXPECT_EQ(error("#1=SIN 30"), "114 8");
    EXPECT_EQ(error("#1=FOO[1]"), "114 4");
    EXPECT_EQ(error("#1=POW[2]"), "114 4");
    EXPECT_EQ(error("#1=SIN[1,2]"), "114 9");
    EXPECT_EQ(error("#1 2"), "114 5");
    EXPECT_EQ(error("#1=1..2"), "114 6");
    EXPECT_EQ(error("#1=(1)"), "114 4");
}

TEST(MacroSyntax, MalformedStatements) {
    EXPECT_EQ(error("IF #1 GOTO 5"), "114 4");
    EXPECT_EQ(error("IF [#1 EQ 1] #2=3"), "114 14");
    EXPECT_EQ(error("IF [#1 EQ 1] THEN GOTO 5"), "114 19");
    EXPECT_EQ(error("IF [#1 EQ 1] GOTO"), "114 18");
    EXPECT_EQ(error("WHILE #1 DO1"), "114 7");
    EXPECT_EQ(error("WHILE [#1 LT 2] END1"), "114 17");
    EXPECT_EQ(error("IF [1 LT 2 LT 3] GOTO 5"), "114 12");
}

TEST(MacroSyntax, LoopNumberMustBeOneToThree) {
    EXPECT_EQ(error("DO4"), "126 3");
    EXPECT_EQ(error("DO0"), "126 3");
    EXPECT_EQ(error("END 4"), "126 5");
    EXPECT_EQ(error("WHILE [1] DO12"), "126 13");
    EXPECT_EQ(error("DO"), "126 3");
}

TEST(MacroSyntax, FiveBracketLevelsAreAllowedSixAreNot) {
    EXPECT_EQ(expr("[[[[[1]]]]]"), "1");
    EXPECT_EQ(error("#1=[[[[[[1]]]]]]"), "118 9");
    // Function brackets count.
    EXPECT_EQ(expr("SIN[[[[[1]]]]]"), "(SIN 1)");
    EXPECT_EQ(error("#1=SIN[[[[[[1]]]]]]"), "118 12");
    EXPECT_EQ(error("X[[[[[[1]]]]]]"), "118 7");
    // Depth is nesting, not the number of brackets side by side.
    EXPECT_EQ(expr("[[[[1]]]]+[[[[2]]]]+[3]"), "(+ (+ 1 2) 3)");
}

TEST(MacroSyntax, ErrorsAreMacroFormatDiagnostics) {
    Block block;
    block.location = make_location(std::make_shared<const std::string>("m.ngc"), 3, 1);
    auto d = parse_block("#1=1+", block);
    ASSERT_TRUE(d.has_value());
    EXPECT_EQ(d->code, "macro-format");
    EXPECT_EQ(d->alarm, alarm::format);
    EXPECT_EQ(d->severity, Severity::error);
    EXPECT_EQ(format_diagnostic(*d), "m.ngc:3:6: error: alarm 114: expression ends too early");
    d = parse_block("G1 Y#1+2", block);
    ASSERT_TRUE(d.has_value());
    EXPECT_EQ(d->message, "an operation in an address needs brackets: Y[...]");
}

}  // namespace
}  // namespace nckit
