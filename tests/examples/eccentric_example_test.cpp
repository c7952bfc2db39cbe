// The eccentric-shaft macro of examples/eccentric/ checked against the law of cosines:
// X(theta) = 2(e cos theta + sqrt(r^2 - e^2 sin^2 theta)) on the finishing pass.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <variant>
#include <vector>

#include "nckit/interp/interpreter.hpp"

namespace nckit {
namespace {

const std::filesystem::path root = NCKIT_SOURCE_DIR;
const std::filesystem::path example = root / "examples" / "eccentric";

constexpr double e_mm = 3.0;
constexpr double r_mm = 20.0;
constexpr double step_deg = 5.0;
constexpr double finishing_feed_mm_rev = 0.1;
constexpr double z_start_machine_mm = -20.0;  // K0 in G54, which sits at machine Z-20
constexpr double z_end_machine_mm = -50.0;

double profile_radius_mm(double theta_deg) {
    double t = theta_deg * std::numbers::pi / 180.0;
    return e_mm * std::cos(t) + std::sqrt(r_mm * r_mm - e_mm * e_mm * std::sin(t) * std::sin(t));
}

struct ProgramRun {
    std::vector<Move> moves;
    std::optional<Diagnostic> error;
};

ProgramRun run(const std::filesystem::path& program) {
    auto machine = load_machine_config(root / "examples" / "machines" / "lathe.toml");
    EXPECT_TRUE(machine.ok());
    auto source = ProgramSource::open(program);
    EXPECT_TRUE(source.ok());
    InterpreterOptions options;
    options.library_dir = example / "library";
    Interpreter interpreter(machine.value(), std::move(source).value(), options);
    ProgramRun result;
    for (;;) {
        InterpResult next = interpreter.next();
        if (auto* move = std::get_if<Move>(&next)) {
            result.moves.push_back(std::move(*move));
        } else {
            if (auto* d = std::get_if<Diagnostic>(&next)) result.error = *d;
            return result;
        }
    }
}

//! The G1 blocks of each pass: the feeds that follow each G32 lead-in.
std::vector<std::vector<Line>> passes(const std::vector<Move>& moves) {
    std::vector<std::vector<Line>> out;
    bool in_pass = false;
    for (const Move& move : moves) {
        if (std::holds_alternative<SyncMove>(move.what)) {
            out.emplace_back();
            in_pass = true;
        } else if (const auto* line = std::get_if<Line>(&move.what)) {
            if (line->rapid) {
                in_pass = false;
            } else if (in_pass) {
                out.back().push_back(*line);
            }
        }
    }
    return out;
}

TEST(EccentricExample, FinishingPassFollowsTheLawOfCosines) {
    ProgramRun r = run(example / "eccentric_shaft.nc");
    ASSERT_FALSE(r.error) << format_diagnostic(*r.error);
    auto all = passes(r.moves);
    ASSERT_EQ(all.size(), 7U);  // six roughing passes, then the finishing pass
    const std::vector<Line>& finish = all.back();
    const double turns = (z_start_machine_mm - z_end_machine_mm) / finishing_feed_mm_rev;
    ASSERT_EQ(finish.size(), static_cast<std::size_t>(std::lround(turns * 360.0 / step_deg)));
    for (std::size_t k = 0; k < finish.size(); ++k) {
        double theta = step_deg * static_cast<double>(k + 1);
        // Addresses are rounded to 0.001 (X on the diameter): 0.0005 mm of radius at most.
        EXPECT_NEAR(finish[k].to[Axis::X], profile_radius_mm(theta), 0.0005 + 1e-9) << "theta " << theta;
        EXPECT_NEAR(finish[k].to[Axis::Z], z_start_machine_mm - finishing_feed_mm_rev * theta / 360.0, 0.0005 + 1e-9);
        // Each block takes its share of a turn: path length / feed per turn = step / 360.
        const Line& l = finish[k];
        double length = std::hypot(l.to[Axis::X] - l.from[Axis::X], l.to[Axis::Z] - l.from[Axis::Z]);
        EXPECT_NEAR(length / l.feed.mm_per_rev, step_deg / 360.0, 2e-3) << "theta " << theta;
    }
}

TEST(EccentricExample, WorkedNumbersOfTheReference) {
    // X(0) = 46, X(90) = 39.547440, X(180) = 34 on the diameter (docs/processes/eccentric.md).
    ProgramRun r = run(example / "eccentric_shaft.nc");
    ASSERT_FALSE(r.error);
    const auto all = passes(r.moves);
    ASSERT_FALSE(all.empty());
    const std::vector<Line>& finish = all.back();
    auto diameter_at = [&](double theta) {
        return 2.0 * finish[static_cast<std::size_t>(theta / step_deg) - 1].to[Axis::X];
    };
    EXPECT_NEAR(diameter_at(360.0), 46.0, 1e-3);
    EXPECT_NEAR(diameter_at(90.0), 39.547, 1e-3);
    EXPECT_NEAR(diameter_at(180.0), 34.0, 1e-3);
    EXPECT_NEAR(diameter_at(270.0), 39.547, 1e-3);
}

TEST(EccentricExample, EveryPassStartsAtTheSameSpindleAngle) {
    ProgramRun r = run(example / "eccentric_shaft.nc");
    ASSERT_FALSE(r.error);
    int leads = 0;
    for (const Move& move : r.moves) {
        const auto* sync = std::get_if<SyncMove>(&move.what);
        if (sync == nullptr) continue;
        ++leads;
        // The lead-in ends at the pass's start after whole turns: spindle angle 0 every time.
        double turns = (sync->from[Axis::Z] - sync->to[Axis::Z]) / sync->feed.mm_per_rev;
        EXPECT_NEAR(turns, std::round(turns), 1e-9);
        EXPECT_NEAR(sync->to[Axis::Z], z_start_machine_mm, 1e-9);
    }
    EXPECT_EQ(leads, 7);
}

TEST(EccentricExample, RoughingPassesStayOutsideTheFinishedProfile) {
    ProgramRun r = run(example / "eccentric_shaft.nc");
    ASSERT_FALSE(r.error);
    auto all = passes(r.moves);
    for (std::size_t p = 0; p + 1 < all.size(); ++p) {
        for (std::size_t k = 0; k < all[p].size(); ++k) {
            double theta = step_deg * static_cast<double>(k + 1);
            EXPECT_GE(all[p][k].to[Axis::X], profile_radius_mm(theta) + 0.2 - 0.001) << "pass " << p;
        }
    }
}

TEST(EccentricExample, EccentricityNotBelowTheRadiusIsAnAlarm) {
    std::filesystem::path program = std::filesystem::temp_directory_path() / "nckit_eccentric_bad.nc";
    std::ofstream(program) << "G21 G18\nG97 S60 M3\nG65 P9100 D60. E20. R20. K0 Z-30. Q2.5 F0.3 H0.1 U0.4\nM30\n";
    ProgramRun r = run(program);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->alarm, 3001);
    EXPECT_EQ(r.error->message, "ECCENTRICITY MUST BE SMALLER THAN THE ECCENTRIC RADIUS");
    EXPECT_NE(r.error->location.file_name().find("O9100.nc"), std::string::npos);
    EXPECT_EQ(r.error->location.line, 6U);
    std::filesystem::remove(program);
}

}  // namespace
}  // namespace nckit
