#pragma once
#include <cstdint>
#include <memory>
#include <string>

namespace nckit {

//! Where a piece of user input came from. The file name is shared, not copied, because every
//! block and every move of a long program carries one.
struct SourceLocation {
    std::shared_ptr<const std::string> file;  //!< path as the user gave it; null for built-ins
    std::uint32_t line = 0;                   //!< 1-based; 0 when the input has no lines
    std::uint32_t column = 0;                 //!< 1-based byte column; 0 for "whole line"

    [[nodiscard]] const std::string& file_name() const;
};

[[nodiscard]] SourceLocation make_location(std::shared_ptr<const std::string> file, std::uint32_t line,
                                           std::uint32_t column);

}  // namespace nckit
