#include "nckit/cam/encoder_cam.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nckit::cam {

EncoderCam::EncoderCam(const CamTable& table, std::int64_t counts_per_rev, double theta_offset_deg)
    : table_(&table), counts_per_rev_(counts_per_rev) {
    if (counts_per_rev <= 0) throw std::invalid_argument("EncoderCam needs counts_per_rev > 0");
    if (!std::isfinite(theta_offset_deg)) {
        throw std::invalid_argument("EncoderCam needs a finite offset");
    }
    slots_.resize(static_cast<std::size_t>(counts_per_rev));
    const double cells = static_cast<double>(table.theta_cells());
    const double offset_turns = theta_offset_deg / 360.0 - std::floor(theta_offset_deg / 360.0);
    for (std::size_t k = 0; k < slots_.size(); ++k) {
        // Position in the turn from the integer count: no accumulated increments.
        double turns = static_cast<double>(k) / static_cast<double>(counts_per_rev) + offset_turns;
        turns -= std::floor(turns);
        const double u = turns * cells;
        const double cell = std::min(std::floor(u), cells - 1);
        slots_[k] = Slot{static_cast<std::size_t>(cell), u - cell};
    }
}

void EncoderCam::seek(std::int64_t count) {
    std::int64_t k = count % counts_per_rev_;
    if (k < 0) k += counts_per_rev_;
    index_ = static_cast<std::size_t>(k);
}

}  // namespace nckit::cam
