#pragma once
// Keeps #500-#999 between runs, as a control keeps them through power-off: a small text file
// (`#500 = 1.25` per line, vacant variables left out), replaced atomically so that a crash in
// the middle of a write leaves the old file or the new one, never a torn one.
#include <filesystem>

#include "nckit/core/result.hpp"
#include "variables.hpp"

namespace nckit::interp {

//! The retained values in `path`; all vacant when the file does not exist yet.
[[nodiscard]] Result<RetainedValues> load_retained(const std::filesystem::path& path);

//! Writes `values` to `path` through a temporary file, fsync and rename.
[[nodiscard]] std::optional<Diagnostic> save_retained(const std::filesystem::path& path, const RetainedValues& values);

}  // namespace nckit::interp
