#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nckit/core/axes.hpp"
#include "nckit/core/result.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/core/tool_table.hpp"

namespace nckit {

enum class AxisKind { linear, rotary };

//! How a number without a decimal point in an axis word is read.
enum class DecimalPointInput {
    calculator,      //!< `X10` is 10 mm (Fanuc parameter DPI = 1; LinuxCNC's only reading)
    least_increment  //!< `X10` is 10 least input increments: 0.010 mm (Fanuc's default)
};

enum class ProfileKind { scurve, trapezoid };

//! The winding sequence a stepper drive writes to its port (docs/drives.md); `none` for
//! a step/direction driver, which sequences the windings itself.
enum class PhaseTableKind {
    none,
    three_phase_six_beat,    //!< A, AB, B, BC, C, CA (the seed's half-step table)
    three_phase_three_beat,  //!< A, B, C
    two_phase_full_step,     //!< AB, BC, CD, DA
    two_phase_half_step      //!< A, AB, B, BC, C, CD, D, DA
};

//! The config spelling of each PhaseTableKind, indexed by the enum's value.
inline constexpr std::array<std::string_view, 5> phase_table_names{"none", "3phase-6beat", "3phase-3beat",
                                                                   "2phase-full", "2phase-half"};

//! A servo axis's closed position loop as the second-order model
//! gain / (T^2 s^2 + 2 damping T s + 1), T = 1 / (2 pi natural_frequency_hz).
struct AxisServoConfig {
    double natural_frequency_hz = 0;  //!< Hz, the loop's undamped natural frequency
    double damping = 0;               //!< zeta, dimensionless, >= 0
    double gain = 1.0;                //!< position out per setpoint in (DC gain), dimensionless
};

struct AxisConfig {
    Axis axis = Axis::X;
    AxisKind kind = AxisKind::linear;
    double max_velocity = 0;               //!< mm/s (deg/s for rotary)
    double max_acceleration = 0;           //!< mm/s^2 (deg/s^2)
    double max_jerk = 0;                   //!< mm/s^3 (deg/s^3)
    double min = 0;                        //!< travel limit, machine coordinates, mm (deg)
    double max = 0;                        //!< travel limit, machine coordinates, mm (deg)
    double steps_per_unit = 0;             //!< motor steps per mm (deg)
    double backlash = 0;                   //!< mm (deg) lost on each reversal
    double backlash_rate_steps_s = 20000;  //!< steps/s at which a reversal's backlash is taken up
    double home = 0;                       //!< reference point G28 returns to, machine coordinates
    //! Where M6 takes this axis (rapid, machine coordinates) before the change; none: it stays.
    std::optional<double> tool_change;
    PhaseTableKind phase_table = PhaseTableKind::none;  //!< windings sequenced by the drive
    bool port_active_low = false;                       //!< phase-table port: winding bits inverted (sinking drivers)
    std::uint8_t port_set_bits = 0;                     //!< phase-table port: bits always written high (e.g. enable)
    std::optional<AxisServoConfig> servo;  //!< a servo axis's position loop ([axis.servo]); none: open loop
};

struct SpindleConfig {
    double max_rpm = 0;      //!< rpm
    int encoder_counts = 0;  //!< counts per spindle turn; the index pulse comes at angle 0
    //! Speed ripple the drive leaves, repeating with the angle: n = rpm·(1 + fraction·
    //! sin(per_turn·θ + phase)). 0 for an ideal spindle.
    double ripple_fraction = 0;
    int ripple_per_turn = 1;      //!< cycles of the ripple per spindle turn
    double ripple_phase_deg = 0;  //!< deg, the ripple's phase at the index
};

//! Fanuc's cutter compensation start-up types (parameter SUP): where the start-up block ends on
//! an outside corner.
enum class CompStartup {
    type_b,  //!< r perpendicular to the start-up block, then the corner as between any two blocks
    type_a   //!< r perpendicular to the next block's start: no path around the corner
};

//! A Fanuc lathe's G-code system (docs/gcode-lathe.md has the table). `none`: the mill codes
//! (and LinuxCNC's lathe codes), as for every machine without the key.
enum class GCodeSystem { none, a, b, c };
//! Whose lathe control a system-A lathe is (docs/gcode-lathe.md, "Haas lathes"): where Haas reads
//! a block differently from Fanuc, nckit follows the machine's maker.
enum class LatheControl {
    fanuc,  //!< Fanuc 0i-T and compatible (the default)
    haas    //!< Haas lathe: G70 reads G71's U W D I K copied onto it and does not use them
};
//! Which G-code dialect programs are read in (docs/gcode-linuxcnc.md lists the differences).
enum class Dialect {
    fanuc,    //!< Fanuc with Custom Macro B (the default)
    linuxcnc  //!< LinuxCNC's RS-274/NGC: O-word subroutines and control flow, named parameters
};

//! A surface G31's skip signal fires on: the plane where one axis stands at `at_mm` (machine
//! coordinates, mm or deg), as a touch probe or tool setter meets the part there.
struct ProbeSurface {
    Axis axis = Axis::Z;
    double at_mm = 0;
};

//! A Custom Macro B input (#1000-#1199) and the value it reads in a run.
struct MacroInput {
    int number = 0;
    double value = 0;
};

struct MachineConfig {
    std::string name;
    Dialect dialect = Dialect::fanuc;  //!< `dialect = "linuxcnc"`; `--dialect` overrides it
    //! `subroutine_path = ["DIR", ...]`: where a LinuxCNC `o<name> call` finds NAME.ngc (after
    //! `--library`), relative to the machine file.
    std::vector<std::filesystem::path> subroutine_path;
    double servo_period_s = 0.001;       //!< s, trajectory sampling period
    bool diameter_mode = false;          //!< lathe: X words are diameters, Moves carry radii
    std::vector<int> exact_stop_mcodes;  //!< M-codes that need the axes at rest
    //! M-codes that switch a cutting beam on / off (laser notching). A code in both this and
    //! exact_stop_mcodes switches at rest; one that is not an exact stop switches where the path
    //! passes it, at speed (the planner places a non-waiting I/O event by position).
    std::vector<int> laser_on_mcodes;
    std::vector<int> laser_off_mcodes;
    DecimalPointInput decimal_point_input = DecimalPointInput::calculator;
    ProfileKind profile = ProfileKind::scurve;
    CompStartup cutter_comp_startup = CompStartup::type_b;  //!< `cutter_comp_startup = "type_a"`
    GCodeSystem gcode_system = GCodeSystem::none;           //!< `gcode_system = "A"` (lathes only)
    LatheControl lathe_control = LatheControl::fanuc;       //!< `lathe_control = "haas"` (system A only)
    //! G codes in force at power-up (`startup_gcodes = "G18 G21 G40 G97 G99"`), read in the
    //! machine's G-code system before the program's first block; empty: none beyond the defaults.
    std::string startup_gcodes;
    SourceLocation startup_gcodes_at;  //!< where the key's value stands, for its errors
    std::vector<AxisConfig> axes;      //!< in the order the config lists them
    SpindleConfig spindle;
    //! The tool table (`tools = "FILE"` in [machine], or `--tools FILE`); empty when none given.
    ToolTable tools;
    std::string tools_file;  //!< where `tools` came from; empty for none
    //! `[probe] surfaces`: where G31 skips; empty: a G31 never meets anything (an error).
    std::vector<ProbeSurface> probe_surfaces;
    //! `restart_safe_mm`: where `nckit restart` retracts the tool before its approach, a machine
    //! coordinate of the retract axis (Z; X on a lathe); unset: that axis's `max` travel limit.
    std::optional<double> restart_safe_mm;
    //! `restart_feed_mm_min`: feed of the restart approach's last move onto the restart point.
    double restart_feed_mm_min = 100;
    //! `[inputs]`: #1000-#1199 that read a value other than 0.
    std::vector<MacroInput> macro_inputs;

    //! The configured axis, or null when the machine has no such axis.
    [[nodiscard]] const AxisConfig* find(Axis axis) const;
    [[nodiscard]] AxisSet axis_set() const;
    [[nodiscard]] bool is_exact_stop_mcode(int code) const;
    [[nodiscard]] bool is_laser_on_mcode(int code) const;
    [[nodiscard]] bool is_laser_off_mcode(int code) const;
};

//! The built-in 3-axis mill used when no `--machine` is given.
[[nodiscard]] MachineConfig default_mill();

//! Parses and validates a machine config; every error carries FILE:LINE:COL.
[[nodiscard]] Result<MachineConfig> parse_machine_config(std::string_view toml_text, const std::string& file_name);
[[nodiscard]] Result<MachineConfig> load_machine_config(const std::filesystem::path& path);

}  // namespace nckit
