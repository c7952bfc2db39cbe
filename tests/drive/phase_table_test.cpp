#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/drive/phase_table.hpp"

namespace nckit::drive {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes first_bytes(PhaseTableKind kind, int count, PortEncoding encoding = {}) {
    Bytes out;
    for (int i = 0; i < count; ++i) out.push_back(port_byte(kind, i, encoding));
    return out;
}

TEST(PhaseTable, SeedSixBeatPortCodes) {
    // docs/drives.md: A, AB, B, BC, C, CA -> 0BH, 09H, 0DH, 0CH, 0EH, 0AH.
    EXPECT_EQ(first_bytes(PhaseTableKind::three_phase_six_beat, 7, seed_port_encoding),
              (Bytes{0x0B, 0x09, 0x0D, 0x0C, 0x0E, 0x0A, 0x0B}));
    // The winding patterns 100, 110, 010, 011, 001, 101 behind them.
    EXPECT_EQ(first_bytes(PhaseTableKind::three_phase_six_beat, 6), (Bytes{0b100, 0b110, 0b010, 0b011, 0b001, 0b101}));
}

TEST(PhaseTable, OtherTables) {
    EXPECT_EQ(first_bytes(PhaseTableKind::three_phase_three_beat, 4), (Bytes{0b100, 0b010, 0b001, 0b100}));
    EXPECT_EQ(first_bytes(PhaseTableKind::two_phase_full_step, 5), (Bytes{0b1100, 0b0110, 0b0011, 0b1001, 0b1100}));
    EXPECT_EQ(first_bytes(PhaseTableKind::two_phase_half_step, 9),
              (Bytes{0b1000, 0b1100, 0b0100, 0b0110, 0b0010, 0b0011, 0b0001, 0b1001, 0b1000}));
    EXPECT_EQ(first_bytes(PhaseTableKind::none, 3), (Bytes{0, 0, 0}));
    EXPECT_EQ(first_bytes(PhaseTableKind::two_phase_full_step, 2, {true, 0x80}), (Bytes{0x83, 0x89}));
}

TEST(PhaseTable, ReverseRunsTheTableBackwards) {
    PhaseSequencer motor(PhaseTableKind::three_phase_six_beat, seed_port_encoding);
    EXPECT_EQ(motor.output(), 0x0B);  // A
    Bytes back;
    for (int i = 0; i < 7; ++i) back.push_back(motor.step(Direction::reverse));
    // A -> CA -> C -> BC -> B -> AB -> A -> CA: through count 0 into negative counts.
    EXPECT_EQ(back, (Bytes{0x0A, 0x0E, 0x0C, 0x0D, 0x09, 0x0B, 0x0A}));
    EXPECT_EQ(motor.step_count(), -7);
}

TEST(PhaseTable, OutputDependsOnlyOnTheNetCount) {
    std::mt19937_64 random(7);
    std::bernoulli_distribution forward(0.5);
    for (PhaseTableKind kind : {PhaseTableKind::three_phase_six_beat, PhaseTableKind::three_phase_three_beat,
                                PhaseTableKind::two_phase_full_step, PhaseTableKind::two_phase_half_step}) {
        const PortEncoding encoding{true, 0x80};  // enable bit clear of every winding bit
        PhaseSequencer motor(kind, encoding, 1'000'000'000'000LL);
        const auto length = static_cast<std::int64_t>(phase_patterns(kind).size());
        std::uint8_t previous = motor.output();
        for (int i = 0; i < 100'000; ++i) {
            const Direction d = forward(random) ? Direction::forward : Direction::reverse;
            const std::uint8_t now = motor.step(d);
            ASSERT_EQ(now, port_byte(kind, motor.step_count(), encoding));
            ASSERT_EQ(now, port_byte(kind, motor.step_count() - 7 * length, encoding));
            ASSERT_NE(now, previous);  // every step changes the windings
            previous = now;
        }
    }
}

TEST(PhaseTable, AdjacentBeatsDifferInOneWinding) {
    // Half-step tables switch one winding per beat; full-step tables swap one for another.
    for (PhaseTableKind kind : {PhaseTableKind::three_phase_six_beat, PhaseTableKind::two_phase_half_step}) {
        const auto table = phase_patterns(kind);
        for (std::size_t i = 0; i < table.size(); ++i) {
            const unsigned changed = table[i] ^ table[(i + 1) % table.size()];
            EXPECT_EQ(__builtin_popcount(changed), 1) << name(kind) << " beat " << i;
        }
    }
}

TEST(PhaseTable, NamesRoundTrip) {
    for (PhaseTableKind kind :
         {PhaseTableKind::none, PhaseTableKind::three_phase_six_beat, PhaseTableKind::three_phase_three_beat,
          PhaseTableKind::two_phase_full_step, PhaseTableKind::two_phase_half_step}) {
        EXPECT_EQ(parse_phase_table(name(kind)), kind);
    }
    EXPECT_EQ(name(PhaseTableKind::three_phase_six_beat), "3phase-6beat");
    EXPECT_EQ(parse_phase_table("3phase-6beat"), PhaseTableKind::three_phase_six_beat);
    EXPECT_EQ(parse_phase_table("2phase-half"), PhaseTableKind::two_phase_half_step);
    EXPECT_FALSE(parse_phase_table("3PHASE-6BEAT").has_value());
    EXPECT_FALSE(parse_phase_table("").has_value());
    EXPECT_EQ(winding_count(PhaseTableKind::three_phase_three_beat), 3);
    EXPECT_EQ(winding_count(PhaseTableKind::two_phase_full_step), 4);
}

}  // namespace
}  // namespace nckit::drive
