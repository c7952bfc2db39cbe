#pragma once
// The binary step record of `nckit steps` and `nckit crosshatch --steps`: 10 bytes,
// little-endian, no header: int64 time in ns, uint8 axis index, int8 direction (+1 or -1).
#include <cstdint>
#include <string>

#include "nckit/drive/step_generator.hpp"

namespace nckit::cli {

inline void append_step_record(std::string& out, const StepEvent& event) {
    const auto t = static_cast<std::uint64_t>(event.t_ns);
    char bytes[10];
    for (int i = 0; i < 8; ++i) bytes[i] = static_cast<char>((t >> (8 * i)) & 0xFF);
    bytes[8] = static_cast<char>(event.axis);
    bytes[9] = static_cast<char>(event.direction);
    out.append(bytes, sizeof bytes);
}

}  // namespace nckit::cli
