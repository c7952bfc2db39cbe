#pragma once
#include <string>
#include <vector>

#include "nckit/core/source_location.hpp"

namespace nckit {

enum class Severity { error, warning, note };

//! A problem in user input (program, machine config, job), tied to where it is.
struct Diagnostic {
    SourceLocation location;
    Severity severity = Severity::error;
    std::string code;     //!< stable kind name, e.g. "modal-conflict", "travel-limit"
    std::string message;  //!< one sentence, lower case, no trailing period
    int alarm = 0;        //!< Fanuc-style alarm number for macro alarms; 0 when none
};

[[nodiscard]] Diagnostic error_at(SourceLocation location, std::string code, std::string message);

//! `FILE:LINE:COL: error: message`, the form compilers use, so editors can jump to it.
[[nodiscard]] std::string format_diagnostic(const Diagnostic& diagnostic);

using Diagnostics = std::vector<Diagnostic>;

}  // namespace nckit
