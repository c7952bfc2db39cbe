#include "nckit/interp/run_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <variant>

#include <fmt/format.h>

namespace nckit {

namespace {

std::array<std::uint32_t, 256> make_crc_table() {
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t i = 0; i < 256; ++i) {
        std::uint32_t c = i;
        for (int k = 0; k < 8; ++k) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1U) : c >> 1U;
        table[i] = c;
    }
    return table;
}

const AxisVector* end_of(const Move& move) {
    if (const auto* line = std::get_if<Line>(&move.what)) return &line->to;
    if (const auto* arc = std::get_if<Arc>(&move.what)) return &arc->to;
    if (const auto* sync = std::get_if<SyncMove>(&move.what)) return &sync->to;
    return nullptr;
}

Diagnostic journal_error(const std::string& path, const std::string& what) {
    return error_at(make_location(std::make_shared<const std::string>(path), 1, 1), "journal-write",
                    fmt::format("run journal: {}: {}", what, std::strerror(errno)));
}

void append_retained(std::string& out, int number, const std::optional<double>& value) {
    if (value) {
        fmt::format_to(std::back_inserter(out), " #{}={}", number, *value);
    } else {
        fmt::format_to(std::back_inserter(out), " #{}=-", number);
    }
}

std::string with_checksum(std::string payload) {
    const std::uint32_t crc = crc32(payload);
    fmt::format_to(std::back_inserter(payload), " *{:08x}\n", crc);
    return payload;
}

}  // namespace

std::uint32_t crc32(std::string_view bytes, std::uint32_t crc) {
    static const std::array<std::uint32_t, 256> table = make_crc_table();
    crc = ~crc;
    for (char ch : bytes) crc = table[(crc ^ static_cast<unsigned char>(ch)) & 0xFFU] ^ (crc >> 8U);
    return ~crc;
}

Result<std::pair<std::uint64_t, std::uint32_t>> file_crc32(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return Result<std::pair<std::uint64_t, std::uint32_t>>(
            error_at(make_location(std::make_shared<const std::string>(path.string()), 1, 1), "journal-unreadable",
                     "cannot read the program to check it against the run journal"));
    }
    std::uint64_t size = 0;
    std::uint32_t crc = 0;
    std::string chunk(1 << 16, '\0');
    while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0) {
        const auto got = static_cast<std::size_t>(in.gcount());
        crc = crc32(std::string_view(chunk.data(), got), crc);
        size += got;
    }
    return std::pair<std::uint64_t, std::uint32_t>{size, crc};
}

std::string journal_header_line(const JournalHeader& header) {
    std::string payload = fmt::format("nckit-journal {} {} {:08x} {}", journal_format_version, header.program_bytes,
                                      header.program_crc, header.axes);
    for (const RetainedVariable& v : header.retained_start) append_retained(payload, v.number, v.value);
    return with_checksum(std::move(payload));
}

std::string journal_block_line(const JournalBlock& block, const std::string& axes) {
    std::string payload = fmt::format("B {} {} {}", block.block, block.line, block.sequence_number);
    if (block.position) {
        for (std::size_t i = 0; i < axes.size() && i < block.position->size(); ++i) {
            fmt::format_to(std::back_inserter(payload), " {}={}", axes[i], (*block.position)[i]);
        }
    } else {
        payload += " -";
    }
    for (const auto& [number, value] : block.retained_changes) append_retained(payload, number, value);
    return with_checksum(std::move(payload));
}

