// `nckit piston --json` as a library value: every key of the contract, in its place, with the
// number it reports; a missing rpm limit is null.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "nckit/process/piston/piston_json.hpp"

namespace nckit {
namespace {

PistonSimulation distinct_values() {
    PistonSimulation s;
    s.parameters.rpm = 1500.5;
    s.parameters.encoder_counts = 4096;
    s.parameters.servo.model_error = 0.05;
    s.parameters.ripple.fraction = 0.002;
    s.parameters.servo.natural_frequency_hz = 800;
    s.parameters.servo.damping = 0.7;
    s.parameters.servo.stroke_mm = 0.6;
    s.parameters.servo.dac_bits = 16;
    s.parameters.air_turns = 20;
    s.parameters.learning.harmonics = 40;
    s.parameters.learning.gain = 0.5;
    s.parameters.z_start_mm = -3;
    s.parameters.z_end_mm = 45;
    s.parameters.feed_mm_rev = 0.2;
    const auto run = [](FtsRunResult& r, double pv_um, double rms_um, double peak_command_mm) {
        r.pv_um = pv_um;
        r.rms_um = rms_um;
        r.peak_command_mm = peak_command_mm;
    };
    run(s.fts.uncompensated, 12.5, 4.25, 0.31);
    run(s.fts.feedforward, 1.5, 0.5, 0.32);
    run(s.fts.learning, 0.125, 0.0625, 0.33);
    s.fts.tick_rate_hz = 102400.0;
    s.fts.dac_step_mm = 0.6 / 65536;
    s.fts.learning_contraction.any_frequency = 0.9;
    s.fts.learning_contraction.learned_harmonics = 0.6;
    s.fts.ticks = 123456;
    s.fts.cut_ticks = 100000;
    s.fts.duration_s = 9.6;
    s.table_theta_cells = 360;
    s.table_z_cells = 48;
    s.table_bytes = 1 << 20;
    s.table_error_bound_mm = 1e-7;
    s.table_tolerance_mm = 5e-7;
    s.fit = StrokeFit{0.25, 90, 12, 0.3};
    s.acceleration_mm_s2 = 3000;
    s.acceleration_limit_mm_s2 = 9806.65;
    s.max_rpm = 2700.25;
    s.settled_turn = 7;
    return s;
}

std::vector<std::string> keys_of(const nlohmann::ordered_json& object) {
    std::vector<std::string> out;
    for (const auto& [key, value] : object.items()) out.push_back(key);
    return out;
}

TEST(PistonJson, EveryKeyOfTheContractInItsOrder) {
    const nlohmann::ordered_json j = to_json(distinct_values());
    EXPECT_EQ(keys_of(j),
              (std::vector<std::string>{"profile_error_um", "rpm", "encoder_counts", "tick_rate_hz", "dac_step_mm",
                                        "model_error", "spindle_ripple", "servo", "cam_table", "learning",
                                        "servo_demand", "z_mm", "feed_mm_rev", "ticks", "cut_ticks", "duration_s"}));
    EXPECT_EQ(keys_of(j["servo"]),
              (std::vector<std::string>{"natural_frequency_hz", "damping", "stroke_mm", "dac_bits"}));
    EXPECT_EQ(keys_of(j["cam_table"]),
              (std::vector<std::string>{"theta_cells", "z_cells", "cells", "bytes", "error_bound_mm", "tolerance_mm"}));
    EXPECT_EQ(keys_of(j["learning"]),
              (std::vector<std::string>{"settled_turn", "settle_limit_um", "air_turns", "harmonics", "gain",
                                        "contraction", "contraction_learned"}));
    EXPECT_EQ(keys_of(j["servo_demand"]),
              (std::vector<std::string>{"peak_displacement_mm", "displacement_limit_mm", "peak_displacement_theta_deg",
                                        "peak_displacement_z_mm", "peak_command_mm", "acceleration_mm_s2",
                                        "acceleration_limit_mm_s2", "max_rpm"}));
    EXPECT_EQ(keys_of(j["z_mm"]), (std::vector<std::string>{"from", "to"}));
    for (const char* run : {"uncompensated", "feedforward", "learning"}) {
        EXPECT_EQ(keys_of(j["profile_error_um"][run]), (std::vector<std::string>{"pv", "rms"})) << run;
    }
}

TEST(PistonJson, TheNumbersAreTheSimulationsOwn) {
    const PistonSimulation s = distinct_values();
    const nlohmann::ordered_json j = to_json(s);
    EXPECT_EQ(j["profile_error_um"]["uncompensated"]["pv"].get<double>(), 12.5);
    EXPECT_EQ(j["profile_error_um"]["learning"]["rms"].get<double>(), 0.0625);
    EXPECT_EQ(j["rpm"].get<double>(), 1500.5);
    EXPECT_EQ(j["encoder_counts"].get<int>(), 4096);
    EXPECT_EQ(j["cam_table"]["cells"].get<std::size_t>(), 360U * 48U);
    EXPECT_EQ(j["learning"]["settled_turn"].get<int>(), 7);
    EXPECT_EQ(j["learning"]["settle_limit_um"].get<double>(), PistonRunOptions{}.settle_limit_um);
    EXPECT_EQ(j["servo_demand"]["peak_command_mm"]["feedforward"].get<double>(), 0.32);
    EXPECT_EQ(j["servo_demand"]["peak_displacement_theta_deg"].get<double>(), 90.0);
    EXPECT_EQ(j["servo_demand"]["max_rpm"].get<double>(), 2700.25);
    EXPECT_EQ(j["z_mm"]["from"].get<double>(), -3.0);
    EXPECT_EQ(j["ticks"].get<std::int64_t>(), 123456);
    // Printed and read back, the report is the same value (what a user's parser sees).
    EXPECT_EQ(nlohmann::ordered_json::parse(j.dump()), j);
}

TEST(PistonJson, NoRpmLimitIsNull) {
    PistonSimulation s = distinct_values();
    s.max_rpm = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(to_json(s)["servo_demand"]["max_rpm"].is_null());
}

}  // namespace
}  // namespace nckit
