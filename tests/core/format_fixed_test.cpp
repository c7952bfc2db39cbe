// The fast 4-decimal formatter prints exactly what fmt's "{:.4f}" prints, sign of zero included.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <fmt/format.h>

#include "nckit/core/format_fixed.hpp"

namespace nckit {
namespace {

std::string fast(double value) {
    std::string out;
    append_fixed4(out, value);
    return out;
}

TEST(FormatFixed, NegativeValuesRoundingToZeroKeepTheirSignAsFmtDoes) {
    for (double v : {-0.0, -0.00004, -0.000049999, -1e-12}) EXPECT_EQ(fast(v), fmt::format("{:.4f}", v)) << v;
    EXPECT_EQ(fast(-0.00004), "-0.0000");
    EXPECT_EQ(fast(0.00004), "0.0000");
    EXPECT_EQ(fast(-0.00005000001), "-0.0001");
}

TEST(FormatFixed, MatchesFmtOnRandomValuesNearTiesAndAcrossMagnitudes) {
    std::mt19937_64 random(20261125);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-8, 9);
    std::uniform_int_distribution<long long> units(-99999999999LL, 99999999999LL);
    std::uniform_int_distribution<int> ulps(-4, 4);
    for (int i = 0; i < 200000; ++i) {
        double v = 0;
        switch (i % 3) {
            case 0:
                v = unit(random) * std::pow(10.0, exponent(random));
                break;
            case 1: {
                // A tie in decimal (k + 0.5) / 1e4, nudged by a few ulps either way.
                double tie = (static_cast<double>(units(random) % 100000000) + 0.5) / 1e4;
                v = tie;
                for (int k = ulps(random); k != 0; k += k > 0 ? -1 : 1) v = std::nextafter(v, k > 0 ? 1e300 : -1e300);
                break;
            }
            default:
                v = static_cast<double>(units(random) % 1000) * 1e-8;
                break;  // around zero, both signs
        }
        ASSERT_EQ(fast(v), fmt::format("{:.4f}", v)) << fmt::format("{:.17g}", v);
    }
}

}  // namespace
}  // namespace nckit
