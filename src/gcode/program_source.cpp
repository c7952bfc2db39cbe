#include "nckit/gcode/program_source.hpp"

#include <cerrno>
#include <cstring>
#include <string_view>

#include <unistd.h>
#include <utility>

#include <fmt/format.h>

namespace nckit {

namespace {
constexpr std::size_t buffer_bytes = 1 << 20;
constexpr std::string_view utf8_bom = "\xEF\xBB\xBF";
}  // namespace

Result<ProgramSource> ProgramSource::open(const std::filesystem::path& path) {
    ProgramSource source;
    if (path == "-") {
        // Standard input, read as any pipe: streamed once, never searched backwards.
        source.name_ = std::make_shared<const std::string>("<stdin>");
        source.rereadable_ = false;
        int fd = ::dup(STDIN_FILENO);
        source.file_ = fd >= 0 ? ::fdopen(fd, "rb") : nullptr;
        if (source.file_ == nullptr) {
            if (fd >= 0) ::close(fd);
            return error_at(make_location(source.name_, 0, 0), "file",
                            fmt::format("cannot read standard input: {}", std::strerror(errno)));
        }
        source.text_.resize(buffer_bytes);
        return source;
    }
    source.name_ = std::make_shared<const std::string>(path.string());
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        return error_at(make_location(source.name_, 0, 0), "file", "is a directory, not a program");
    }
    source.file_ = std::fopen(path.c_str(), "rb");
    if (source.file_ == nullptr) {
        return error_at(make_location(source.name_, 0, 0), "file",
                        fmt::format("cannot open: {}", std::strerror(errno)));
    }
    source.rereadable_ = std::filesystem::is_regular_file(path, ec);
    source.text_.resize(buffer_bytes);
    return source;
}

ProgramSource ProgramSource::from_string(std::string text, std::string name) {
    ProgramSource source;
    source.name_ = std::make_shared<const std::string>(std::move(name));
    source.text_ = std::move(text);
    source.end_ = source.text_.size();
    source.eof_ = true;
    return source;
}

ProgramSource::ProgramSource(ProgramSource&& other) noexcept {
    *this = std::move(other);
}

ProgramSource& ProgramSource::operator=(ProgramSource&& other) noexcept {
    if (this != &other) {
        if (file_ != nullptr) std::fclose(file_);
        name_ = std::move(other.name_);
        file_ = std::exchange(other.file_, nullptr);
        text_ = std::move(other.text_);
        begin_ = other.begin_;
        end_ = other.end_;
        buffer_offset_ = other.buffer_offset_;
        line_number_ = other.line_number_;
        eof_ = other.eof_;
        rereadable_ = other.rereadable_;
        line_ = std::move(other.line_);
    }
    return *this;
}

ProgramSource::~ProgramSource() {
    if (file_ != nullptr) std::fclose(file_);
}

bool ProgramSource::refill() {
    if (file_ == nullptr || eof_) return false;
    buffer_offset_ += end_;
    std::size_t got = std::fread(text_.data(), 1, text_.size(), file_);
    begin_ = 0;
    end_ = got;
    if (got < text_.size()) eof_ = true;
    return got > 0;
}

Result<std::optional<ProgramSource::Line>> ProgramSource::next() {
    line_.clear();
    bool straddles = false;
    std::uint64_t line_offset = buffer_offset_ + begin_;
    for (;;) {
        const char* start = text_.data() + begin_;
        const auto* newline = static_cast<const char*>(std::memchr(start, '\n', end_ - begin_));
        std::size_t length = newline ? static_cast<std::size_t>(newline - start) : end_ - begin_;
        if (line_.size() + length > max_line_bytes) {
            return error_at(make_location(name_, line_number_ + 1, 1), "line-too-long",
                            fmt::format("block longer than {} bytes", max_line_bytes));
        }
        if (newline != nullptr || (eof_ && (begin_ < end_ || straddles))) {
            std::string_view text;
            if (straddles) {
                line_.append(start, length);
                text = line_;
            } else {
                text = std::string_view(start, length);
            }
            begin_ += length + (newline ? 1 : 0);
            if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
            // A UTF-8 byte-order mark (editors on Windows write one) is not part of the program.
            if (line_offset == 0 && text.starts_with(utf8_bom)) text.remove_prefix(utf8_bom.size());
            ++line_number_;
            return std::optional<Line>(Line{text, line_number_, line_offset});
        }
        // The line goes on past the buffer: keep what we have and read more.
        line_.append(start, length);
        straddles = !line_.empty();
        begin_ = end_;
        if (!refill()) {
            if (file_ != nullptr && std::ferror(file_) != 0) {
                return error_at(make_location(name_, line_number_ + 1, 1), "file", "read error");
            }
            if (!straddles) return std::optional<Line>{};
            eof_ = true;
            begin_ = end_ = 0;
        }
    }
}

void ProgramSource::append(std::string_view text) {
    if (file_ != nullptr) return;  // a file or pipe is read as it is
    if (end_ > 0 && text_[end_ - 1] != '\n') text_ += '\n';
    text_.append(text);
    if (!text.empty() && text.back() != '\n') text_ += '\n';
    end_ = text_.size();
}

void ProgramSource::seek(std::uint64_t offset, std::uint32_t line_number) {
    line_number_ = line_number > 0 ? line_number - 1 : 0;
    if (file_ == nullptr) {
        begin_ = static_cast<std::size_t>(offset);
        return;
    }
    // Inside the buffer, or at its end when nothing follows (a loop back to the last line of a
    // file must not cost a read of the file per pass).
    if (offset >= buffer_offset_ && (offset < buffer_offset_ + end_ || (eof_ && offset == buffer_offset_ + end_))) {
        begin_ = static_cast<std::size_t>(offset - buffer_offset_);
        return;
    }
    std::fseek(file_, static_cast<long>(offset), SEEK_SET);
    std::clearerr(file_);
    eof_ = false;
    buffer_offset_ = offset;
    end_ = 0;
    refill();
    buffer_offset_ = offset;
}

}  // namespace nckit

namespace nckit {

Result<ProgramSource> ProgramSource::reopen() const {
    if (file_ == nullptr) return from_string(text_, *name_);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(*name_, ec)) {
        return error_at(make_location(name_, 0, 0), "file",
                        "a program read from a pipe cannot be searched or called into");
    }
    return open(*name_);
}

}  // namespace nckit
