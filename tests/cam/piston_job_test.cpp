#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "nckit/process/piston/piston_job.hpp"

namespace nckit::cam {
namespace {

const std::string base_job = R"~([piston]
rpm = 2500
z_mm = [0.0, 10.0, 20.0, 30.0, 40.0, 50.0]
major_diameter_mm = [89.80, 89.90, 89.96, 89.98, 89.96, 89.92]
ovality_mm = [0.40, 0.50, 0.60, 0.70, 0.75, 0.80]
shape = "ellipse2"
[servo]
natural_frequency_hz = 135.0
damping = 0.3
dac_bits = 16
stroke_mm = 1.0
model_error = 0.10
)~";

//! `text` with the line that starts with `key = ` replaced by `line` (removed when empty).
std::string with(std::string text, std::string_view key, std::string_view line) {
    const std::string start = "\n" + std::string(key) + " = ";
    const std::size_t at = text.find(start);
    if (at == std::string::npos) throw std::logic_error("no key " + std::string(key));
    const std::size_t end = text.find('\n', at + 1);
    text.replace(at + 1, end - at, line.empty() ? std::string() : std::string(line) + "\n");
    return text;
}

//! `text` with `lines` added at the end of [piston] (before [servo]).
std::string in_piston(std::string text, std::string_view lines) {
    return text.insert(text.find("[servo]"), std::string(lines));
}

Result<PistonJob> parse(const std::string& text) {
    return parse_piston_job(text, "job.toml");
}

//! 1-based line and column of `needle`'s byte `offset` in `text`.
std::pair<std::uint32_t, std::uint32_t> where(const std::string& text, std::string_view needle,
                                              std::size_t offset = 0) {
    const std::size_t at = text.find(needle);
    if (at == std::string::npos) throw std::logic_error("no " + std::string(needle));
    const std::size_t pos = at + offset;
    const std::size_t line_start = text.rfind('\n', pos == 0 ? 0 : pos - 1);
    const std::size_t column = line_start == std::string::npos ? pos + 1 : pos - line_start;
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(pos), '\n');
    return {static_cast<std::uint32_t>(line), static_cast<std::uint32_t>(column)};
}

//! The job fails with a diagnostic at `needle` (+ `offset`) whose message holds `words`.
void expect_error(const std::string& text, std::string_view needle, std::size_t offset, std::string_view words) {
    const Result<PistonJob> job = parse(text);
    ASSERT_FALSE(job.ok()) << "no error for:\n" << text;
    const auto [line, column] = where(text, needle, offset);
    std::string all;
    for (const Diagnostic& d : job.diagnostics()) {
        all += format_diagnostic(d) + "\n";
        if (d.location.line == line && d.location.column == column && d.message.find(words) != std::string::npos) {
            EXPECT_EQ(d.location.file_name(), "job.toml");
            return;
        }
    }
    ADD_FAILURE() << "expected job.toml:" << line << ":" << column << " '" << words << "', got:\n" << all;
}

