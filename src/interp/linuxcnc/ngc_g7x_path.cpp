// The whole profile of LinuxCNC's lathe cycles: turned and mirrored into the working frame,
// corner finishes shaped, offset by an allowance, and the passes of G70 and G71/G72.
#include <algorithm>
#include <cmath>
#include <deque>

#include <fmt/format.h>

#include "ngc_g7x_profile.hpp"

namespace nckit::interp::ngc {

using namespace g7x_detail;

namespace {

constexpr std::uint64_t max_steps = 1'000'000;  //!< bounds the pass search on any profile
constexpr double max_finish_passes = 10'000;

using Path = std::vector<ProfileSegment>;

//! Turns the profile by 90 degrees (G72 and steep G70 shapes are roughed like G71's).
void turn_path(Path& path, MoveSink& sink) {
    for (ProfileSegment& s : path) turn(s);
    sink.flips ^= 4;
}

//! Mirrors the profile so that it runs towards -X and -Z, from its first end to its last.
void orient(Path& path, MoveSink& sink) {
    const ZX span = path.front().end - path.back().end;
    if (std::imag(span) > 0) {
        for (ProfileSegment& s : path) mirror_x(s);
        sink.flips ^= 2;
    }
    if (std::real(span) < 0) {
        for (ProfileSegment& s : path) mirror_z(s);
        sink.flips ^= 1;
    }
}

void shape_corners(Path& path, MoveSink& sink) {
    for (std::size_t i = 1; i + 1 < path.size(); ++i) {
        if (path[i].corner != CornerFinish::none) shape_corner(path[i], path[i - 1], path[i + 1], sink);
    }
    std::erase_if(path, [](const ProfileSegment& s) { return length_scale(s) < 1e-3; });
}

void require_monotonic(Path& path, MoveSink& sink) {
    // The approach (the first element) may run back in Z: it starts where the cut does.
    if (std::real(path.front().end - path.front().start) > 0) path.front().start.real(path.front().end.real());
    for (const ProfileSegment& s : path) {
        if (!monotonic(s)) sink.fail("the profile is not monotonic");
    }
}

//! G70 turns the shape by 90 degrees when, without its approach and mirrored, it is not monotonic;
//! turned, it must be.
bool should_turn(const Path& path, MoveSink& sink) {
    Path rest(path.begin() + 1, path.end());
    if (rest.empty()) return false;
    MoveSink scratch;
    orient(rest, scratch);
    if (std::all_of(rest.begin(), rest.end(), [](const ProfileSegment& s) { return monotonic(s); })) return false;
    turn_path(rest, scratch);
    orient(rest, scratch);
    require_monotonic(rest, sink);
    return true;
}

//! Offsets the profile (all but its approach) by `distance` towards the stock, in steps no
//! larger than half the shortest element, joining the elements again after every step.
void add_distance(Path& path, double distance, MoveSink& sink) {
    if (path.size() < 2) return;
    const ZX v1 = path.front().end - path.front().start;
    const ZX v2 = path.back().start - path.front().start;
    if (std::imag(v1 / v2) < 0) distance = -distance;
    ProfileSegment approach = path.front();
    path.erase(path.begin());
    double done = 0;
    std::uint64_t rounds = 0;
    while (done != distance && !path.empty()) {
        if (++rounds > 100000) {
            sink.fail("the finishing allowance takes too many offset steps");
            return;
        }
        double step = 1e9;
        for (const ProfileSegment& s : path) step = std::min(step, length_scale(s) / 2);
        step = std::min(step, std::abs(distance - done));
        if (distance < 0) step = -step;
        for (ProfileSegment& s : path) offset(s, step);
        std::erase_if(path, [](const ProfileSegment& s) { return length_scale(s) < 1e-3; });
        if (path.empty()) break;
        // Where two offset neighbours part in Z, an arc about their old meeting point joins them.
        for (std::size_t i = 0; i + 1 < path.size(); ++i) {
            if (std::real(path[i].end - path[i + 1].start) > 1e-2) {
                ProfileSegment s = path[i];
                ProfileSegment e = path[i + 1];
                offset(s, -step);
                offset(e, -step);
                ProfileSegment join;
                join.arc = true;
                join.ccw = distance > 0;
                join.start = path[i].end;
                join.center = (s.end + e.start) / 2.0;
                join.end = path[i + 1].start;
                path.insert(path.begin() + static_cast<std::ptrdiff_t>(i) + 1, join);
                ++i;
            }
        }
        // Join neighbours; an element turned back by the offset, or shrunk to nothing, goes (and
        // the joining starts over, from the second element, as LinuxCNC's does).
        for (std::size_t i = 0; path.size() >= 2 && i + 1 < path.size(); ++i) {
            if (!monotonic(path[i])) {
                if (i > 0 && length_scale(path[i]) >= length_scale(path[i - 1])) {
                    path.erase(path.begin() + static_cast<std::ptrdiff_t>(i) - 1);
                } else {
                    path.erase(path.begin() + static_cast<std::ptrdiff_t>(i));
                }
                i = 0;
                if (path.size() < 2) break;
            }
            if (length_scale(path[i]) < 1e-3) {
                path.erase(path.begin() + static_cast<std::ptrdiff_t>(i));
                i = 0;
            } else {
                meet(path[i], path[i + 1], sink);
            }
            if (sink.fault) return;
        }
        done += step;
    }
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        const ZX mid = (path[i].end + path[i + 1].start) / 2.0;
        path[i].end = path[i + 1].start = mid;
    }
    if (path.empty()) {
        sink.fail("the finishing allowance leaves no profile");
        return;
    }
    approach.end = path.front().start;
    path.insert(path.begin(), approach);
}

void finish_passes(Path path, const G7xRequest& q, MoveSink& sink) {
    if (should_turn(path, sink)) turn_path(path, sink);
    if (sink.fault) return;
    orient(path, sink);
    shape_corners(path, sink);
    require_monotonic(path, sink);
    if (sink.fault) return;
    if (q.passes > max_finish_passes) {
        sink.fail("too many finishing passes (P)");
        return;
    }
    for (auto pass = static_cast<std::int64_t>(q.passes); pass > 0; --pass) {
        const double distance = static_cast<double>(pass - 1) * (q.d - q.e) / q.passes + q.e;
        Path offset_path = path;
        add_distance(offset_path, distance, sink);
        if (sink.fault) return;
        sink.rapid(offset_path.front().start, true);
        sink.rapid(offset_path.front().end);
        for (std::size_t k = 1; k < offset_path.size(); ++k) draw(offset_path[k], sink);
    }
}

//! The roughing passes: level by level down from the start, each cut along Z until it meets
//! the profile, then up and back by the retract distance; pockets once their entry is passed.
class Rougher {
public:
    Rougher(Path& path, int variant, double depth, double retract, MoveSink& sink)
        : path_(path), variant_(variant), delta_(depth), escape_(retract * ZX(1, 1)), sink_(sink) {}

