#include <cmath>
#include <stdexcept>

#include "nckit/process/fts/fts_controller.hpp"

namespace nckit {

double Dac::step_mm() const {
    return std::ldexp(stroke_mm, -bits);
}

Dac::Output Dac::convert(double wanted_mm) const {
    if (std::isnan(wanted_mm)) throw std::invalid_argument("DAC input is not a number");
    const std::int64_t mid = std::int64_t{1} << (bits - 1);
    const std::int64_t top = (std::int64_t{1} << bits) - 1;
    const double step = step_mm();
    // Clamp in the double domain first: llround of a value beyond int64 is undefined.
    const double codes_from_mid = wanted_mm / step;
    Output out;
    if (codes_from_mid < static_cast<double>(-mid) - 0.5) {
        out.code = 0;
        out.clamped = true;
    } else if (codes_from_mid >= static_cast<double>(top - mid) + 0.5) {
        out.code = top;
        out.clamped = true;
    } else {
        out.code = std::llround(codes_from_mid) + mid;
    }
    // (code - mid) * step is exact: a small integer times a power-of-two fraction of the stroke.
    out.command_mm = static_cast<double>(out.code - mid) * step;
    return out;
}

}  // namespace nckit
