#pragma once
// The data a report page carries: a JSON header and binary arrays, packed into one buffer,
// gzip-compressed and base64-encoded so it sits inline in the HTML and the browser unpacks it
// with its own DecompressionStream (no library, no network).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace nckit {

//! Layout (all little-endian): u32 header length, the header's JSON text, zero padding to a
//! multiple of 8, then the blobs, each starting at a multiple of 8. header["blobs"][name] is
//! {"offset", "length" (bytes), "type", "count", "scale"?}. Types:
//! - "u8", "f32", "f64": plain arrays;
//! - "delta": signed integers as zigzag LEB128 varints of successive differences; value k is
//!   scale · (sum of the first k+1 differences);
//! - "text": UTF-8.
class Payload {
public:
    nlohmann::json header = nlohmann::json::object();

    void add_u8(const std::string& name, const std::vector<std::uint8_t>& values);
    void add_f32(const std::string& name, const std::vector<double>& values);
    void add_f64(const std::string& name, const std::vector<double>& values);
    //! Values are rounded to multiples of scale first.
    void add_delta(const std::string& name, const std::vector<double>& values, double scale);
    void add_delta_int(const std::string& name, const std::vector<std::int64_t>& values);
    void add_text(const std::string& name, std::string_view text);

    //! The packed buffer (uncompressed).
    [[nodiscard]] std::string pack() const;

private:
    void add(const std::string& name, const char* type, std::size_t count, std::string bytes, double scale = 0);
    std::string blobs_;
};

//! gzip (RFC 1952) of bytes, zlib level 6.
[[nodiscard]] std::string gzip(std::string_view bytes);
[[nodiscard]] std::string base64(std::string_view bytes);

}  // namespace nckit
