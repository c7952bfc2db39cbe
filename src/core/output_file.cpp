#include "nckit/core/output_file.hpp"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

namespace nckit {

namespace {

namespace fs = std::filesystem;

// NAME.partial files being written, for the signal handler: plain C strings in lock-free slots,
// because a handler may only call async-signal-safe functions (unlink, signal, raise).
constexpr std::size_t registry_slots = 64;
std::array<std::atomic<char*>, registry_slots> partial_registry{};
constexpr std::array<int, 4> cleanup_signals = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

extern "C" void remove_partials_and_die(int signal_number) {
    for (std::atomic<char*>& slot : partial_registry) {
        if (char* path = slot.load()) ::unlink(path);
    }
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
}

void install_cleanup_handlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int signal_number : cleanup_signals) {
            struct sigaction current {};
            // A handler the embedding program installed stays; only the default action is taken over.
            if (::sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler == SIG_DFL) {
                struct sigaction action {};
                action.sa_handler = remove_partials_and_die;
                sigemptyset(&action.sa_mask);
                ::sigaction(signal_number, &action, nullptr);
            }
        }
    });
}

int register_partial(const fs::path& partial) {
    install_cleanup_handlers();
    char* copy = ::strdup(partial.c_str());
    if (copy == nullptr) return -1;
    for (std::size_t i = 0; i < registry_slots; ++i) {
        char* expected = nullptr;
        if (partial_registry[i].compare_exchange_strong(expected, copy)) return static_cast<int>(i);
    }
    std::free(copy);  // more outputs at once than slots: the file is still removed when dropped
    return -1;
}

void unregister_partial(int slot) {
    if (slot < 0) return;
    std::free(partial_registry[static_cast<std::size_t>(slot)].exchange(nullptr));
}

OutputError error_of(const std::string& name, int error_number, std::string detail) {
    return OutputError{name, std::strerror(error_number), std::move(detail)};
}

std::string folder_of(const fs::path& path) {
    fs::path parent = path.parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

// Follows symlinks (at most 40, as the kernel does) to the name they finally point at, which may
// not exist yet.
std::variant<fs::path, OutputError> resolve_symlinks(const std::string& name) {
    fs::path path = name;
    for (int hops = 0; hops < 40; ++hops) {
        struct stat link_status {};
        if (::lstat(path.c_str(), &link_status) != 0 || !S_ISLNK(link_status.st_mode)) return path;
        std::array<char, 4096> buffer{};
        ssize_t length = ::readlink(path.c_str(), buffer.data(), buffer.size() - 1);
        if (length < 0) return error_of(name, errno, fmt::format("cannot read the symlink '{}'", path.string()));
        fs::path target(std::string(buffer.data(), static_cast<std::size_t>(length)));
        path = target.is_absolute() ? target : path.parent_path() / target;
    }
    return error_of(name, ELOOP, "symlinks nested more than 40 deep");
}

}  // namespace

std::string OutputError::message() const {
    std::string text = fmt::format("{}: cannot write: {}", name, reason);
    if (!detail.empty()) text += fmt::format(" ({})", detail);
    return text;
}

