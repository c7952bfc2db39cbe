#include "partial_file.hpp"

#include <filesystem>
#include <utility>

#include <fmt/format.h>

namespace nckit::cli {

namespace {
std::string partial_name(const std::string& name) { return name + ".partial"; }

void report_cannot_write(const std::string& name) { fmt::print(stderr, "{}:0:0: error: cannot write\n", name); }
}  // namespace

std::optional<PartialFile> PartialFile::create(const std::string& name) {
    std::FILE* file = std::fopen(partial_name(name).c_str(), "wb");
    if (file == nullptr) {
        report_cannot_write(name);
        return std::nullopt;
    }
    return PartialFile(name, file);
}

PartialFile::PartialFile(PartialFile&& other) noexcept
    : name_(std::move(other.name_)), file_(std::exchange(other.file_, nullptr)) {}

PartialFile& PartialFile::operator=(PartialFile&& other) noexcept {
    if (this != &other) {
        discard();
        name_ = std::move(other.name_);
        file_ = std::exchange(other.file_, nullptr);
    }
    return *this;
}

PartialFile::~PartialFile() { discard(); }

void PartialFile::discard() {
    if (file_ == nullptr) return;
    std::fclose(file_);
    file_ = nullptr;
    std::error_code ignored;
    std::filesystem::remove(partial_name(name_), ignored);
}

bool PartialFile::commit() {
    bool written = std::ferror(file_) == 0;
    written = std::fclose(file_) == 0 && written;
    file_ = nullptr;
    std::error_code ec;
    if (written) std::filesystem::rename(partial_name(name_), name_, ec);
    if (!written || ec) {
        std::filesystem::remove(partial_name(name_), ec);
        report_cannot_write(name_);
        return false;
    }
    return true;
}

}  // namespace nckit::cli