Result<RunJournal> RunJournal::create(const std::filesystem::path& path, const Interpreter& interpreter,
                                      const std::filesystem::path& program, JournalOptions options) {
    auto program_crc = file_crc32(program);
    if (!program_crc) return Result<RunJournal>(program_crc.diagnostics().front());
    RunJournal journal;
    journal.path_ = path.string();
    journal.options_ = options;
    for (const AxisConfig& axis : interpreter.machine().axes) {
        journal.axes_ += letter(axis.axis);
        journal.axis_order_.push_back(axis.axis);
    }
    journal.retained_writes_ = interpreter.retained_writes();
    journal.retained_ = interpreter.retained_values();
    journal.fd_ = ::open(journal.path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (journal.fd_ < 0) return Result<RunJournal>(journal_error(journal.path_, "cannot create"));
    JournalHeader header{program_crc->first, program_crc->second, journal.axes_, journal.retained_};
    journal.write(journal_header_line(header), true);
    if (journal.error_) return Result<RunJournal>(*journal.error_);
    return journal;
}

RunJournal::RunJournal(RunJournal&& other) noexcept {
    *this = std::move(other);
}

RunJournal& RunJournal::operator=(RunJournal&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = std::exchange(other.fd_, -1);
        path_ = std::move(other.path_);
        axes_ = std::move(other.axes_);
        axis_order_ = std::move(other.axis_order_);
        options_ = other.options_;
        blocks_ = other.blocks_;
        pending_ = std::move(other.pending_);
        position_ = std::move(other.position_);
        retained_writes_ = other.retained_writes_;
        retained_ = std::move(other.retained_);
        last_sync_ = other.last_sync_;
        written_ = other.written_;
        error_ = std::move(other.error_);
    }
    return *this;
}

RunJournal::~RunJournal() {
    if (fd_ >= 0) ::close(fd_);
}

void RunJournal::on_move(const Interpreter& interpreter, const Move& move) {
    if (blocks_.note(move, interpreter.output_batch())) {
        Pending p;
        p.record.block = blocks_.count();
        p.record.line = move.where.line;
        p.record.sequence_number = move.sequence_number;
        p.file = move.where.file.get();
        // The interpreter ran this block's assignments before handing out its first move.
        if (interpreter.retained_writes() != retained_writes_) {
            retained_writes_ = interpreter.retained_writes();
            std::vector<RetainedVariable> now = interpreter.retained_values();
            std::size_t i = 0, j = 0;
            while (i < retained_.size() || j < now.size()) {
                if (j == now.size() || (i < retained_.size() && retained_[i].number < now[j].number)) {
                    p.record.retained_changes.emplace_back(retained_[i++].number, std::nullopt);
                } else if (i == retained_.size() || now[j].number < retained_[i].number) {
                    p.record.retained_changes.emplace_back(now[j].number, now[j].value);
                    ++j;
                } else {
                    if (!(retained_[i] == now[j])) p.record.retained_changes.emplace_back(now[j].number, now[j].value);
                    ++i;
                    ++j;
                }
            }
            retained_ = std::move(now);
        }
        pending_.push_back(std::move(p));
    }
    if (const AxisVector* end = end_of(move)) {
        std::vector<double> at(axis_order_.size());
        for (std::size_t i = 0; i < axis_order_.size(); ++i) at[i] = (*end)[axis_order_[i]];
        position_ = std::move(at);
    }
    if (!pending_.empty()) pending_.back().record.position = position_;
}

void RunJournal::on_reached(const SourceLocation& where) {
    // Motion is reached in move order: every block before the first pending block of this
    // line is behind the machine. A line whose block is already complete changes nothing.
    for (std::size_t i = 0; i < pending_.size(); ++i) {
        if (pending_[i].file == where.file.get() && pending_[i].record.line == where.line) {
            complete(i);
            return;
        }
    }
}

void RunJournal::finish() {
    complete(pending_.size());
    if (fd_ >= 0 && !error_ && ::fsync(fd_) != 0) error_ = journal_error(path_, "cannot sync");
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
}

void RunJournal::complete(std::size_t count) {
    if (count == 0) return;
    std::string text;
    for (std::size_t i = 0; i < count; ++i) {
        text += journal_block_line(pending_.front().record, axes_);
        pending_.pop_front();
    }
    written_ += static_cast<std::int64_t>(count);
    const auto now = std::chrono::steady_clock::now();
    write(text, now - last_sync_ >= std::chrono::milliseconds(options_.fsync_interval_ms));
}

void RunJournal::write(const std::string& text, bool sync_now) {
    if (fd_ < 0 || error_) return;
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error_ = journal_error(path_, "cannot write");
            return;
        }
        done += static_cast<std::size_t>(n);
    }
    if (sync_now) {
        if (::fdatasync(fd_) != 0) {
            error_ = journal_error(path_, "cannot sync");
            return;
        }
        last_sync_ = std::chrono::steady_clock::now();
    }
}

}  // namespace nckit
