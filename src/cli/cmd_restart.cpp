// nckit restart PROGRAM --seq N[:k] | --line L | --block B: a program that picks up the run at
// the target block (docs/restart.md). The logic is nckit::write_restart; this file parses the
// target, writes the file and prints the report.
#include <charconv>
#include <cstdio>
#include <iterator>

#include <fmt/format.h>

#include "common.hpp"
#include "nckit/interp/restart.hpp"
#include "partial_file.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct RestartOptions {
    std::string program;
    std::string output;
    std::string seq;
    std::int64_t line = 0;
    std::int64_t block = 0;
    int decimals = -1;
    bool json = false;
    MachineOptions machine;
};

//! "N" or "N:k" (k-th time N is reached), both positive integers; nothing when malformed.
std::optional<RestartTarget> parse_seq(const std::string& text) {
    RestartTarget target;
    target.kind = RestartTarget::Kind::sequence;
    const char* begin = text.data();
    const char* end = begin + text.size();
    auto [p, error] = std::from_chars(begin, end, target.number);
    if (error != std::errc{} || target.number < 0) return std::nullopt;
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

std::string report_json(const RestartReport& r, const MachineConfig& machine) {
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
    fmt::format_to(o, ",\"worst_deviation_mm\":{}}}\n", json_number(r.worst_deviation_mm));
    return out;
}

int run_restart(const RestartOptions& options, const RestartTarget& target) {
    // Searching is not running: #500-#999 stay as the file holds them.
    auto interpreter = open_program_or_report(options.program, options.machine, false);
    if (!interpreter) return exit_bad_input;
    std::string text;
    Result<RestartReport> report = write_restart(*interpreter, target, options.program, text, options.decimals);
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
    if (options.json) std::fputs(report_json(*report, interpreter->machine()).c_str(), stdout);
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
    CLI::Option* line =
        verb->add_option("--line", options->line, "restart at the first block run from this line of PROGRAM")
            ->check(CLI::PositiveNumber);
    CLI::Option* block =
        verb->add_option("--block", options->block, "restart at the B-th executed block that moves (1-based)")
            ->check(CLI::PositiveNumber);
    seq->excludes(line)->excludes(block);
    line->excludes(block);
    verb->add_option("-o,--output", options->output, "write the restart program here (default: standard output)");
    verb->add_option("--decimals", options->decimals, "round coordinates to N decimals (default: exact)")
        ->check(CLI::Range(0, 17));
    verb->add_flag("--json", options->json, "print the target, the state rebuilt and the approach as JSON");
    add_machine_options(*verb, options->machine);
    verb->callback([options, seq, line, block, &exit_status] {
        std::optional<RestartTarget> target;
        if (seq->count() > 0) {
            target = parse_seq(options->seq);
            if (!target) {
                fmt::print(stderr, "nckit restart: error: --seq wants N or N:k with whole numbers (k >= 1), not '{}'\n",
                           options->seq);
                exit_status = exit_bad_input;
                return;
            }
        } else if (line->count() > 0) {
            target = RestartTarget{RestartTarget::Kind::line, options->line, 1};
        } else if (block->count() > 0) {
            target = RestartTarget{RestartTarget::Kind::block, options->block, 1};
        } else {
            fmt::print(stderr, "nckit restart: error: name the target with --seq, --line or --block\n");
            exit_status = exit_bad_input;
            return;
        }
        exit_status = run_restart(*options, *target);
    });
}

}  // namespace nckit::cli
