#pragma once
// The machine file's [probe] and [inputs] tables: what a simulated G31 skip signal and the
// Custom Macro B inputs #1000-#1199 see (machine_probe_inputs.cpp).
#include "nckit/core/machine.hpp"
#include "nckit/core/toml_table_reader.hpp"

namespace nckit::core_detail {

//! Reads `[probe] surfaces = [{ axis = "Z", at = -20.0 }, ...]` and `[inputs] 1000 = 1`.
void read_probe_and_inputs(TableReader& root, MachineConfig& config, ConfigSink& sink);

}  // namespace nckit::core_detail