    void run() {
        pocket_starts_.push_back(path_.front().start);
        ZX at = path_.front().start;
        std::size_t p = 0;
        while (pocket(at, p)) {
            if (sink_.fault) return;
        }
    }

private:
    bool tick() {
        if (++sink_.steps > max_steps) {
            sink_.fail("the roughing passes do not come to an end");
            return false;
        }
        return true;
    }

    //! One pocket; true when the next one is to be cut from `at`, element `p`.
    bool pocket(ZX& at, std::size_t& p) {
        double x = std::imag(pocket_starts_.back());
        if (variant_ == 2) {
            // G71.2: the first pass is skipped; only the pockets behind it are cut.
            for (; p < path_.size(); ++p) {
                if (dive(path_[p], at, -1e9, sink_, p == 0)) break;
            }
            variant_ = 3;
        }
        while (p < path_.size()) {
            if (!tick() || sink_.fault) return false;
            while (x - tolerance > std::imag(at)) {
                x -= delta_;
                if (!tick()) return false;
            }
            if (dive(path_[p], at, x, sink_, p == 0)) return follow_up(at, p);
            if (std::abs(std::imag(at) - x) > tolerance) {
                ++p;
                continue;
            }
            cut_level(at, p, x);
        }
        return false;
    }

    bool follow_up(ZX& at, std::size_t& p) {
        if (variant_ == 1) {
            // G71.1: after the first pass, along the shape to the end, no pockets.
            for (; p < path_.size(); ++p) climb_only(path_[p], at, sink_);
            return false;
        }
        for (; p < path_.size(); ++p) {
            if (!climb(path_[p], at, sink_)) continue;
            if (variant_ == 3) {
                if (std::imag(at) > std::imag(pocket_starts_.back()) && pocket_starts_.size() > 1) {
                    pocket_starts_.pop_back();
                }
                if (pocket_starts_.size() == 1) pocket_starts_.push_back(at);
            }
            return !sink_.fault;
        }
        return false;
    }

