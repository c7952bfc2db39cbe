#pragma once
// The machine file's [[axis]] tables: limits, travel, backlash, the step port and the servo model
// of each axis, and the checks across axes (machine_axes.cpp).
#include "nckit/core/machine.hpp"
#include "nckit/core/toml_table_reader.hpp"

namespace nckit::core_detail {

//! Reads every `[[axis]]`; at least one is required and no axis may be named twice. Only axes
//! whose table had no error reach `config.axes`.
void read_axes(TableReader& root, MachineConfig& config, ConfigSink& sink);

}  // namespace nckit::core_detail
