#include "nckit/drive/phase_table.hpp"

#include <algorithm>
#include <array>

namespace nckit::drive {

namespace {

// Winding A is the highest bit, as on the seed's port (A bit 2, B bit 1, C bit 0).
constexpr std::uint8_t A3 = 0b100, B3 = 0b010, C3 = 0b001;
constexpr std::array<std::uint8_t, 6> three_phase_six_beat{A3, A3 | B3, B3, B3 | C3, C3, C3 | A3};
constexpr std::array<std::uint8_t, 3> three_phase_three_beat{A3, B3, C3};
constexpr std::uint8_t A4 = 0b1000, B4 = 0b0100, C4 = 0b0010, D4 = 0b0001;
constexpr std::array<std::uint8_t, 4> two_phase_full{A4 | B4, B4 | C4, C4 | D4, D4 | A4};
constexpr std::array<std::uint8_t, 8> two_phase_half{A4, A4 | B4, B4, B4 | C4, C4, C4 | D4, D4, D4 | A4};

}  // namespace

std::string_view name(PhaseTableKind kind) {
    return phase_table_names[static_cast<std::size_t>(kind)];
}

std::optional<PhaseTableKind> parse_phase_table(std::string_view text) {
    const auto* hit = std::find(phase_table_names.begin(), phase_table_names.end(), text);
    if (hit == phase_table_names.end()) return std::nullopt;
    return static_cast<PhaseTableKind>(hit - phase_table_names.begin());
}

std::span<const std::uint8_t> phase_patterns(PhaseTableKind kind) {
    switch (kind) {
        case PhaseTableKind::none:
            return {};
        case PhaseTableKind::three_phase_six_beat:
            return three_phase_six_beat;
        case PhaseTableKind::three_phase_three_beat:
            return three_phase_three_beat;
        case PhaseTableKind::two_phase_full_step:
            return two_phase_full;
        case PhaseTableKind::two_phase_half_step:
            return two_phase_half;
    }
    return {};
}

int winding_count(PhaseTableKind kind) {
    switch (kind) {
        case PhaseTableKind::none:
            return 0;
        case PhaseTableKind::three_phase_six_beat:
        case PhaseTableKind::three_phase_three_beat:
            return 3;
        case PhaseTableKind::two_phase_full_step:
        case PhaseTableKind::two_phase_half_step:
            return 4;
    }
    return 0;
}

std::uint8_t winding_pattern(PhaseTableKind kind, std::int64_t step_count) {
    const std::span<const std::uint8_t> table = phase_patterns(kind);
    if (table.empty()) return 0;
    const auto length = static_cast<std::int64_t>(table.size());
    // Floor modulo: step -1 is the last beat, so reversing through zero keeps the sequence.
    const std::int64_t beat = ((step_count % length) + length) % length;
    return table[static_cast<std::size_t>(beat)];
}

std::uint8_t port_byte(PhaseTableKind kind, std::int64_t step_count, PortEncoding encoding) {
    const auto mask = static_cast<std::uint8_t>((1U << winding_count(kind)) - 1U);
    std::uint8_t bits = winding_pattern(kind, step_count);
    if (encoding.active_low) bits = static_cast<std::uint8_t>(~bits & mask);
    return static_cast<std::uint8_t>(bits | encoding.set_bits);
}

}  // namespace nckit::drive
