#pragma once
#include <cstdint>
#include <vector>

#include "nckit/cam/cam_table.hpp"

namespace nckit::cam {

//! A CamTable read at consecutive spindle encoder counts, the way a servo tick uses it. The
//! table cell and the fraction through it of every count of one turn are computed once (from
//! the integer count, so a long run never drifts), leaving each tick the Z lookup and the patch.
class EncoderCam {
public:
    //! `counts_per_rev` > 0; count 0 lies `theta_offset_deg` from the profile's major axis.
    //! Keeps a reference to `table`, which must outlive this object.
    EncoderCam(const CamTable& table, std::int64_t counts_per_rev, double theta_offset_deg = 0.0);

    //! mm at encoder count `count` (any integer, taken modulo the turn) and `z_mm`.
    [[nodiscard]] double at_count(std::int64_t count, double z_mm) const {
        std::int64_t k = count % counts_per_rev_;
        k += k < 0 ? counts_per_rev_ : 0;
        const auto& slot = slots_[static_cast<std::size_t>(k)];
        return table_->at_cell(slot.cell, slot.t, z_mm);
    }

    //! The position at the current count and `z_mm`; then moves on one count. Starts at
    //! count 0.
    [[nodiscard]] double next(double z_mm) {
        const Slot& slot = slots_[index_];
        ++index_;
        index_ = index_ == slots_.size() ? 0 : index_;  // a compare, predicted but once a turn
        return table_->at_cell(slot.cell, slot.t, z_mm);
    }

    //! The count within the turn that next() evaluates.
    [[nodiscard]] std::int64_t count_in_turn() const { return static_cast<std::int64_t>(index_); }
    //! Makes next() evaluate `count` (any integer, taken modulo the turn).
    void seek(std::int64_t count);
    [[nodiscard]] std::int64_t counts_per_rev() const { return counts_per_rev_; }

private:
    struct Slot {
        std::size_t cell = 0;  //!< θ cell of the table
        double t = 0;          //!< fraction through it, [0, 1)
    };
    const CamTable* table_;
    std::int64_t counts_per_rev_;
    std::vector<Slot> slots_;  //!< one per count of a turn
    std::size_t index_ = 0;    //!< count within the turn next() evaluates
};

}  // namespace nckit::cam
