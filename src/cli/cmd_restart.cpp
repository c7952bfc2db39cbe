// nckit restart PROGRAM --seq N[:k] | --line L[:k] | --block B | --journal FILE: a program that
// picks up the run at the target block (docs/restart.md). The logic is nckit::write_restart and
// nckit::write_journal_restart; this file parses the target, writes the file and prints the
// report.
#include <charconv>
#include <cstdio>
#include <iterator>

#include <fmt/format.h>

#include "common.hpp"
#include "nckit/interp/restart.hpp"
#include "nckit/pipeline/journal_restart.hpp"
#include "partial_file.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct RestartOptions {
    std::string program;
    std::string output;
    std::string seq;
    std::string line;
    std::string journal;
    std::int64_t block = 0;
    int decimals = -1;
    bool json = false;
    MachineOptions machine;
};

//! "N" or "N:k" (k-th time N is reached), whole numbers, k >= 1; nothing when malformed.
std::optional<RestartTarget> parse_occurrence(const std::string& text, RestartTarget::Kind kind) {
    RestartTarget target;
    target.kind = kind;
    const char* begin = text.data();
    const char* end = begin + text.size();
    auto [p, error] = std::from_chars(begin, end, target.number);
    if (error != std::errc{} || target.number < (kind == RestartTarget::Kind::line ? 1 : 0)) return std::nullopt;
    if (p != end) {
        if (*p != ':') return std::nullopt;
        auto [q, error2] = std::from_chars(p + 1, end, target.occurrence);
        if (error2 != std::errc{} || q != end || target.occurrence < 1) return std::nullopt;
    }
    return target;
}

std::string vector_json(const AxisVector& v, const MachineConfig& machine) {
    std::string out = "{";
    for (const AxisConfig& axis : machine.axes) {
        if (out.size() > 1) out += ',';
        fmt::format_to(std::back_inserter(out), "\"{}\":{}", letter(axis.axis), json_number(v[axis.axis]));
    }
    return out + "}";
}

//! The mirror, scaling and rotation in force: {"mirror":{"X":at},"scale":null or {"center":{..},
//! "factors":{..}},"rotation":null or {"plane":"G17","center":[u,v],"deg":R}}, work mm / deg.
std::string transform_json(const TransformView& t, const MachineConfig& machine) {
    std::string mirror = "{";
    for (const AxisConfig& axis : machine.axes) {
        if (!t.mirrored[index(axis.axis)]) continue;
        if (mirror.size() > 1) mirror += ',';
        fmt::format_to(std::back_inserter(mirror), "\"{}\":{}", letter(axis.axis), json_number(t.mirror_at[axis.axis]));
    }
    mirror += '}';
    std::string scale = "null";
    if (t.scale_on) {
        AxisVector factors;
        for (std::size_t i = 0; i < axis_count; ++i) factors.value[i] = t.scale[i];
        scale = fmt::format("{{\"center\":{},\"factors\":{}}}", vector_json(t.scale_center, machine),
                            vector_json(factors, machine));
    }
    std::string rotation = "null";
    if (t.rotate_on) {
        rotation = fmt::format("{{\"plane\":\"{}\",\"center\":[{},{}],\"deg\":{}}}",
                               t.rotate_plane == Plane::xy   ? "G17"
                               : t.rotate_plane == Plane::zx ? "G18"
                                                             : "G19",
                               json_number(t.rotate_first), json_number(t.rotate_second), json_number(t.rotate_deg));
    }
    return fmt::format("{{\"mirror\":{},\"scale\":{},\"rotation\":{}}}", mirror, scale, rotation);
}