TEST(CamPistonJob, ReadsTheDocumentedSchema) {
    const Result<PistonJob> job = parse(base_job);
    ASSERT_TRUE(job.ok()) << format_diagnostic(job.diagnostics().front());
    EXPECT_EQ(job->rpm, 2500);
    EXPECT_EQ(job->z_mm, (std::vector<double>{0, 10, 20, 30, 40, 50}));
    EXPECT_EQ(job->z_breaks_mm, job->z_mm);
    EXPECT_EQ(job->profile.shape().kind(), ShapeKind::ellipse2);
    EXPECT_NEAR(job->profile.major_diameter_mm(30), 89.98, 1e-12);
    EXPECT_NEAR(job->profile.ovality_mm(40), 0.75, 1e-12);
    EXPECT_NEAR(job->profile.radius_mm(0, 50), 44.96, 1e-12);
    EXPECT_NEAR(job->profile.radius_mm(90, 50), 44.96 - 0.4, 1e-12);
    EXPECT_EQ(job->servo.natural_frequency_hz, 135.0);
    EXPECT_EQ(job->servo.damping, 0.3);
    EXPECT_EQ(job->servo.dac_bits, 16);
    EXPECT_EQ(job->servo.stroke_mm, 1.0);
    EXPECT_EQ(job->servo.model_error, 0.10);
    // Optional keys at their defaults.
    EXPECT_EQ(job->servo.max_acceleration_g, 13.0);
    EXPECT_EQ(job->feed_mm_rev, 0.1);
    EXPECT_EQ(job->encoder_counts, 360);
    EXPECT_EQ(job->spindle_ripple, 0.0);
    // docs/processes/piston.md: E 0.8 at 2500 rpm is 0.2 mm at 83.3 Hz, ≈ 54,800 mm/s² ≈ 5.6 g.
    EXPECT_NEAR(job->demand.stroke_mm, 0.4, 1e-9);
    EXPECT_NEAR(job->demand.stroke_z_mm, 50, 1e-9);
    EXPECT_NEAR(job->demand.acceleration_mm_s2(2500), 54831, 5);
    EXPECT_NEAR(job->demand.curvature_z_mm, 50, 1e-9);
}

TEST(CamPistonJob, ReadsTheOptionalKeys) {
    std::string text = in_piston(base_job, "feed_mm_rev = 0.2\nencoder_counts = 4096\nspindle_ripple = 0.01\n");
    text += "max_acceleration_g = 20\n";
    const Result<PistonJob> job = parse(with(text, "dac_bits", ""));
    ASSERT_TRUE(job.ok()) << format_diagnostic(job.diagnostics().front());
    EXPECT_EQ(job->feed_mm_rev, 0.2);
    EXPECT_EQ(job->encoder_counts, 4096);
    EXPECT_EQ(job->spindle_ripple, 0.01);
    EXPECT_EQ(job->servo.max_acceleration_g, 20);
    EXPECT_EQ(job->servo.dac_bits, 16);
}

TEST(CamPistonJob, ReadsEveryShape) {
    const std::string four =
        in_piston(with(base_job, "shape", R"~(shape = "ellipse4")~"), "e4_mm = [0.0, 0.01, 0.02, 0.02, 0.01, 0.0]\n");
    const Result<PistonJob> a = parse(four);
    ASSERT_TRUE(a.ok()) << format_diagnostic(a.diagnostics().front());
    EXPECT_EQ(a->profile.shape().kind(), ShapeKind::ellipse4);
    // (E/4)(1 − cos 90°) + (E4/4)(1 − cos 180°) at 45°, Z 20: E 0.6, E4 0.02.
    EXPECT_NEAR(a->profile.radius_mm(45, 20), 89.96 / 2 - 0.15 - 0.01, 1e-12);
    const Result<PistonJob> b = parse(with(base_job, "shape", R"~(shape = "ellipse")~"));
    ASSERT_TRUE(b.ok());
    EXPECT_EQ(b->profile.shape().kind(), ShapeKind::ellipse);
    EXPECT_NEAR(b->profile.radius_mm(90, 20), (89.96 - 0.6) / 2, 1e-12);
    const Result<PistonJob> c = parse(with(base_job, "shape", R"~(shape_formula = "E/4*(1 - cosd(2*PHI))")~"));
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c->profile.shape().kind(), ShapeKind::formula);
    EXPECT_NEAR(c->profile.radius_mm(30, 10), 89.9 / 2 - 0.125 / 2, 1e-12);
}

TEST(CamPistonJob, TheExamplesLoad) {
    for (const char* name : {"piston.toml", "piston_formula.toml"}) {
        const Result<PistonJob> job = load_piston_job(std::string(NCKIT_SOURCE_DIR) + "/examples/piston/" + name);
        ASSERT_TRUE(job.ok()) << format_diagnostic(job.diagnostics().front());
    }
}

