// The printed forms of a Move: the text line (4 decimals) and the JSON object.
#include "nckit/interp/move_format.hpp"

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

Move make(decltype(Move::what) what, std::uint32_t line = 3, std::int64_t n = -1) {
    return Move{std::move(what), make_location(nullptr, line, 1), n};
}

std::string text(const Move& move, const MachineConfig& machine = default_mill()) {
    std::string out;
    append_move_text(out, move, machine);
    return out;
}

std::string json(const Move& move, const MachineConfig& machine = default_mill()) {
    std::string out;
    append_move_json(out, move, machine);
    return out;
}

Line rapid_to(const AxisVector& to) {
    Line line;
    line.to = to;
    line.rapid = true;
    return line;
}

//! How one value prints as an X coordinate of a rapid.
std::string x_text(double x) {
    std::string line = text(make(rapid_to(xyz(x, 0, 0))));
    return line.substr(4, line.find(' ', 4) - 4);  // "G0 X<value> Y..."
}

//! What printf's correctly rounded %.4f gives, the reference the fast formatter must match.
std::string printf4(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.4f", value);
    std::string s = buffer;
    return s == "-0.0000" ? "0.0000" : s;
}

// ---- text ---------------------------------------------------------------------------------

TEST(MoveText, RapidAndLinear) {
    EXPECT_EQ(text(make(rapid_to(xyz(1, -2.5, 300)))), "G0 X1.0000 Y-2.5000 Z300.0000");
    Line line;
    line.to = xyz(0.1, 0.02, 0.003);
    line.feed.mm_per_min = 600;
    EXPECT_EQ(text(make(line)), "G1 X0.1000 Y0.0200 Z0.0030 F600.0000");
}

TEST(MoveText, NamesOnlyTheMachinesAxesInCanonicalOrder) {
    AxisVector to = xyz(1, 2, 3);
    to[Axis::A] = 45;
    to[Axis::C] = 7;  // not on either machine
    EXPECT_EQ(text(make(rapid_to(to)), lathe()), "G0 X1.0000 Z3.0000");
    EXPECT_EQ(text(make(rapid_to(to)), mill_with_a()), "G0 X1.0000 Y2.0000 Z3.0000 A45.0000");
}

TEST(MoveText, PerRevolutionFeedIsFR) {
    Line line;
    line.to = xyz(0, 0, -10);
    line.feed = Feed{FeedMode::per_revolution, 200, 0.2};
    EXPECT_EQ(text(make(line), lathe()), "G1 X0.0000 Z-10.0000 FR0.2000");
}

TEST(MoveText, ArcsPrintTheirCentre) {
    Arc arc;
    arc.from = xyz(10, 0, 0);
    arc.to = xyz(0, 10, -1);
    arc.center = xyz(0, 0, 0);
    arc.direction = ArcDirection::counterclockwise;
    arc.feed.mm_per_min = 100;
    EXPECT_EQ(text(make(arc)), "G3 X0.0000 Y10.0000 Z-1.0000 CX0.0000 CY0.0000 CZ0.0000 F100.0000");
    arc.direction = ArcDirection::clockwise;
    arc.center = xyz(5, 0, 2);
    EXPECT_EQ(text(make(arc), lathe()), "G2 X0.0000 Z-1.0000 CX5.0000 CZ2.0000 F100.0000");
}

TEST(MoveText, SyncDwellAndIo) {
    SyncMove sync;
    sync.to = xyz(10, 0, -20);
    sync.feed = Feed{FeedMode::per_revolution, 750, 1.5};
    EXPECT_EQ(text(make(sync), lathe()), "G33 X10.0000 Z-20.0000 FR1.5000");
    EXPECT_EQ(text(make(Dwell{1.5})), "G4 P1.5000");
    EXPECT_EQ(text(make(Io{IoKind::mcode, 30, 0})), "M30");
    EXPECT_EQ(text(make(Io{IoKind::tool_select, 12, 0})), "T12");
    EXPECT_EQ(text(make(Io{IoKind::spindle_speed, 0, 1200})), "S1200");
    EXPECT_EQ(text(make(Io{IoKind::spindle_speed, 0, 30.48})), "S30.48");
}