std::string report_json(const RestartReport& r, const MachineConfig& machine, const JournalContents* journal) {
    const ModalView& s = r.state;
    std::string out;
    auto o = std::back_inserter(out);
    fmt::format_to(o, "{{\"line\":{},\"seq\":{},\"block\":{},\"first_record\":{},\"rest_line\":{}", r.where.line,
                   r.sequence_number >= 0 ? std::to_string(r.sequence_number) : "null", r.block, r.first_record,
                   r.rest_line);
    fmt::format_to(o, ",\"state\":{{\"units\":\"{}\",\"distance\":\"{}\",\"plane\":\"{}\",\"diameter_mode\":{}",
                   s.length_factor_mm == 1.0 ? "G21" : "G20", s.incremental ? "G91" : "G90",
                   s.plane == Plane::xy   ? "G17"
                   : s.plane == Plane::zx ? "G18"
                                          : "G19",
                   s.diameter_mode);
    fmt::format_to(o, ",\"work_system\":\"G{}\",\"work_offset\":{},\"g92_offset\":{},\"g52_offset\":{}",
                   54 + s.work_system, vector_json(s.work_offset, machine), vector_json(s.g92_offset, machine),
                   vector_json(s.g52_offset, machine));
    fmt::format_to(o, ",\"tool\":{},\"tool_in_spindle\":{},\"length_offset\":\"G{}{}\",\"h\":{},\"tool_offset\":{}",
                   r.io.tool_selected, r.io.tool_in_spindle, s.length_offset_code / 10,
                   s.length_offset_code % 10 != 0 ? ".1" : "", s.length_offset_h, vector_json(s.tool_offset, machine));
    fmt::format_to(o, ",\"spindle\":\"M{}\",\"speed\":{},\"constant_surface_speed\":{},\"rpm_clamp\":{}",
                   r.io.spindle_mcode, r.io.speed_set ? json_number(r.io.speed) : "null", r.io.constant_surface_speed,
                   json_number(r.io.rpm_clamp));
    std::string latched;
    for (int m : r.io.laser_on) latched += fmt::format("{}\"M{}\"", latched.empty() ? "" : ",", m);
    fmt::format_to(o, ",\"mist\":{},\"flood\":{},\"latched_mcodes\":[{}]", r.io.mist, r.io.flood, latched);
    fmt::format_to(o, ",\"feed_mode\":\"{}\",\"feed\":{},\"path\":\"{}\",\"tolerance_mm\":{},\"transforms\":{}}}",
                   s.feed_mode == FeedMode::per_revolution ? "G95" : "G94", json_number(s.feed),
                   s.path.exact_stop ? "G61" : "G64", json_number(s.path.tolerance_mm), s.transform_active);
    out.pop_back();  // the state's closing brace: its transforms follow
    fmt::format_to(o, ",\"transform\":{}}}", transform_json(s.transform, machine));
    const RestartApproach& a = r.approach;
    std::string sides = "{";
    for (const AxisConfig& axis : machine.axes) {
        if (axis.axis == a.retract_axis) continue;
        if (sides.size() > 1) sides += ',';
        fmt::format_to(std::back_inserter(sides), "\"{}\":{}", letter(axis.axis), a.side[index(axis.axis)]);
    }
    sides += '}';
    fmt::format_to(o,
                   ",\"approach\":{{\"moves\":{},\"retract_axis\":\"{}\",\"safe_mm\":{},\"point\":{},\"sides\":{},"
                   "\"takeup_mm\":{},\"clearance_mm\":{},\"feed_mm_min\":{}}}",
                   a.moves, letter(a.retract_axis), json_number(a.safe_mm), vector_json(a.point, machine), sides,
                   json_number(a.takeup_mm), json_number(a.clearance_mm), json_number(a.feed_mm_min));
    fmt::format_to(o, ",\"worst_deviation_mm\":{}", json_number(r.worst_deviation_mm));
    if (journal != nullptr) {
        std::string retained;
        for (const RetainedVariable& v : r.retained) {
            retained += fmt::format("{}\"{}\":{}", retained.empty() ? "" : ",", v.number, json_number(v.value));
        }
        fmt::format_to(o, ",\"journal\":{{\"records\":{},\"last_block\":{},\"ignored_bytes\":{},\"retained\":{{{}}}}}",
                       journal->records, journal->last ? std::to_string(journal->last->block) : "null",
                       journal->ignored_bytes, retained);
    }
    out += "}\n";
    return out;
}

