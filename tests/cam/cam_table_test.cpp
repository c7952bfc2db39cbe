#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "nckit/cam/cam_table.hpp"
#include "nckit/cam/encoder_cam.hpp"
#include "nckit/cam/piston_cam.hpp"
#include "nckit/process/piston/piston_job.hpp"

namespace nckit::cam {
namespace {

constexpr double pi = std::numbers::pi;

PistonJob example(const std::string& name) {
    Result<PistonJob> job = load_piston_job(std::string(NCKIT_SOURCE_DIR) + "/examples/piston/" + name);
    if (!job) {
        for (const Diagnostic& d : job.diagnostics()) ADD_FAILURE() << format_diagnostic(d);
        throw std::runtime_error("example does not load");
    }
    return std::move(job).value();
}

//! Largest |table − f| over `samples` seeded random points of the table's range.
double random_error(const CamTable& table, const CamFunction& f, std::uint64_t seed, int samples = 100000) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> theta(0, 360);
    std::uniform_real_distribution<double> z(table.z_from_mm(), table.z_to_mm());
    double worst = 0;
    for (int i = 0; i < samples; ++i) {
        const double t = theta(rng), zz = z(rng);
        worst = std::max(worst, std::abs(table(t, zz) - f(t, zz)));
    }
    return worst;
}

TEST(CamTable, ErrorBoundHoldsOnRandomPointsOfTheExamplePiston) {
    const PistonJob job = example("piston.toml");
    const CamTable table = build_cam_table(job);
    EXPECT_TRUE(table.meets_tolerance());
    EXPECT_LE(table.error_bound_mm(), 1e-6);
    EXPECT_GE(table.error_bound_mm(), table.checked_error_mm());
    const double seen = random_error(table, std::cref(job.profile), 1);
    EXPECT_LE(seen, table.error_bound_mm());
    // Stations every 10 mm, so the Z nodes fall on them.
    EXPECT_EQ(table.z_cells() % 5, 0u);
    EXPECT_EQ(table.z_from_mm(), 0.0);
    EXPECT_EQ(table.z_to_mm(), 50.0);
}

TEST(CamTable, ErrorBoundHoldsAcrossAFormulaIntervalBend) {
    // piston_formula.toml's ovality bends at Z 30 (slope 0.01 then 0.005): the one-sided Z
    // derivatives keep the patches either side of the node exact.
    const PistonJob job = example("piston_formula.toml");
    const CamTable table = build_cam_table(job);
    EXPECT_TRUE(table.meets_tolerance());
    const double seen = random_error(table, std::cref(job.profile), 2);
    EXPECT_LE(seen, table.error_bound_mm());
    // Around the bend itself.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> theta(0, 360), z(29.5, 30.5);
    for (int i = 0; i < 20000; ++i) {
        const double t = theta(rng), zz = z(rng);
        ASSERT_LE(std::abs(table(t, zz) - job.profile.radius_mm(t, zz)), table.error_bound_mm());
    }
}

TEST(CamTable, ErrorBoundHoldsForRandomSmoothProfiles) {
    // Random drawings: ovality, 4th harmonic and barrel amplitude, at several tolerances.
    std::mt19937_64 rng(20240612);
    std::uniform_real_distribution<double> ovality(0.1, 2.0), e4(-0.05, 0.05), barrel(0, 0.3);
    std::uniform_real_distribution<double> length(5, 120);
    for (int trial = 0; trial < 12; ++trial) {
        const double e = ovality(rng), h4 = e4(rng), b = barrel(rng), l = length(rng);
        const double tolerance = trial % 3 == 0 ? 1e-7 : trial % 3 == 1 ? 1e-6 : 1e-5;
        const CamFunction f = [=](double theta_deg, double z) {
            const double phi = theta_deg * pi / 180;
            const double s = z / l;
            const double d = 90 - b * (2 * s - 1) * (2 * s - 1);
            const double ez = e * (0.6 + 0.4 * s);
            return d / 2 - ez / 4 * (1 - std::cos(2 * phi)) - h4 / 4 * (1 - std::cos(4 * phi));
        };
        CamTableOptions options;
        options.z_to_mm = l;
        options.tolerance_mm = tolerance;
        const CamTable table = CamTable::build(f, options);
        EXPECT_TRUE(table.meets_tolerance()) << "trial " << trial;
        EXPECT_LE(random_error(table, f, 100 + trial, 20000), table.error_bound_mm())
            << "trial " << trial << ": " << table.theta_cells() << " x " << table.z_cells();
    }
}

TEST(CamTable, TighterToleranceTakesMoreCells) {
    const PistonJob job = example("piston.toml");
    const CamTable coarse = build_cam_table(job, 1e-4);
    const CamTable fine = build_cam_table(job, 1e-8);
    EXPECT_LT(coarse.theta_cells(), fine.theta_cells());
    EXPECT_LE(coarse.error_bound_mm(), 1e-4);
    EXPECT_LE(fine.error_bound_mm(), 1e-8);
    EXPECT_LE(random_error(fine, std::cref(job.profile), 3, 20000), fine.error_bound_mm());
    EXPECT_LE(random_error(coarse, std::cref(job.profile), 4, 20000), coarse.error_bound_mm());
}

TEST(CamTable, WrapsAnyAngleAndHoldsTheEndRowsOutsideZ) {
    const PistonJob job = example("piston.toml");
    const CamTable table = build_cam_table(job);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> theta(0, 360), z(0, 50);
    std::uniform_int_distribution<int> turns(-1000, 1000);
    for (int i = 0; i < 10000; ++i) {
        const double t = theta(rng), zz = z(rng);
        const double shifted = t + 360.0 * turns(rng);
        // The shifted angle carries its own rounding (up to 1e-10 deg at 1000 turns).
        EXPECT_NEAR(table(shifted, zz), table(t, zz), 1e-11);
        EXPECT_NEAR(table(shifted, zz), job.profile.radius_mm(t, zz), table.error_bound_mm() + 1e-11);
    }
    EXPECT_EQ(table(33, -5), table(33, 0));
    EXPECT_EQ(table(33, 75), table(33, 50));
    EXPECT_NEAR(table(-0.0, 0), 44.9, 1e-9);
}

TEST(CamTable, FunctionOfTheAngleAlone) {
    // An eccentric: the tool radius of a crank pin of throw 2 mm and radius 20 mm turned on
    // the main axis, r = e cos θ + sqrt(R² − e² sin² θ).
    const CamFunction f = [](double theta_deg, double) {
        const double t = theta_deg * pi / 180;
        return 2 * std::cos(t) + std::sqrt(400 - 4 * std::sin(t) * std::sin(t));
    };
    CamTableOptions options;
    options.z_from_mm = 7;
    options.z_to_mm = 7;
    const CamTable table = CamTable::build(f, options);
    EXPECT_EQ(table.z_cells(), 1u);
    EXPECT_TRUE(table.meets_tolerance());
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> theta(0, 360), z(-100, 100);
    for (int i = 0; i < 100000; ++i) {
        const double t = theta(rng);
        ASSERT_LE(std::abs(table(t, z(rng)) - f(t, 7)), table.error_bound_mm());
    }
}

TEST(CamTable, StopsAtMaxCellsAndSaysSo) {
    // A kink off the nodes never meets a tight tolerance; the cap holds and the table says so.
    const CamFunction f = [](double theta_deg, double) {
        return 10 + std::abs(std::sin((theta_deg - 1.234) * pi / 180));
    };
    CamTableOptions options;
    options.tolerance_mm = 1e-9;
    options.max_cells = 4096;
    const CamTable table = CamTable::build(f, options);
    EXPECT_LE(table.theta_cells() * table.z_cells(), 4096u);
    EXPECT_FALSE(table.meets_tolerance());
    EXPECT_GT(table.error_bound_mm(), 1e-9);
}

TEST(CamTable, RejectsBadOptions) {
    const CamFunction f = [](double, double) { return 1.0; };
    CamTableOptions options;
    options.z_from_mm = 5;
    options.z_to_mm = 1;
    EXPECT_THROW((void)CamTable::build(f, options), std::invalid_argument);
    options.z_to_mm = 6;
    options.tolerance_mm = 0;
    EXPECT_THROW((void)CamTable::build(f, options), std::invalid_argument);
    const CamFunction bad = [](double, double) { return std::nan(""); };
    EXPECT_THROW((void)CamTable::build(bad, CamTableOptions{}), std::domain_error);
}

TEST(CamEncoder, NextFollowsTheCountsOfEachTurn) {
    const PistonJob job = example("piston.toml");
    const CamTable table = build_cam_table(job);
    for (std::int64_t counts : {360, 1000, 4096, 7}) {
        EncoderCam encoder(table, counts);
        for (std::int64_t k = 0; k < 3 * counts; ++k) {
            const double z = 0.1 * static_cast<double>(k) / static_cast<double>(counts);
            const double theta = 360.0 * static_cast<double>(k % counts) / static_cast<double>(counts);
            ASSERT_EQ(encoder.count_in_turn(), k % counts);
            ASSERT_NEAR(encoder.next(z), table(theta, z), 1e-12) << counts << " " << k;
        }
    }
}

TEST(CamEncoder, AnyCountWithAnOffset) {
    const PistonJob job = example("piston.toml");
    const CamTable table = build_cam_table(job);
    EncoderCam encoder(table, 360, 90.0);  // count 0 on the minor axis
    EXPECT_NEAR(encoder.at_count(0, 0), table(90, 0), 1e-12);
    EXPECT_NEAR(encoder.at_count(-90, 0), table(0, 0), 1e-12);
    EXPECT_NEAR(encoder.at_count(360 * 1000 + 45, 20), table(135, 20), 1e-12);
    EXPECT_NEAR(encoder.at_count(45, 20), job.profile.radius_mm(135, 20), table.error_bound_mm());
    encoder.seek(-1);
    EXPECT_EQ(encoder.count_in_turn(), 359);
    EXPECT_NEAR(encoder.next(10), table(89, 10), 1e-12);
    EXPECT_EQ(encoder.count_in_turn(), 0);
    EXPECT_THROW(EncoderCam(table, 0), std::invalid_argument);
}

TEST(CamPistonOptions, NodesFallOnTheStations) {
    const std::vector<double> even{0, 10, 20, 30, 40, 50};
    EXPECT_EQ(aligned_z_cells(even), 5u);
    const std::vector<double> uneven{0, 5, 12, 30, 50};
    EXPECT_EQ(aligned_z_cells(uneven), 50u);
    const std::vector<double> decimals{0.1, 0.35, 0.6};
    EXPECT_EQ(aligned_z_cells(decimals), 2u);
    const std::vector<double> none{0, 1, 1 + std::sqrt(2.0)};
    EXPECT_EQ(aligned_z_cells(none, 100), 0u);
    const CamTableOptions options = piston_cam_options(none);
    EXPECT_EQ(options.min_z_cells, 3u);  // one cell per shortest interval
    EXPECT_EQ(options.z_from_mm, 0.0);
}

}  // namespace
}  // namespace nckit::cam
