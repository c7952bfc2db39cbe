// nckit notch FILE: laser notching. Moves each laser-on M-code back along the cut line by the
// run-up the S-curve needs to reach the cut's feed, runs the stroke on past the programmed end
// with the beam switched off there by position, and reports the planned speed along every
// programmed cut before and after. -o writes the rewritten program (a plain program, as
// `nckit expand` writes); the report goes to standard output, as text or with --json.
//
// The job runs in passes over the program (nckit::run_notch_job), so the report streams out cut
// by cut in bounded memory: the rewritten program waits in an unnamed temporary file until it is
// checked, and a program from standard input is first copied to one, to be read again.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <variant>

#include <fmt/format.h>

#include "common.hpp"
#include "nckit/gcode/program_source.hpp"
#include "nckit/process/notch/notch.hpp"
#include "nckit/process/notch/notch_json.hpp"
#include "nckit/report/process_pages.hpp"
#include "partial_file.hpp"
#include "tool_path_page.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct NotchCliOptions {
    std::string program;
    std::string output;
    MachineOptions machine;
    bool json = false;
    std::string html;
    std::size_t cuts_per_pass = NotchOptions{}.cuts_per_chunk;
};

void print_cut_text(const NotchCut& cut) {
    fmt::print("line {}{}: M{} then a {:.4f} mm cut at F{}\n", cut.where.line,
               cut.sequence_number >= 0 ? fmt::format(" (N{})", cut.sequence_number) : std::string(),
               cut.laser_on_mcode, cut.length_mm, cut.feed_mm_min);
    fmt::print("  run-up {:.6f} mm (placed {:.4f} mm{}), overrun {:.6f} mm\n", cut.run_up_mm, cut.run_up_placed_mm,
               cut.approach_shortened ? ", on the approach" : ", head steps back", cut.overrun_mm);
    for (const auto& [name, speed] : {std::pair{"before", &cut.before}, std::pair{"after ", &cut.after}}) {
        fmt::print("  {} speed along the cut: min {:.3f} max {:.3f} mean {:.3f} mm/min over {:.4f} mm\n", name,
                   speed->min_mm_min, speed->max_mm_min, speed->mean_mm_min, speed->covered_mm);
    }
}

//! The report, printed as the cuts come: "{"cuts":[" (or the count line) once the job is
//! checked, then each cut.
class ReportPrinter {
public:
    ReportPrinter(bool json, std::string program) : json_(json), program_(std::move(program)) {}
    void begin(std::size_t cuts) const {
        if (json_) {
            fmt::print("{{\"cuts\":[");
        } else {
            fmt::print("{}: {} notch cut(s)\n", program_, cuts);
        }
    }
    void cut(const NotchCut& cut) {
        if (json_) {
            fmt::print("{}{}", printed_ == 0 ? "" : ",", to_json(cut).dump());
        } else {
            print_cut_text(cut);
        }
        ++printed_;
    }
    void end() const {
        if (json_) fmt::print("]}}\n");
    }

private:
    bool json_;
    std::string program_;
    std::size_t printed_ = 0;
};

//! An unnamed temporary file (gone when nckit exits, however it exits), written and then read
//! back by path through /proc/self/fd.
class SpoolFile {
public:
    static std::optional<SpoolFile> create() {
        std::FILE* file = std::tmpfile();
        if (file == nullptr) {
            fmt::print(stderr, "nckit notch: error: cannot create a temporary file: {}\n", std::strerror(errno));
            return std::nullopt;
        }
        return SpoolFile(file);
    }
    [[nodiscard]] int fd() const { return ::fileno(file_.get()); }
    void write(std::string_view bytes) {
        if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file_.get()) != bytes.size()) failed_ = true;
    }
    //! Everything written is on disk; false (and why printed) when a write failed (disk full).
    [[nodiscard]] bool flush() {
        if (std::fflush(file_.get()) != 0 || failed_ || std::ferror(file_.get()) != 0) {
            fmt::print(stderr, "nckit notch: error: cannot write a temporary file: {}\n", std::strerror(errno));
            return false;
        }
        return true;
    }
    [[nodiscard]] std::string path() const { return fmt::format("/proc/self/fd/{}", fd()); }
    //! Hands the whole content to `sink` in pieces.
    template <class Sink>
    bool copy_to(Sink&& sink) const {
        std::string buffer(1 << 16, '\0');
        for (off_t at = 0;;) {
            const ssize_t got = ::pread(fd(), buffer.data(), buffer.size(), at);
            if (got < 0) return false;
            if (got == 0) return true;
            sink(std::string_view(buffer.data(), static_cast<std::size_t>(got)));
            at += got;
        }
    }

private:
    struct Close {
        void operator()(std::FILE* file) const { std::fclose(file); }
    };
    explicit SpoolFile(std::FILE* file) : file_(file) {}
    std::unique_ptr<std::FILE, Close> file_;
    bool failed_ = false;
};

//! Standard input copied to a spool file that stands in for it: each pass rewinds it and reads
//! "-" again (so diagnostics still name <stdin>).
bool spool_standard_input(std::optional<SpoolFile>& spool) {
    spool = SpoolFile::create();
    if (!spool) return false;
    std::string buffer(1 << 16, '\0');
    for (;;) {
        const ssize_t got = ::read(STDIN_FILENO, buffer.data(), buffer.size());
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            fmt::print(stderr, "<stdin>: error: cannot read standard input: {}\n", std::strerror(errno));
            return false;
        }
        if (got == 0) break;
        spool->write(std::string_view(buffer.data(), static_cast<std::size_t>(got)));
    }
    if (!spool->flush()) return false;
    if (::dup2(spool->fd(), STDIN_FILENO) < 0 || ::lseek(STDIN_FILENO, 0, SEEK_SET) != 0) {
        fmt::print(stderr, "nckit notch: error: cannot read standard input again: {}\n", std::strerror(errno));
        return false;
    }
    return true;
}

