#include <iterator>

#include <fmt/format.h>

#include "nckit/process/fts/fast_tool_servo.hpp"

namespace nckit {

int settled_turn(const std::vector<double>& turn_pv_um, double limit_um) {
    int first = -1;
    for (int k = static_cast<int>(turn_pv_um.size()) - 1; k >= 0; --k) {
        if (!(turn_pv_um[static_cast<std::size_t>(k)] <= limit_um)) break;
        first = k;
    }
    return first;
}

std::string format_fts_trace_csv(const std::vector<FtsTraceRow>& rows) {
    std::string out = "t_s,theta_deg,z_mm,radius_mm,target_mm,command_mm,actual_mm,actual_mm_s\n";
    out.reserve(out.size() + rows.size() * 140);
    auto it = std::back_inserter(out);
    for (const FtsTraceRow& r : rows) {
        // 1e-12 s and 1e-12 mm: the differences of t_s are the hold intervals a re-simulation
        // steps by, and at ~100 mm/s a ps of error is 1e-10 mm.
        fmt::format_to(it, "{:.12f},{:.9f},{:.9f},{:.12f},{:.12f},{:.12f},{:.12f},{:.9f}\n", r.t_s, r.theta_deg, r.z_mm,
                       r.radius_mm, r.target_mm, r.command_mm, r.actual_mm, r.actual_mm_s);
    }
    return out;
}

}  // namespace nckit