TEST(CamPistonJob, FormulaAndTableAgree) {
    // A linear drawing: the natural spline through its stations is the line itself, even
    // beyond the ends, so table and formula jobs give the same piston everywhere.
    std::string table =
        with(base_job, "major_diameter_mm", "major_diameter_mm = [89.8, 89.84, 89.88, 89.92, 89.96, 90.0]");
    std::string formula = with(base_job, "major_diameter_mm", R"~(major_diameter_mm = "89.8 + 0.004*Z")~");
    formula = with(formula, "ovality_mm", R"~(ovality_mm = "0.4 + 0.008*Z")~");
    table = with(table, "ovality_mm", "ovality_mm = [0.40, 0.48, 0.56, 0.64, 0.72, 0.80]");
    const Result<PistonJob> a = parse(table);
    const Result<PistonJob> b = parse(formula);
    ASSERT_TRUE(a.ok() && b.ok());
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> theta(0, 360), z(-20, 70);
    for (int i = 0; i < 10000; ++i) {
        const double t = theta(rng), zz = z(rng);
        ASSERT_NEAR(a->profile.radius_mm(t, zz), b->profile.radius_mm(t, zz), 1e-12);
    }
}

TEST(CamPistonJob, AFineTableFollowsItsFormula) {
    // A barrel D = 89.98 − 0.0002 (Z − 30)² tabulated every 1 mm: the free ends make the spline
    // differ near the ends (D'' is not 0 there), by an error that dies away inwards.
    std::string z = "z_mm = [", d = "major_diameter_mm = [", e = "ovality_mm = [";
    for (int i = 0; i <= 50; ++i) {
        const double v = 89.98 - 0.0002 * (i - 30) * (i - 30);
        z += std::to_string(i) + (i < 50 ? ", " : "]");
        d += fmt::format("{:.17g}", v) + (i < 50 ? ", " : "]");
        e += std::string("0.5") + (i < 50 ? ", " : "]");
    }
    std::string table = with(with(with(base_job, "z_mm", z), "major_diameter_mm", d), "ovality_mm", e);
    std::string formula = with(base_job, "major_diameter_mm", R"~(major_diameter_mm = "89.98 - 0.0002*(Z - 30)^2")~");
    formula = with(formula, "ovality_mm", "ovality_mm = 0.5");
    const Result<PistonJob> a = parse(table);
    const Result<PistonJob> b = parse(formula);
    ASSERT_TRUE(a.ok()) << format_diagnostic(a.diagnostics().front());
    ASSERT_TRUE(b.ok()) << format_diagnostic(b.diagnostics().front());
    for (double zz = 0; zz <= 50; zz += 0.05) {
        const double difference = std::abs(a->profile.major_diameter_mm(zz) - b->profile.major_diameter_mm(zz));
        EXPECT_LE(difference, 2e-5) << zz;
        if (zz >= 10 && zz <= 40) {
            EXPECT_LE(difference, 1e-9) << zz;
        }
    }
}

TEST(CamPistonJob, SegmentsMakeBreaks) {
    std::string text = with(base_job, "ovality_mm", "");
    text = in_piston(text, R"~([[piston.segment]]
z_from_mm = 0
z_to_mm = 25
ovality_mm = "0.4 + 0.01*Z"
[[piston.segment]]
z_from_mm = 25
z_to_mm = 50
ovality_mm = "0.65 + 0.006*(Z - 25)"
)~");
    const Result<PistonJob> job = parse(text);
    ASSERT_TRUE(job.ok()) << format_diagnostic(job.diagnostics().front());
    EXPECT_EQ(job->z_breaks_mm, (std::vector<double>{0, 10, 20, 25, 30, 40, 50}));
    EXPECT_NEAR(job->profile.ovality_mm(40), 0.74, 1e-12);
}

// --- Every validation error, at its file position ---------------------------------------