std::variant<OutputFile, OutputError> OutputFile::open(const std::string& name) {
    OutputFile out;
    out.name_ = name;
    if (name == "-") {
        out.kind_ = Kind::standard_output;
        out.stream_ = stdout;
        return out;
    }
    auto resolved = resolve_symlinks(name);
    if (auto* error = std::get_if<OutputError>(&resolved)) return std::move(*error);
    const fs::path target = std::get<fs::path>(std::move(resolved));
    const std::string via = target.string() == name ? std::string{} : fmt::format("'{}', ", target.string());

    struct stat status {};
    const bool exists = ::stat(target.c_str(), &status) == 0;
    if (exists && S_ISDIR(status.st_mode)) return error_of(name, EISDIR, via + "a folder, not a file");
    if (exists && !S_ISREG(status.st_mode)) {
        // A device, pipe or socket is written through: replacing it would destroy it.
        int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) return error_of(name, errno, via + "cannot open for writing");
        out.stream_ = ::fdopen(fd, "wb");
        if (out.stream_ == nullptr) {
            int saved = errno;
            ::close(fd);
            return error_of(name, saved, "");
        }
        out.kind_ = Kind::write_through;
        return out;
    }
    if (!exists) {
        const std::string folder = folder_of(target);
        struct stat folder_status {};
        if (::stat(folder.c_str(), &folder_status) != 0) {
            return error_of(name, errno, fmt::format("folder '{}' does not exist", folder));
        }
        if (!S_ISDIR(folder_status.st_mode)) {
            return error_of(name, ENOTDIR, fmt::format("'{}' is not a folder", folder));
        }
    }
    out.kind_ = Kind::atomic_replace;
    out.target_ = target;
    out.partial_ = target;
    out.partial_ += ".partial";
    // A stale NAME.partial (a crash, or a symlink someone left there) is removed, never read or
    // followed; O_EXCL then creates a fresh one.
    ::unlink(out.partial_.c_str());
    const mode_t mode = exists ? (status.st_mode & 07777) : 0666;
    int fd = ::open(out.partial_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd < 0) {
        int saved = errno;
        return error_of(
            name, saved,
            fmt::format("cannot create '{}' in folder '{}'", out.partial_.filename().string(), folder_of(target)));
    }
    if (exists) ::fchmod(fd, mode);  // keep the replaced file's permissions whatever the umask
    out.stream_ = ::fdopen(fd, "wb");
    if (out.stream_ == nullptr) {
        int saved = errno;
        ::close(fd);
        ::unlink(out.partial_.c_str());
        return error_of(name, saved, "");
    }
    out.registry_slot_ = register_partial(out.partial_);
    return out;
}

OutputFile::OutputFile(OutputFile&& other) noexcept {
    *this = std::move(other);
}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
    if (this != &other) {
        discard();
        name_ = std::move(other.name_);
        target_ = std::move(other.target_);
        partial_ = std::move(other.partial_);
        stream_ = std::exchange(other.stream_, nullptr);
        kind_ = other.kind_;
        registry_slot_ = std::exchange(other.registry_slot_, -1);
    }
    return *this;
}

OutputFile::~OutputFile() {
    discard();
}

void OutputFile::discard() {
    if (stream_ == nullptr) return;
    switch (kind_) {
        case Kind::standard_output:
            std::fflush(stdout);
            break;
        case Kind::write_through:
            std::fclose(stream_);
            break;
        case Kind::atomic_replace:
            std::fclose(stream_);
            ::unlink(partial_.c_str());
            unregister_partial(registry_slot_);
            registry_slot_ = -1;
            break;
    }
    stream_ = nullptr;
}

std::optional<OutputError> OutputFile::commit() {
    if (stream_ == nullptr) return std::nullopt;
    std::FILE* stream = std::exchange(stream_, nullptr);
    errno = 0;
    bool ok = std::fflush(stream) == 0 && std::ferror(stream) == 0;
    int saved = errno != 0 ? errno : EIO;
    if (kind_ == Kind::standard_output)
        return ok ? std::nullopt : std::optional(error_of(name_, saved, "standard output"));
    if (kind_ == Kind::write_through) {
        ok = std::fclose(stream) == 0 && ok;
        if (!ok) return error_of(name_, errno != 0 ? errno : saved, "");
        return std::nullopt;
    }
    // Data on disk before the rename makes it visible, the rename on disk before we say done.
    if (ok && ::fsync(::fileno(stream)) != 0) {
        ok = false;
        saved = errno;
    }
    if (std::fclose(stream) != 0 && ok) {
        ok = false;
        saved = errno;
    }
    if (ok && std::rename(partial_.c_str(), target_.c_str()) != 0) {
        ok = false;
        saved = errno;
    }
    if (!ok) ::unlink(partial_.c_str());
    unregister_partial(registry_slot_);
    registry_slot_ = -1;
    if (!ok) return error_of(name_, saved, "");
    int folder = ::open(folder_of(target_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
    return std::nullopt;
}

std::optional<OutputError> write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
    // A file that is really named "-" is a file, not standard output.
    auto opened = OutputFile::open(path.string() == "-" ? "./-" : path.string());
    if (auto* error = std::get_if<OutputError>(&opened)) return std::move(*error);
    OutputFile& out = std::get<OutputFile>(opened);
    out.write(bytes);
    return out.commit();
}

}  // namespace nckit
