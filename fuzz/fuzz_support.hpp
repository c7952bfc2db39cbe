#pragma once
// What the fuzz targets share: a finding is an abort with a message (libFuzzer saves the input).
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace nckit::fuzz {

[[noreturn]] inline void finding(const char* what) {
    std::fprintf(stderr, "nckit fuzz finding: %s\n", what);
    std::abort();
}

inline void require(bool holds, const char* what) {
    if (!holds) finding(what);
}

inline std::string_view text_of(const unsigned char* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

}  // namespace nckit::fuzz