TEST(CamPistonJobError, FormulaSyntaxAtTheColumnOfTheFault) {
    const std::string text = with(base_job, "major_diameter_mm", R"~(major_diameter_mm = "89.9 + * Z")~");
    expect_error(text, "\"89.9 + * Z\"", 8, "formula syntax in 'major_diameter_mm'");
    const std::string shape = with(base_job, "shape", R"~(shape_formula = "E/4*(1 - cosd(2*PHIX))")~");
    expect_error(shape, "PHIX", 0, "unexpected token \"PHIX\"");
    const std::string literal = with(base_job, "ovality_mm", "ovality_mm = '0.4 + (0.01*Z'");
    // muparser finds the missing ')' at the end: the column of the closing quote.
    expect_error(literal, "'0.4 + (0.01*Z'", 14, "missing parenthesis");
}

TEST(CamPistonJobError, ArraysOfDifferentLengths) {
    const std::string text = with(base_job, "ovality_mm", "ovality_mm = [0.4, 0.5, 0.6]");
    expect_error(text, "[0.4, 0.5, 0.6]", 0, "'ovality_mm' has 3 values for the 6 stations");
}

TEST(CamPistonJobError, StationsMustIncreaseStrictly) {
    const std::string text = with(base_job, "z_mm", "z_mm = [0.0, 10.0, 20.0, 20.0, 40.0, 50.0]");
    expect_error(text, "20.0, 40.0", 0, "'z_mm' must increase strictly: 20 follows 20");
    const std::string one = with(base_job, "z_mm", "z_mm = [0.0]");
    expect_error(one, "[0.0]", 0, "at least 2 stations");
    const std::string text_entry = with(base_job, "z_mm", R"~(z_mm = [0.0, "ten", 20.0, 30, 40, 50])~");
    expect_error(text_entry, "\"ten\"", 0, "each entry of 'z_mm' must be a number");
}

TEST(CamPistonJobError, ImpossibleDiametersAndOvality) {
    expect_error(with(base_job, "major_diameter_mm", "major_diameter_mm = [89.80, 89.90, -89.96, 89.98, 89.96, 89.92]"),
                 "-89.96", 0, "a diameter must be positive");
    expect_error(with(base_job, "major_diameter_mm", "major_diameter_mm = [89.80, 89.90, 89.96, 89.98, 8996, 89.92]"),
                 "8996", 0, "not a piston");
    expect_error(with(base_job, "ovality_mm", "ovality_mm = [0.40, 0.50, -0.1, 0.70, 0.75, 0.80]"), "-0.1", 0,
                 "must be zero or more");
    expect_error(with(base_job, "ovality_mm", "ovality_mm = [0.40, 0.50, 0.60, 90.0, 0.75, 0.80]"), "90.0", 0,
                 "less than the major diameter");
    // A spline that dips below zero between stations is found on the fine grid.
    expect_error(with(base_job, "ovality_mm", "ovality_mm = [0.0, 0.0, 0.0, 0.9, 0.0, 0.0]"), "[0.0, 0.0, 0.0, 0.9", 0,
                 "must be zero or more");
    // A formula that goes wrong somewhere along Z.
    expect_error(with(base_job, "ovality_mm", R"~(ovality_mm = "0.8 - 0.02*Z")~"), "\"0.8 - 0.02*Z\"", 0,
                 "'ovality_mm' is -0.0");
    expect_error(with(base_job, "major_diameter_mm", R"~(major_diameter_mm = "90/(Z-25)")~"), "\"90/(Z-25)\"", 0,
                 "a diameter must be positive");
}

