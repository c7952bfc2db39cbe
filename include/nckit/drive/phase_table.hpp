#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "nckit/core/machine.hpp"

namespace nckit::drive {

//! The config's PhaseTableKind is the drive option; core owns it so the machine config can
//! name it without including the drive stage.
using nckit::PhaseTableKind;

enum class Direction { forward, reverse };

//! How winding patterns become the port byte. Winding A is the highest of the table's
//! winding bits (3-phase: A bit 2, B bit 1, C bit 0; 2-phase: A bit 3 .. D bit 0).
struct PortEncoding {
    bool active_low = false;  //!< invert the winding bits (drivers that sink current)
    //! Bits always written high (e.g. an enable line); keep them clear of the winding bits.
    std::uint8_t set_bits = 0;
};

//! The milling retrofit's port: active-low windings with bit 3 held high, giving the codes
//! 0BH, 09H, 0DH, 0CH, 0EH, 0AH for the six beats A, AB, B, BC, C, CA (docs/drives.md).
inline constexpr PortEncoding seed_port_encoding{true, 0x08};

//! The encoding an axis's config asks for (`port_active_low`, `port_set_bits`).
[[nodiscard]] inline PortEncoding port_encoding(const AxisConfig& axis) {
    return {axis.port_active_low, axis.port_set_bits};
}

//! The config spelling ("3phase-6beat", ...) of a table; see core's phase_table_names.
[[nodiscard]] std::string_view name(PhaseTableKind kind);
//! The table a config string names, or nullopt for an unknown name.
[[nodiscard]] std::optional<PhaseTableKind> parse_phase_table(std::string_view text);

//! Energised windings of each beat in order (winding A the highest bit); empty for `none`.
[[nodiscard]] std::span<const std::uint8_t> phase_patterns(PhaseTableKind kind);
//! Number of winding bits the table drives: 3 or 4 (0 for `none`).
[[nodiscard]] int winding_count(PhaseTableKind kind);

//! The winding pattern after the motor has made `step_count` steps from beat 0 (negative
//! counts run the table backwards). Taken mod the table length, so it never drifts.
[[nodiscard]] std::uint8_t winding_pattern(PhaseTableKind kind, std::int64_t step_count);
//! The byte written to the port for that pattern under `encoding`.
[[nodiscard]] std::uint8_t port_byte(PhaseTableKind kind, std::int64_t step_count, PortEncoding encoding = {});

//! A motor's phase output driven by single steps: holds the absolute step count, so the
//! output after any sequence of steps depends only on the net count.
class PhaseSequencer {
public:
    explicit PhaseSequencer(PhaseTableKind kind, PortEncoding encoding = {}, std::int64_t step_count = 0)
        : kind_(kind), encoding_(encoding), step_count_(step_count) {}

    //! One step in `direction`; returns the byte to write to the port.
    std::uint8_t step(Direction direction) {
        step_count_ += direction == Direction::forward ? 1 : -1;
        return output();
    }
    [[nodiscard]] std::uint8_t output() const { return port_byte(kind_, step_count_, encoding_); }
    [[nodiscard]] std::int64_t step_count() const { return step_count_; }
    [[nodiscard]] PhaseTableKind kind() const { return kind_; }

private:
    PhaseTableKind kind_;
    PortEncoding encoding_;
    std::int64_t step_count_;  //!< steps from beat 0, forward positive
};

}  // namespace nckit::drive
