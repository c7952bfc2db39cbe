#pragma once
// The edge between LinuxCNC and nckit: no C++ exception may unwind into LinuxCNC's task.
#include <exception>
#include <string>

#include <fmt/format.h>

#include "linuxcnc_headers.hpp"

namespace nckit::lcnc {

//! Runs `body`; an exception (out of memory, a file system error) becomes an interpreter error
//! with its text in `error` instead of unwinding into LinuxCNC.
template <typename Body>
int guarded(std::string& error, Body&& body) {
    try {
        return body();
    } catch (const std::exception& e) {
        error = fmt::format("nckit interpreter: {}", e.what());
    } catch (...) {
        error = "nckit interpreter: unexpected failure";
    }
    return INTERP_ERROR;
}

}  // namespace nckit::lcnc