int run_restart(const RestartOptions& options, const std::optional<RestartTarget>& target) {
    std::optional<JournalContents> journal;
    MachineOptions machine = options.machine;
    if (!target) {
        auto read = read_journal(options.journal);
        if (!read) {
            print_diagnostics(read.diagnostics());
            return exit_bad_input;
        }
        journal = std::move(read).value();
        // The search starts from #500-#999 as the interrupted run found them, not the live file.
        machine.retained_start = journal->header.retained_start;
    }
    // Searching is not running: #500-#999 stay as the file holds them.
    auto interpreter = open_program_or_report(options.program, machine, false);
    if (!interpreter) return exit_bad_input;
    if (journal) {
        if (auto mismatch = check_journal_matches(*journal, options.program, interpreter->machine())) {
            print_diagnostic(*mismatch);
            return exit_bad_input;
        }
    }
    std::string text;
    Result<RestartReport> report =
        journal ? write_journal_restart(*interpreter, *journal, options.program, text, options.decimals)
                : write_restart(*interpreter, *target, options.program, text, RestartSettings{options.decimals, {}});
    if (!report) {
        print_diagnostics(report.diagnostics());
        return exit_bad_input;
    }
    if (options.output.empty()) {
        if (!options.json) std::fwrite(text.data(), 1, text.size(), stdout);
    } else {
        auto file = PartialFile::create(options.output);
        if (!file) return exit_bad_input;
        std::fwrite(text.data(), 1, text.size(), file->get());
        if (!file->commit()) return exit_bad_input;
    }
    if (options.json)
        std::fputs(report_json(*report, interpreter->machine(), journal ? &*journal : nullptr).c_str(), stdout);
    if (options.decimals >= 0 && !options.json) {
        fmt::print(stderr, "restart: coordinates rounded to {} decimals, worst deviation {} mm\n", options.decimals,
                   json_number(report->worst_deviation_mm));
    }
    return 0;
}

}  // namespace

void add_restart_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<RestartOptions>();
    CLI::App* verb =
        app.add_subcommand("restart", "Write a program that restarts a run at a block (power cut, broken tool)");
    verb->add_option("PROGRAM", options->program, "NC program")->required();
    CLI::Option* seq =
        verb->add_option("--seq", options->seq, "restart at sequence number N (N:k: the k-th time it is reached)");
    CLI::Option* line = verb->add_option(
        "--line", options->line, "restart at the first block run from this line of PROGRAM (L:k: the k-th time)");
    CLI::Option* block =
        verb->add_option("--block", options->block, "restart at the B-th executed block that moves (1-based)")
            ->check(CLI::PositiveNumber);
    CLI::Option* journal =
        verb->add_option("--journal", options->journal,
                         "restart after the last block a run journal (steps/servo --journal) records as done");
    seq->excludes(line)->excludes(block)->excludes(journal);
    line->excludes(block)->excludes(journal);
    block->excludes(journal);
    verb->add_option("-o,--output", options->output, "write the restart program here (default: standard output)");
    verb->add_option("--decimals", options->decimals, "round coordinates to N decimals (default: exact)")
        ->check(CLI::Range(0, 17));
    verb->add_flag("--json", options->json, "print the target, the state rebuilt and the approach as JSON");
    add_machine_options(*verb, options->machine);
    verb->callback([options, seq, line, block, journal, &exit_status] {
        std::optional<RestartTarget> target;
        if (seq->count() > 0) {
            target = parse_occurrence(options->seq, RestartTarget::Kind::sequence);
            if (!target) {
                fmt::print(stderr, "nckit restart: error: --seq wants N or N:k with whole numbers (k >= 1), not '{}'\n",
                           options->seq);
                exit_status = exit_bad_input;
                return;
            }
        } else if (line->count() > 0) {
            target = parse_occurrence(options->line, RestartTarget::Kind::line);
            if (!target) {
                fmt::print(stderr,
                           "nckit restart: error: --line wants L or L:k with whole numbers (L, k >= 1), not '{}'\n",
                           options->line);
                exit_status = exit_bad_input;
                return;
            }
        } else if (journal->count() > 0) {
            // The target comes from the journal.
        } else if (block->count() > 0) {
            target = RestartTarget{RestartTarget::Kind::block, options->block, 1};
        } else {
            fmt::print(stderr, "nckit restart: error: name the target with --seq, --line, --block or --journal\n");
            exit_status = exit_bad_input;
            return;
        }
        exit_status = run_restart(*options, target);
    });
}

}  // namespace nckit::cli