TEST(MoveText, FourDecimalsRoundedToNearest) {
    EXPECT_EQ(x_text(1.23454), "1.2345");
    EXPECT_EQ(x_text(1.23456), "1.2346");
    EXPECT_EQ(x_text(-1.23456), "-1.2346");
    EXPECT_EQ(x_text(0.99999), "1.0000");
    EXPECT_EQ(x_text(-9.99996), "-10.0000");
}

TEST(MoveText, HalfwayValuesRoundAsTheirExactBinaryValue) {
    // 1.00005 is stored a little above ...05, 2.00005 a little below: printf rounds them apart.
    EXPECT_EQ(x_text(1.00005), "1.0001");
    EXPECT_EQ(x_text(-2.34565), "-2.3457");
    EXPECT_EQ(x_text(2.00005), "2.0000");
    EXPECT_EQ(x_text(-2.00005), "-2.0000");
    EXPECT_EQ(x_text(123456789.12345), "123456789.1234");
}

TEST(MoveText, NoNegativeZero) {
    EXPECT_EQ(x_text(-0.0), "0.0000");
    EXPECT_EQ(x_text(-0.00001), "0.0000");
    EXPECT_EQ(x_text(-0.0000499), "0.0000");
    EXPECT_EQ(x_text(-0.00005), "-0.0001");
    EXPECT_EQ(x_text(-1e-300), "0.0000");
}

TEST(MoveText, BigValues) {
    EXPECT_EQ(x_text(123456789.5), "123456789.5000");
    EXPECT_EQ(x_text(-987654321.0625), "-987654321.0625");
    EXPECT_EQ(x_text(12345678901234.5), "12345678901234.5000");
    EXPECT_EQ(x_text(-1e15), "-1000000000000000.0000");
    EXPECT_EQ(x_text(1e20), "100000000000000000000.0000");
}

TEST(MoveText, MatchesPrintfOnRandomValues) {
    std::mt19937_64 random(20240611);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> magnitude(-6, 14);
    std::uniform_int_distribution<long long> ten_thousandths(-99999999, 99999999);
    for (int i = 0; i < 100000; ++i) {
        double value = unit(random) * std::pow(10.0, magnitude(random));
        ASSERT_EQ(x_text(value), printf4(value)) << std::hexfloat << value;
        // Values on or next to a 0.00005 boundary, where rounding is decided.
        double halfway = (static_cast<double>(ten_thousandths(random)) + 0.5) / 1e4;
        ASSERT_EQ(x_text(halfway), printf4(halfway)) << std::hexfloat << halfway;
        double next = std::nextafter(halfway, 0.0);
        ASSERT_EQ(x_text(next), printf4(next)) << std::hexfloat << next;
    }
}

// ---- JSON ---------------------------------------------------------------------------------

TEST(MoveJson, LinearWithEveryKey) {
    Line line;
    line.from = xyz(0, -0.0, 0);
    line.to = xyz(1.5, 2, -0.25);
    line.feed.mm_per_min = 600;
    line.path.exact_stop = true;
    EXPECT_EQ(json(make(line, 7, 10)), R"({"line":7,"n":10,"kind":"linear","start":{"X":0,"Y":0,"Z":0},)"
                                       R"("end":{"X":1.5,"Y":2,"Z":-0.25},"feed_mm_min":600,"exact_stop":true})");
}

TEST(MoveJson, RapidHasNoFeed) {
    EXPECT_EQ(json(make(rapid_to(xyz(1, 2, 3))), lathe()),
              R"({"line":3,"kind":"rapid","start":{"X":0,"Z":0},"end":{"X":1,"Z":3}})");
}