TEST(CamPistonJobError, SpindleAndServoRanges) {
    expect_error(with(base_job, "rpm", "rpm = 0"), "rpm = 0", 6, "'rpm' must be positive");
    expect_error(with(base_job, "rpm", "rpm = 250000"), "250000", 0, "at most 100000");
    expect_error(with(base_job, "stroke_mm", "stroke_mm = 0"), "stroke_mm = 0", 12, "'stroke_mm' must be positive");
    expect_error(with(base_job, "damping", "damping = -0.1"), "-0.1", 0, "'damping' must be zero or more");
    expect_error(with(base_job, "dac_bits", "dac_bits = 0"), "dac_bits = 0", 11, "from 1 to 32");
    expect_error(with(base_job, "dac_bits", "dac_bits = 33"), "33", 0, "from 1 to 32");
    expect_error(with(base_job, "dac_bits", "dac_bits = 16.5"), "16.5", 0, "must be an integer");
    expect_error(with(base_job, "model_error", "model_error = 0.95"), "0.95", 0, "at most 0.9");
    expect_error(with(base_job, "model_error", "model_error = -0.1"), "-0.1", 0, "'model_error' must be zero or more");
    expect_error(with(base_job, "natural_frequency_hz", "natural_frequency_hz = -135"), "-135", 0, "must be positive");
    expect_error(in_piston(base_job, "encoder_counts = 0\n"), "encoder_counts = 0", 17, "from 1 to 10000000");
    expect_error(in_piston(base_job, "feed_mm_rev = -0.1\n"), "-0.1", 0, "must be positive");
    expect_error(in_piston(base_job, "spindle_ripple = 0.7\n"), "spindle_ripple = 0.7", 17, "at most 0.5");
}

TEST(CamPistonJobError, ProfileNeedsMoreStrokeThanTheServoHas) {
    const std::string text = with(base_job, "stroke_mm", "stroke_mm = 0.35");
    // E 0.8 at Z 50 swings the radius over 0.4 mm.
    expect_error(text, "[0.40, 0.50", 0, "needs 0.4000 mm of stroke");
}

TEST(CamPistonJobError, ProfileNeedsMoreAccelerationThanTheServoHasAtTheRpm) {
    // 5.6 g at 2500 rpm; at 4000 rpm (4000/2500)² × 5.59 ≈ 14.3 g > 13 g.
    const std::string text = with(base_job, "rpm", "rpm = 4000");
    expect_error(text, "rpm = 4000", 6, "more than the servo's 'max_acceleration_g' = 13; at most 3812 rpm");
    // E = 2 mm needs ≈ 14 g at 2500 rpm (docs/processes/piston.md): more than 13 g.
    std::string big = with(with(base_job, "ovality_mm", "ovality_mm = 2.0"), "stroke_mm", "stroke_mm = 1.5");
    expect_error(big, "rpm = 2500", 6, "(13.98 g)");
    EXPECT_TRUE(parse(with(big, "rpm", "rpm = 2000")).ok());  // ≈ 9 g
}

TEST(CamPistonJobError, SegmentGapOverlapCoverageAndSteps) {
    const std::string no_e = with(base_job, "ovality_mm", "");
    auto segments = [&](std::string_view first_to, std::string_view second_from, std::string_view second_to,
                        std::string_view second_formula) {
        return in_piston(no_e, fmt::format(R"~([[piston.segment]]
z_from_mm = 0
z_to_mm = {}
ovality_mm = "0.4 + 0.01*Z"
[[piston.segment]]
z_from_mm = {}
z_to_mm = {}
ovality_mm = "{}"
)~",
                                           first_to, second_from, second_to, second_formula));
    };
    const std::string gap = segments("20", "25", "50", "0.65 + 0.005*(Z-25)");
    expect_error(gap, "z_from_mm = 25", 12, "not given between Z 20 and 25 mm");
    const std::string overlap = segments("30", "25", "50", "0.65 + 0.005*(Z-25)");
    expect_error(overlap, "z_from_mm = 25", 12, "intervals overlap between Z 25 and 30 mm");
    const std::string short_end = segments("25", "25", "45", "0.65 + 0.005*(Z-25)");
    expect_error(short_end, "z_to_mm = 45", 10, "to the last station Z 50 mm");
    const std::string step = segments("25", "25", "50", "0.66 + 0.005*(Z-25)");
    expect_error(step, "z_from_mm = 25", 12, "jumps by 0.01 mm at Z 25 mm");
    const std::string reversed = segments("25", "25", "20", "0.65");
    expect_error(reversed, "z_to_mm = 20", 10, "'z_to_mm' must be greater than 'z_from_mm'");
    const std::string twice = in_piston(base_job, R"~([[piston.segment]]
z_from_mm = 0
z_to_mm = 50
ovality_mm = "0.5"
)~");
    expect_error(twice, "\"0.5\"", 0, "given in [piston] (line 5) and again");
    const std::string bad_formula = segments("25", "25", "50", "0.65 + 0.005*(Z-25");
    expect_error(bad_formula, "(Z-25\"", 5, "missing parenthesis");
    const std::string empty = in_piston(base_job, "[[piston.segment]]\nz_from_mm = 0\nz_to_mm = 50\n");
    expect_error(empty, "[[piston.segment]]", 0, "gives none of");
}