    //! At level x: a cut along Z to the first element it meets, the retract, the way back.
    void cut_level(ZX at, std::size_t& p, double& x) {
        for (std::size_t ip = p; ip < path_.size(); ++ip) {
            const std::vector<double> is = crossings_at_x(path_[ip], at.imag());
            if (is.empty()) continue;
            // The diving element itself, if an arc, may be met a second time.
            const double to_z = ip != p ? is.front() : is.back();
            const double distance = std::abs(to_z - std::real(at));
            if (to_z - tolerance > std::real(at)) continue;  // met at the starting point only
            if (distance < tolerance) {
                if (p == ip) continue;
                if (std::abs(at - path_[ip].start) < tolerance) {
                    p = ip;  // at the next element's start: go on along it
                } else {
                    x -= delta_;  // an element of no length here
                }
                return;
            }
            ZX to = at;
            to.real(to_z);
            sink_.feed(to);
            const double scale = std::min(1.0, distance / 2 / std::real(escape_));
            sink_.rapid(to + scale * escape_);
            sink_.rapid(at - std::conj(scale * escape_));
            if (p == 0) {
                sink_.rapid(at);
            } else {
                sink_.feed(at);
            }
            x -= delta_;
            return;
        }
        // No element met at this level: LinuxCNC 2.9 tries the same level for ever here.
        sink_.fail(fmt::format("the roughing pass at level {:.4f} meets no element of the profile", at.imag()));
    }

    Path& path_;
    int variant_;
    double delta_;
    ZX escape_;
    MoveSink& sink_;
    std::deque<ZX> pocket_starts_;
};

void rough_passes(Path path, const G7xRequest& q, MoveSink& sink) {
    if (q.cycle == 72) turn_path(path, sink);
    orient(path, sink);
    shape_corners(path, sink);
    require_monotonic(path, sink);
    if (sink.fault) return;
    add_distance(path, q.d, sink);
    if (sink.fault) return;
    for (ProfileSegment& s : path) shift(s, ZX(q.w, q.u));
    sink.rapid(path.front().start);
    if (std::imag(path.back().end) < std::imag(path.front().start)) {
        ProfileSegment rise;
        rise.start = path.back().end;
        rise.end = ZX(std::real(path.back().end), std::imag(path.front().start));
        path.push_back(rise);
    }
    Rougher(path, q.variant, std::max(q.i, 2 * tolerance), q.r, sink).run();
}

}  // namespace

std::optional<std::string> plan_g7x(std::vector<ProfileSegment> profile, const G7xRequest& request,
                                    std::vector<ProfileMove>& moves) {
    if (profile.size() <= 1) return std::nullopt;
    profile.front().start = request.start;
    MoveSink sink;
    sink.out = &moves;
    if (request.cycle == 70) {
        finish_passes(std::move(profile), request, sink);
    } else {
        rough_passes(std::move(profile), request, sink);
    }
    return sink.fault;
}

}  // namespace nckit::interp::ngc