int run_notch(const NotchCliOptions& options) {
    std::optional<SpoolFile> input;
    const bool from_stdin = options.program == "-";
    if (from_stdin && !spool_standard_input(input)) return exit_bad_input;
    auto interpreter = open_program_or_report(options.program, options.machine, false);
    if (!interpreter) return exit_bad_input;
    const MachineConfig machine = interpreter->machine();
    if (machine.laser_on_mcodes.empty()) {
        // Without a laser-on code there is no cut to find: "0 notch cut(s)" would be a silent no-op.
        fmt::print(stderr,
                   "{}: error: machine '{}' names no laser code: give [machine] laser_on_mcodes (and "
                   "laser_off_mcodes), e.g. --machine examples/machines/notcher.toml\n",
                   options.machine.machine.empty() ? "nckit notch" : options.machine.machine, machine.name);
        return exit_bad_input;
    }
    std::optional<SpoolFile> rewritten = SpoolFile::create();
    if (!rewritten) return exit_bad_input;

    NotchStreams streams;
    bool first_pass = true;
    streams.original = [&]() -> std::optional<MoveReader> {
        std::optional<Interpreter> run;
        if (first_pass) {
            run = std::move(interpreter);  // opened above, warnings on
            first_pass = false;
        } else {
            if (from_stdin) ::lseek(STDIN_FILENO, 0, SEEK_SET);
            run = open_program_or_report(options.program, options.machine, false, false);
            if (!run) return std::nullopt;
        }
        auto shared = std::make_shared<Interpreter>(std::move(*run));
        return MoveReader([shared] { return shared->next(); });
    };
    streams.write_rewritten = [&](std::string_view text) { rewritten->write(text); };
    streams.rewritten = [&]() -> std::optional<MoveReader> {
        if (!rewritten->flush()) return std::nullopt;
        auto source = ProgramSource::open(rewritten->path());
        if (!source) {
            print_diagnostics(source.diagnostics());
            return std::nullopt;
        }
        auto shared = std::make_shared<Interpreter>(machine, std::move(source).value());
        return MoveReader([shared] { return shared->next(); });
    };
    // The -o file is complete and in place before the report starts; with --html the report
    // waits for the page (which needs every cut), as the page comes first.
    ReportPrinter printer(options.json, options.program);
    NotchJob held;
    const bool hold = !options.html.empty();
    streams.on_checked = [&](std::size_t cuts) {
        if (!options.output.empty()) {
            std::optional<PartialFile> out = PartialFile::create(options.output);
            if (!out) return false;
            if (!rewritten->copy_to([&](std::string_view bytes) { out->write(bytes); })) {
                fmt::print(stderr, "nckit notch: error: cannot read a temporary file: {}\n", std::strerror(errno));
                return false;
            }
            if (!out->commit()) return false;
        }
        if (!hold) printer.begin(cuts);
        return true;
    };
    streams.on_cut = [&](NotchCut&& cut) {
        if (hold) {
            held.cuts.push_back(std::move(cut));
        } else {
            printer.cut(cut);
        }
    };
    NotchOptions job_options;
    job_options.cuts_per_chunk = options.cuts_per_pass;
    NotchRunStatus status = run_notch_job(machine, options.program, streams, job_options);
    if (!status.ok()) {
        std::fflush(stdout);
        print_diagnostics(status.diagnostics);
        return exit_bad_input;
    }
    if (hold) {
        // The page shows the rewritten program's tool path beside the speeds over the cuts.
        if (!rewritten->copy_to([&](std::string_view bytes) { held.program += bytes; })) return exit_bad_input;
        ReportPage page = notch_page(held, options.program);
        page.tool_path = plan_tool_path_text(
            held.program, options.output.empty() ? options.program + " (rewritten)" : options.output, machine);
        if (!page.tool_path || !write_page(page, options.html)) return exit_bad_input;
        printer.begin(held.cuts.size());
        for (const NotchCut& cut : held.cuts) printer.cut(cut);
    }
    printer.end();
    return 0;
}

}  // namespace

void add_notch_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<NotchCliOptions>();
    CLI::App* verb = app.add_subcommand(
        "notch", "Laser notching: place each laser-on M-code a run-up before its cut so the cut runs at feed");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    verb->add_option("-o,--output", options->output, "write the rewritten program here");
    add_machine_options(*verb, options->machine);
    verb->add_flag("--json", options->json, "print the report (with the speed profiles) as one JSON object");
    verb->add_option("--html", options->html,
                     "write an interactive page: speed over each cut before and after, the rewritten tool path");
    verb->add_option("--cuts-per-pass", options->cuts_per_pass,
                     "cuts checked per run of the program, 1-1000000 (default 4096): memory holds about two "
                     "passes' cuts, and each further pass runs the program once more")
        ->check(CLI::Range(1, 1000000));
    verb->callback([options, &exit_status] { exit_status = run_notch(*options); });
}

}  // namespace nckit::cli
