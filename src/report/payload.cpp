#include "nckit/report/payload.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <zlib.h>

namespace nckit {

namespace {

void pad8(std::string& s) {
    s.append((8 - s.size() % 8) % 8, '\0');
}

template <typename T>
void put(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));  // x86-64 and ARM are little-endian, as the layout is
    out.append(bytes, sizeof(T));
}

void put_varint(std::string& out, std::int64_t value) {
    auto zigzag = (static_cast<std::uint64_t>(value) << 1) ^ static_cast<std::uint64_t>(value >> 63);
    while (zigzag >= 0x80) {
        out.push_back(static_cast<char>((zigzag & 0x7f) | 0x80));
        zigzag >>= 7;
    }
    out.push_back(static_cast<char>(zigzag));
}

}  // namespace

void Payload::add(const std::string& name, const char* type, std::size_t count, std::string bytes, double scale) {
    pad8(blobs_);
    nlohmann::json entry{{"offset", blobs_.size()}, {"length", bytes.size()}, {"type", type}, {"count", count}};
    if (scale > 0) entry["scale"] = scale;
    header["blobs"][name] = std::move(entry);
    blobs_ += bytes;
}

void Payload::add_u8(const std::string& name, const std::vector<std::uint8_t>& values) {
    add(name, "u8", values.size(), std::string(values.begin(), values.end()));
}

void Payload::add_f32(const std::string& name, const std::vector<double>& values) {
    std::string bytes;
    bytes.reserve(values.size() * 4);
    for (double v : values) put(bytes, static_cast<float>(v));
    add(name, "f32", values.size(), std::move(bytes));
}

void Payload::add_f64(const std::string& name, const std::vector<double>& values) {
    std::string bytes;
    bytes.reserve(values.size() * 8);
    for (double v : values) put(bytes, v);
    add(name, "f64", values.size(), std::move(bytes));
}

void Payload::add_delta(const std::string& name, const std::vector<double>& values, double scale) {
    std::string bytes;
    bytes.reserve(values.size() * 2);
    std::int64_t last = 0;
    for (double v : values) {
        const auto k = static_cast<std::int64_t>(std::llround(v / scale));
        put_varint(bytes, k - last);
        last = k;
    }
    add(name, "delta", values.size(), std::move(bytes), scale);
}

void Payload::add_delta_int(const std::string& name, const std::vector<std::int64_t>& values) {
    std::string bytes;
    bytes.reserve(values.size());
    std::int64_t last = 0;
    for (std::int64_t k : values) {
        put_varint(bytes, k - last);
        last = k;
    }
    add(name, "delta", values.size(), std::move(bytes), 1.0);
}

void Payload::add_text(const std::string& name, std::string_view text) {
    add(name, "text", text.size(), std::string(text));
}

std::string Payload::pack() const {
    const std::string head = header.dump();
    std::string out;
    put(out, static_cast<std::uint32_t>(head.size()));
    out += head;
    pad8(out);
    out += blobs_;
    return out;
}

std::string gzip(std::string_view bytes) {
    z_stream z{};
    // windowBits 15 + 16: a gzip wrapper, which DecompressionStream("gzip") reads.
    if (deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
        throw std::runtime_error("zlib: deflateInit2 failed");
    }
    std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())), '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    z.avail_in = static_cast<uInt>(bytes.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    const int status = deflate(&z, Z_FINISH);
    const std::size_t produced = z.total_out;
    deflateEnd(&z);
    if (status != Z_STREAM_END) throw std::runtime_error("zlib: deflate did not finish");
    out.resize(produced);
    return out;
}

std::string base64(std::string_view bytes) {
    static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const auto n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
        out += {digits[(n >> 18) & 63], digits[(n >> 12) & 63], digits[(n >> 6) & 63], digits[n & 63]};
    }
    if (i + 1 == bytes.size()) {
        const auto n = static_cast<unsigned char>(bytes[i]) << 16;
        out += {digits[(n >> 18) & 63], digits[(n >> 12) & 63], '=', '='};
    } else if (i + 2 == bytes.size()) {
        const auto n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
        out += {digits[(n >> 18) & 63], digits[(n >> 12) & 63], digits[(n >> 6) & 63], '='};
    }
    return out;
}

}  // namespace nckit