TEST(CamPistonJobError, ShapeChoices) {
    expect_error(with(base_job, "shape", ""), "[piston]", 0, "missing key 'shape'");
    expect_error(with(base_job, "shape", R"~(shape = "oval")~"), "\"oval\"", 0,
                 "shape 'oval' is not one of ellipse2 ellipse4 ellipse");
    expect_error(in_piston(base_job, "shape_formula = \"0\"\n"), "shape_formula", 16, "not both");
    EXPECT_EQ(parse(in_piston(base_job, "shape_formula = \"0\"\n")).diagnostics().size(), 1u);
    expect_error(with(base_job, "shape", R"~(shape = "ellipse4")~"), "\"ellipse4\"", 0, "needs 'e4_mm'");
    expect_error(in_piston(base_job, "e4_mm = 0.01\n"), "0.01\n", 0, "used only by shape 'ellipse4'");
    // A shape formula whose radius is not finite somewhere (1/0 at PHI 90).
    expect_error(with(base_job, "shape", R"~(shape_formula = "E/(PHI-90)")~"), "\"E/(PHI-90)\"", 0,
                 "the section's radius is -inf mm at Z 0 mm, PHI 90°");
}

TEST(CamPistonJobError, FileAndTablesAndKeys) {
    expect_error(base_job + "bogus = 1\n", "bogus", 0, "unknown key 'bogus' in [servo]");
    expect_error(in_piston(base_job, "rmp = 2500\n"), "rmp", 0, "unknown key 'rmp' in [piston]");
    const std::string no_servo = base_job.substr(0, base_job.find("[servo]"));
    expect_error(no_servo, "[piston]", 0, "missing table [servo]");
    expect_error(with(base_job, "rpm", "rpm = = 2"), "= = 2", 2, "toml syntax error");
    expect_error(with(base_job, "major_diameter_mm", "major_diameter_mm = true"), "true", 0,
                 "numbers at the stations, a formula string or a number");
    const Result<PistonJob> missing = load_piston_job("/nonexistent/piston.toml");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.diagnostics().front().code, "config-io");
    EXPECT_NE(missing.diagnostics().front().message.find("cannot read piston job"), std::string::npos);
}

TEST(CamPistonJobError, EveryErrorInOnePass) {
    std::string text = with(base_job, "rpm", "rpm = -1");
    text = with(text, "damping", "damping = -1");
    text = with(text, "shape", R"~(shape = "oval")~");
    const Result<PistonJob> job = parse(text);
    ASSERT_FALSE(job.ok());
    EXPECT_EQ(job.diagnostics().size(), 3u);
    // In file order.
    EXPECT_LT(job.diagnostics()[0].location.line, job.diagnostics()[1].location.line);
    EXPECT_LT(job.diagnostics()[1].location.line, job.diagnostics()[2].location.line);
}

}  // namespace
}  // namespace nckit::cam