TEST(MoveJson, ArcKeys) {
    Arc arc;
    arc.from = xyz(10, 0, 0);
    arc.to = xyz(0, 10, 0);
    arc.center = xyz(0, 0, 0);
    arc.center[Axis::A] = 5;  // the centre names linear axes only
    arc.direction = ArcDirection::counterclockwise;
    arc.plane = Plane::zx;
    arc.feed = Feed{FeedMode::per_revolution, 40, 0.1};
    nlohmann::json j = nlohmann::json::parse(json(make(arc), mill_with_a()));
    EXPECT_EQ(j["kind"], "arc");
    EXPECT_EQ(j["line"], 3);
    EXPECT_FALSE(j.contains("n"));
    EXPECT_EQ(j["end"], (nlohmann::json{{"X", 0}, {"Y", 10}, {"Z", 0}, {"A", 0}}));
    EXPECT_EQ(j["center"], (nlohmann::json{{"X", 0}, {"Y", 0}, {"Z", 0}}));
    EXPECT_EQ(j["dir"], "ccw");
    EXPECT_EQ(j["plane"], "zx");
    EXPECT_EQ(j["turns"], 0);
    EXPECT_EQ(j["feed_mm_min"], 40);
    EXPECT_EQ(j["feed_mm_rev"], 0.1);
    EXPECT_FALSE(j.contains("exact_stop"));
    arc.direction = ArcDirection::clockwise;
    EXPECT_EQ(nlohmann::json::parse(json(make(arc)))["dir"], "cw");
}

TEST(MoveJson, SyncAndDwell) {
    SyncMove sync;
    sync.to = xyz(0, 0, -20);
    sync.feed = Feed{FeedMode::per_revolution, 750, 1.5};
    EXPECT_EQ(json(make(sync), lathe()), R"({"line":3,"kind":"sync","start":{"X":0,"Z":0},"end":{"X":0,"Z":-20},)"
                                         R"("feed_mm_min":750,"feed_mm_rev":1.5})");
    EXPECT_EQ(json(make(Dwell{0.25})), R"({"line":3,"kind":"dwell","seconds":0.25})");
}

TEST(MoveJson, IoCodes) {
    Io m3{IoKind::mcode, 3, 1200};
    EXPECT_EQ(json(make(m3)), R"({"line":3,"kind":"io","code":"M3","rpm":1200})");
    Io css{IoKind::spindle_speed, 0, 200};
    css.constant_surface_speed = true;
    css.rpm_clamp = 1500;
    EXPECT_EQ(json(make(css)), R"({"line":3,"kind":"io","code":"S","surface_speed_m_min":200,"rpm_clamp":1500})");
    Io m6{IoKind::mcode, 6, 0};
    m6.waits = true;
    EXPECT_EQ(json(make(m6)), R"({"line":3,"kind":"io","code":"M6","waits":true})");
    EXPECT_EQ(json(make(Io{IoKind::tool_select, 4, 0})), R"({"line":3,"kind":"io","code":"T4"})");
}

TEST(MoveJson, FullPrecisionAndNoNegativeZero) {
    nlohmann::json j = nlohmann::json::parse(json(make(rapid_to(xyz(0.1 + 0.2, -0.0, 1e-7)))));
    EXPECT_EQ(j["end"]["X"].get<double>(), 0.1 + 0.2);
    EXPECT_EQ(j["end"]["Z"].get<double>(), 1e-7);
    EXPECT_EQ(json(make(rapid_to(xyz(0, -0.0, 0)))).find("-0"), std::string::npos);
}

TEST(MoveJson, EveryMoveOfAProgramIsValidJson) {
    const MachineConfig m = default_mill();
    for (const Move& move : moves_of("N1 G0 X1\nS100 M3 M8 T1 M6\nG1 X2 F100\nG2 X4 I1\nG4 P10\nG33 Z-1 K1\nM30\n")) {
        nlohmann::json j = nlohmann::json::parse(json(move, m));
        EXPECT_TRUE(j.contains("line"));
        EXPECT_TRUE(j.contains("kind"));
    }
}

}  // namespace
}  // namespace nckit::test
