#pragma once
// Private to the process stage: how its JSON reports write a number that may not exist.
#include <cmath>

#include <nlohmann/json.hpp>

namespace nckit::process_detail {

//! The number, or null where it does not exist (an infinite limit, a NaN): JSON has no inf/nan.
inline nlohmann::ordered_json finite_or_null(double value) {
    return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

}  // namespace nckit::process_detail
