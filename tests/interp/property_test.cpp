// Invariants over thousands of random paths (fixed seed): the move chain is continuous, arcs end
// on their circle, and absolute, incremental and mixed writings of one path end at the same points.
#include <array>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit::test {
namespace {

using Microns = std::array<long long, 3>;  // X Y Z in µm, so every coordinate prints exactly

constexpr long long reach_um = 300'000;  // every end point stays within ±300 mm
constexpr std::array<char, 3> axis_names = {'X', 'Y', 'Z'};
constexpr std::array<char, 3> offset_names = {'I', 'J', 'K'};

std::string mm(long long um) {
    std::string digits = std::to_string(std::llabs(um) % 1000);
    return (um < 0 ? "-" : "") + std::to_string(std::llabs(um) / 1000) + "." + std::string(3 - digits.size(), '0') +
           digits;
}

bool within_reach(const Microns& p) {
    for (long long v : p) {
        if (std::llabs(v) > reach_um) return false;
    }
    return true;
}

//! One random path written three ways: absolute, incremental, and switching at random.
struct Programs {
    std::string absolute;
    std::string incremental;
    std::string mixed;
    std::vector<Microns> ends;  //!< the end point of each move, in order
};

class PathWriter {
public:
    explicit PathWriter(std::uint64_t seed) : random_(seed) {}

    Programs make(int moves) {
        Programs out;
        // First plane index of each plane: G17 X,Y; G18 Z,X; G19 Y,Z (counter-clockwise order).
        const int plane = pick(0, 2);
        first_ = std::array<int, 3>{0, 2, 1}[plane];
        second_ = std::array<int, 3>{1, 0, 2}[plane];
        std::string head = std::string(plane == 0 ? "G17" : plane == 1 ? "G18" : "G19") + " G21 F1000\n";
        out.absolute = head + "G90\n";
        out.incremental = head + "G91\n";
        out.mixed = head;
        bool mixed_incremental = false;
        position_ = Microns{};
        for (int i = 0; i < moves; ++i) {
            Block b = next_block();
            out.absolute += b.code + words(b, false) + "\n";
            out.incremental += b.code + words(b, true) + "\n";
            bool incremental = pick(0, 1) == 1;
            if (incremental != mixed_incremental) out.mixed += incremental ? "G91 " : "G90 ";
            mixed_incremental = incremental;
            out.mixed += b.code + words(b, incremental) + "\n";
            position_ = b.end;
            out.ends.push_back(b.end);
        }
        return out;
    }

private:
    struct Block {
        std::string code;  // "G0", "G2", ...
        Microns end{};
        std::array<bool, 3> named{};  // which axis words are written
        std::string extra;            // " I.. J.." or " R.."
    };

    int pick(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random_); }
    long long pick_um(long long low, long long high) {
        return std::uniform_int_distribution<long long>(low, high)(random_);
    }

    std::string words(const Block& b, bool incremental) const {
        std::string out;
        for (int a = 0; a < 3; ++a) {
            if (!b.named[a]) continue;
            out += std::string(" ") + axis_names[a] + mm(incremental ? b.end[a] - position_[a] : b.end[a]);
        }
        return out + b.extra;
    }

    Block next_block() {
        for (;;) {
            int kind = pick(0, 5);
            Block b = kind <= 1 ? straight(kind) : kind <= 3 ? centre_arc(kind) : radius_arc(kind);
            if (within_reach(b.end)) return b;
        }
    }

    Block straight(int kind) {
        Block b;
        b.code = kind == 0 ? "G0" : "G1";
        b.end = position_;
        const int always = pick(0, 2);  // a block without axis words would not move
        for (int a = 0; a < 3; ++a) {
            if (a != always && pick(0, 3) == 0) continue;  // leave this axis where it is, unwritten
            b.end[a] = pick_um(-reach_um, reach_um);
            b.named[a] = true;
        }
        return b;
    }

