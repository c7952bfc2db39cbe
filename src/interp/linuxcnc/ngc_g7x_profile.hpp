#pragma once
// LinuxCNC 2.9's lathe cycles G70 (finishing), G71 (roughing along Z) and G72 (roughing along
// X, "facing"): the finished shape (the profile, read from an O-word subroutine) as a chain of
// lines and arcs in the ZX plane, each point a complex number z + i*x, and the passes cut along
// it. The pass rules are LinuxCNC's own (docs/dialects.md, "LinuxCNC's lathe cycles"): the
// profile is turned and mirrored until it runs towards -Z and -X, offset by the finishing
// allowance in steps no larger than half its shortest element, and roughed level by level
// from the start point, pockets included, so that the moves equal those of LinuxCNC.
#include <complex>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace nckit::interp::ngc {

using ZX = std::complex<double>;  //!< a point of the ZX plane: real part Z, imaginary part X

//! A corner finish that waits for its neighbours to be known (A: fillet radius, C: chamfer).
enum class CornerFinish { none, fillet, chamfer };

//! One element of the profile, a line or an arc (centre, direction), start to end.
struct ProfileSegment {
    bool arc = false;
    bool ccw = false;  //!< G3 as seen in the turned and mirrored frame
    ZX start;
    ZX end;
    ZX center;
    CornerFinish corner = CornerFinish::none;
    double finish = 0;  //!< the corner finish's size while it is still to be shaped, else 0
};

//! One move of a cycle, in the program's own ZX frame.
struct ProfileMove {
    enum class Kind { rapid, feed, arc };
    Kind kind = Kind::rapid;
    ZX end;
    ZX center;
    bool ccw = false;
    bool comp_off = false;  //!< G70's approach: made with cutter compensation off
};

//! What a G70/G71/G72 block asks for (LinuxCNC's words and defaults).
struct G7xRequest {
    int cycle = 71;     //!< 70, 71 or 72
    int variant = 0;    //!< 0 (G71), 1 (G71.1: no pockets), 2 (G71.2: pockets only)
    ZX start;           //!< Z and X of the block: where the passes start from
    double d = 0;       //!< finishing allowance (G70: of the first pass)
    double e = 0;       //!< G70: allowance of the last pass
    double i = 1;       //!< depth of cut
    double r = 0.5;     //!< retract distance
    double u = 0;       //!< shift of the roughed shape in X
    double w = 0;       //!< shift in Z
    double passes = 1;  //!< G70 P: its whole part passes; the allowance steps by (D - E) / P
};

//! The moves of one cycle over `profile` (its first element runs from the start point), or the
//! reason LinuxCNC refuses the shape.
[[nodiscard]] std::optional<std::string> plan_g7x(std::vector<ProfileSegment> profile, const G7xRequest& request,
                                                  std::vector<ProfileMove>& moves);

namespace g7x_detail {

constexpr double tolerance = 1e-6;  //!< LinuxCNC's closeness for points on the profile

//! Collects a cycle's moves, turned back from the working frame into the program's, and the
//! first fault the geometry meets.
struct MoveSink {
    int flips = 0;  //!< bit 0: Z mirrored, bit 1: X mirrored, bit 2: turned by 90 degrees
    std::vector<ProfileMove>* out = nullptr;
    std::optional<std::string> fault;
    std::uint64_t steps = 0;  //!< bounds the pass search (and the moves it makes)

    void rapid(ZX end, bool comp_off = false);
    void feed(ZX end);
    void arc(bool ccw, ZX center, ZX end);
    void fail(std::string message) {
        if (!fault) fault = std::move(message);
    }
};

double length_scale(const ProfileSegment& s);  //!< LinuxCNC's "radius" of an element
bool monotonic(const ProfileSegment& s);
void offset(ProfileSegment& s, double distance);
void shift(ProfileSegment& s, ZX by);
void mirror_x(ProfileSegment& s);
void mirror_z(ProfileSegment& s);
void turn(ProfileSegment& s);
std::vector<double> crossings_at_x(const ProfileSegment& s, double x);
//! Moves p's end and n's start to where the two meet.
void meet(ProfileSegment& p, ProfileSegment& n, MoveSink& sink);
void draw(const ProfileSegment& s, MoveSink& sink);
bool climb(const ProfileSegment& s, ZX& at, MoveSink& sink);
void climb_only(const ProfileSegment& s, ZX& at, MoveSink& sink);
bool dive(const ProfileSegment& s, ZX& at, double x, MoveSink& sink, bool fast);
//! Shapes a fillet or chamfer between its neighbours.
void shape_corner(ProfileSegment& corner, ProfileSegment& prev, ProfileSegment& next, MoveSink& sink);

}  // namespace g7x_detail

}  // namespace nckit::interp::ngc
