#include "nckit/interp/move_format.hpp"

#include "nckit/core/format_fixed.hpp"

#include <cmath>
#include <iterator>
#include <string_view>
#include <variant>

#include <fmt/format.h>

namespace nckit {

namespace {

template <class... Ts>
struct overloaded : Ts... {
    using Ts::operator()...;
};
// clang 14 (the fuzz build) does not deduce an aggregate's template arguments by itself.
template <class... Ts>
overloaded(Ts...) -> overloaded<Ts...>;

//! -0.0000 reads as a different number to a person; print it as 0.
double no_negative_zero(double value, double resolution) {
    return std::abs(value) < resolution / 2 ? 0.0 : value;
}

void fixed(std::string& out, std::string_view prefix, double value) {
    out += ' ';
    out += prefix;
    append_fixed4(out, no_negative_zero(value, 1e-4));
}

void axes_text(std::string& out, const AxisVector& p, const MachineConfig& machine) {
    AxisSet configured;
    for (const AxisConfig& axis : machine.axes) configured.insert(axis.axis);
    for (std::size_t i = 0; i < axis_count; ++i) {
        auto axis = static_cast<Axis>(i);
        const char name[1] = {letter(axis)};
        if (configured.contains(axis)) fixed(out, std::string_view(name, 1), p[axis]);
    }
}

void feed_text(std::string& out, const Feed& feed) {
    if (feed.mode == FeedMode::per_revolution) {
        out += " FR";
        append_fixed4(out, feed.mm_per_rev);
    } else {
        fixed(out, "F", feed.mm_per_min);
    }
}

std::string io_code(const Io& io) {
    switch (io.kind) {
        case IoKind::mcode:
            return fmt::format("M{}", io.number);
        case IoKind::spindle_speed:
            return "S";
        case IoKind::tool_select:
            return fmt::format("T{}", io.number);
    }
    return "?";
}

void json_number(std::string& out, double value) {
    fmt::format_to(std::back_inserter(out), "{}", no_negative_zero(value, 1e-300));
}

void json_axes(std::string& out, const char* key, const AxisVector& p, const MachineConfig& machine,
               bool linear_only = false) {
    fmt::format_to(std::back_inserter(out), ",\"{}\":{{", key);
    bool first = true;
    for (std::size_t i = 0; i < axis_count; ++i) {
        auto axis = static_cast<Axis>(i);
        const AxisConfig* config = machine.find(axis);
        if (config == nullptr || (linear_only && i > index(Axis::Z))) continue;
        fmt::format_to(std::back_inserter(out), "{}\"{}\":", first ? "" : ",", letter(axis));
        json_number(out, p[axis]);
        first = false;
    }
    out += '}';
}

void json_feed(std::string& out, const Feed& feed) {
    out += ",\"feed_mm_min\":";
    json_number(out, feed.mm_per_min);
    if (feed.mode == FeedMode::per_revolution) {
        out += ",\"feed_mm_rev\":";
        json_number(out, feed.mm_per_rev);
    }
}

const char* plane_name(Plane plane) {
    switch (plane) {
        case Plane::xy:
            return "xy";
        case Plane::zx:
            return "zx";
        case Plane::yz:
            return "yz";
    }
    return "xy";
}

}  // namespace

void append_move_text(std::string& out, const Move& move, const MachineConfig& machine) {
    std::visit(overloaded{
                   [&](const Line& l) {
                       out += l.rapid ? "G0" : "G1";
                       axes_text(out, l.to, machine);
                       if (!l.rapid) feed_text(out, l.feed);
                   },
                   [&](const Arc& a) {
                       out += a.direction == ArcDirection::clockwise ? "G2" : "G3";
                       axes_text(out, a.to, machine);
                       for (Axis axis : {Axis::X, Axis::Y, Axis::Z}) {
                           if (machine.find(axis) == nullptr) continue;
                           const char name[2] = {'C', letter(axis)};
                           fixed(out, std::string_view(name, 2), a.center[axis]);
                       }
                       feed_text(out, a.feed);
                   },
                   [&](const SyncMove& s) {
                       out += "G33";
                       axes_text(out, s.to, machine);
                       feed_text(out, s.feed);
                       if (s.start_angle_deg != 0)
                           fmt::format_to(std::back_inserter(out), " Q{:.3f}", s.start_angle_deg);
                   },
                   [&](const Dwell& d) { fmt::format_to(std::back_inserter(out), "G4 P{:.4f}", d.seconds); },
                   [&](const Io& io) {
                       if (io.kind == IoKind::spindle_speed) {
                           fmt::format_to(std::back_inserter(out), "S{}", io.value);
                       } else {
                           out += io_code(io);
                       }
                   },
               },
               move.what);
}

void append_move_json(std::string& out, const Move& move, const MachineConfig& machine) {
    fmt::format_to(std::back_inserter(out), "{{\"line\":{}", move.where.line);
    if (move.sequence_number >= 0) fmt::format_to(std::back_inserter(out), ",\"n\":{}", move.sequence_number);
    std::visit(overloaded{
                   [&](const Line& l) {
                       out += l.rapid ? ",\"kind\":\"rapid\"" : ",\"kind\":\"linear\"";
                       json_axes(out, "start", l.from, machine);
                       json_axes(out, "end", l.to, machine);
                       if (!l.rapid) json_feed(out, l.feed);
                       if (l.path.exact_stop) out += ",\"exact_stop\":true";
                   },
                   [&](const Arc& a) {
                       out += ",\"kind\":\"arc\"";
                       json_axes(out, "start", a.from, machine);
                       json_axes(out, "end", a.to, machine);
                       json_axes(out, "center", a.center, machine, true);
                       fmt::format_to(std::back_inserter(out), ",\"dir\":\"{}\",\"plane\":\"{}\",\"turns\":{}",
                                      a.direction == ArcDirection::clockwise ? "cw" : "ccw", plane_name(a.plane),
                                      a.full_turns);
                       json_feed(out, a.feed);
                       if (a.path.exact_stop) out += ",\"exact_stop\":true";
                   },
                   [&](const SyncMove& s) {
                       out += ",\"kind\":\"sync\"";
                       json_axes(out, "start", s.from, machine);
                       json_axes(out, "end", s.to, machine);
                       json_feed(out, s.feed);
                       if (s.start_angle_deg != 0) {
                           out += ",\"start_angle_deg\":";
                           json_number(out, s.start_angle_deg);
                       }
                   },
                   [&](const Dwell& d) {
                       out += ",\"kind\":\"dwell\",\"seconds\":";
                       json_number(out, d.seconds);
                   },
                   [&](const Io& io) {
                       fmt::format_to(std::back_inserter(out), ",\"kind\":\"io\",\"code\":\"{}\"", io_code(io));
                       if (io.kind == IoKind::spindle_speed ||
                           (io.kind == IoKind::mcode && (io.number == 3 || io.number == 4))) {
                           out += io.constant_surface_speed ? ",\"surface_speed_m_min\":" : ",\"rpm\":";
                           json_number(out, io.value);
                           if (io.constant_surface_speed && io.rpm_clamp > 0) {
                               out += ",\"rpm_clamp\":";
                               json_number(out, io.rpm_clamp);
                           }
                       }
                       if (io.waits) out += ",\"waits\":true";
                   },
               },
               move.what);
    out += '}';
}

}  // namespace nckit