    //! A quarter, half, three-quarter or whole turn around a centre on the µm grid, so the end
    //! lies exactly on the circle; sometimes a helix.
    Block centre_arc(int kind) {
        Block b;
        b.code = kind == 2 ? "G2" : "G3";
        long long o1 = 0;
        long long o2 = 0;
        while (std::llabs(o1) + std::llabs(o2) < 1000) {
            o1 = pick_um(-50'000, 50'000);
            o2 = pick_um(-50'000, 50'000);
        }
        // Start relative to the centre is (-o1, -o2); turn it by k quarter turns.
        long long s1 = -o1;
        long long s2 = -o2;
        for (int k = pick(0, 3); k > 0; --k) {
            long long t = s1;
            s1 = -s2;
            s2 = t;
        }
        b.end = position_;
        b.end[first_] = position_[first_] + o1 + s1;
        b.end[second_] = position_[second_] + o2 + s2;
        b.named[first_] = b.named[second_] = true;
        int normal = 3 - first_ - second_;
        if (pick(0, 2) == 0) {
            b.end[normal] += pick_um(-20'000, 20'000);
            b.named[normal] = true;
        }
        b.extra = std::string(" ") + offset_names[first_] + mm(o1) + " " + offset_names[second_] + mm(o2);
        return b;
    }

    //! An R arc at least 1 µm longer than half its chord, the short or (R < 0) the long way.
    Block radius_arc(int kind) {
        Block b;
        b.code = kind == 4 ? "G2" : "G3";
        long long d1 = 0;
        long long d2 = 0;
        while (d1 == 0 && d2 == 0) {
            d1 = pick_um(-60'000, 60'000);
            d2 = pick_um(-60'000, 60'000);
        }
        auto half = static_cast<long long>(std::ceil(std::hypot(static_cast<double>(d1), static_cast<double>(d2)) / 2));
        long long r = half + 1 + pick_um(0, 30'000);
        b.end = position_;
        b.end[first_] += d1;
        b.end[second_] += d2;
        b.named[first_] = b.named[second_] = true;
        b.extra = " R" + mm(pick(0, 1) == 0 ? r : -r);
        return b;
    }

    std::mt19937_64 random_;
    Microns position_{};
    int first_ = 0;
    int second_ = 1;
};

const AxisVector& end_of(const Move& move) {
    if (const auto* line = std::get_if<Line>(&move.what)) return line->to;
    return std::get<Arc>(move.what).to;
}

const AxisVector& start_of(const Move& move) {
    if (const auto* line = std::get_if<Line>(&move.what)) return line->from;
    return std::get<Arc>(move.what).from;
}

TEST(InterpreterProperties, RandomPathsAreContinuousAndAgreeInEveryDistanceMode) {
    constexpr int programs = 2000;
    constexpr int moves_per_program = 25;
    constexpr double same_mm = 1e-9;
    PathWriter writer(0x5eed);
    int arcs = 0;
    for (int p = 0; p < programs; ++p) {
        Programs path = writer.make(moves_per_program);
        const std::vector<Move> absolute = moves_of(path.absolute);
        const std::vector<Move> incremental = moves_of(path.incremental);
        const std::vector<Move> mixed = moves_of(path.mixed);
        ASSERT_EQ(absolute.size(), path.ends.size()) << path.absolute;
        ASSERT_EQ(incremental.size(), path.ends.size()) << path.incremental;
        ASSERT_EQ(mixed.size(), path.ends.size()) << path.mixed;
        AxisVector previous{};
        for (std::size_t i = 0; i < absolute.size(); ++i) {
            const Move& a = absolute[i];
            SCOPED_TRACE("program " + std::to_string(p) + ", move " + std::to_string(i) + "\n" + path.absolute);
            EXPECT_EQ(start_of(a), previous) << "chain broken";
            EXPECT_EQ(start_of(incremental[i]), i == 0 ? AxisVector{} : end_of(incremental[i - 1]));
            previous = end_of(a);
            for (int axis = 0; axis < 3; ++axis) {
                const double expected = static_cast<double>(path.ends[i][axis]) / 1000.0;
                ASSERT_NEAR(end_of(a)[axis], expected, same_mm);
                ASSERT_NEAR(end_of(incremental[i])[axis], expected, same_mm);
                ASSERT_NEAR(end_of(mixed[i])[axis], expected, same_mm);
            }
            if (const auto* arc = std::get_if<Arc>(&a.what)) {
                ++arcs;
                EXPECT_NEAR(arc_start_radius(*arc), arc_end_radius(*arc), 1e-6);
                const Arc& other = std::get<Arc>(incremental[i].what);
                EXPECT_NEAR(arc_start_radius(other), arc_end_radius(other), 1e-6);
                for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(arc->center[axis], other.center[axis], 1e-6);
            }
        }
    }
    EXPECT_GT(arcs, programs * moves_per_program / 3) << "the generator must make plenty of arcs";
}

}  // namespace
}  // namespace nckit::test
