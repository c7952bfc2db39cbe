#pragma once
// The machine's tool table: for each tool (or offset) number its length, radius and their wear,
// and the lathe columns (X/Z offsets, nose radius, tip orientation). H words look up lengths and
// D words radii by the same numbers, as LinuxCNC does and as a Fanuc control with one offset per
// tool number does. Read from a TOML tool file or LinuxCNC's `tool.tbl` as it is.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "nckit/core/result.hpp"

namespace nckit {

//! One row of the table. Every length is mm, angles deg; internal units whatever the file used.
struct ToolEntry {
    int number = 0;              //!< T number, also the H and D number that reads this row
    int pocket = 0;              //!< tool changer pocket (LinuxCNC's P); 0 = unknown
    double length_mm = 0;        //!< geometry length offset (H; LinuxCNC's Z column)
    double length_wear_mm = 0;   //!< added to the length when H is applied
    double radius_mm = 0;        //!< geometry radius (D; tool.tbl's D column is a diameter)
    double radius_wear_mm = 0;   //!< added to the radius when D is applied
    double x_offset_mm = 0;      //!< lathe: X offset (radius value); its Z offset is length_mm
    double x_wear_mm = 0;        //!< lathe: X wear (radius value), added to x_offset_mm
    int orientation = 0;         //!< lathe: tip orientation 0..9 (LinuxCNC's Q)
    double front_angle_deg = 0;  //!< lathe: LinuxCNC's I
    double back_angle_deg = 0;   //!< lathe: LinuxCNC's J
    std::string comment;

    //! What G43 H applies: geometry plus wear.
    [[nodiscard]] double total_length_mm() const { return length_mm + length_wear_mm; }
    //! What G41/G42 D applies: geometry plus wear.
    [[nodiscard]] double total_radius_mm() const { return radius_mm + radius_wear_mm; }
    //! A lathe's nose radius: the same column as a mill tool's radius.
    [[nodiscard]] double nose_radius_mm() const { return radius_mm; }
};

//! Tool numbers run 0..max_tool_number (T0 / H0 / D0 mean "no tool" and "no offset").
inline constexpr int max_tool_number = 99999999;
//! Offsets, radii and wear beyond ±100 m are typing errors, not tools; the bound also keeps
//! geometry plus wear (and an inch table's ×25.4) finite.
inline constexpr double max_tool_value_mm = 100000.0;

class ToolTable {
public:
    //! The row of `number`, or null when the table has none.
    [[nodiscard]] const ToolEntry* find(int number) const;
    //! The row of `number`, created empty when missing (G10 L1/L10-L13 write rows in a run).
    ToolEntry& entry(int number);
    void insert(ToolEntry entry) { rows_[entry.number] = std::move(entry); }

    //! Radius compensation value of offset D (geometry + wear, mm); D0 is 0, an unknown D nothing.
    [[nodiscard]] std::optional<double> radius_mm(int d_number) const;
    //! Tool length offset of H (geometry + wear, mm); H0 is 0, an unknown H nothing.
    [[nodiscard]] std::optional<double> length_mm(int h_number) const;

    [[nodiscard]] bool empty() const { return rows_.empty(); }
    [[nodiscard]] std::size_t size() const { return rows_.size(); }
    [[nodiscard]] const std::map<int, ToolEntry>& rows() const { return rows_; }

private:
    std::map<int, ToolEntry> rows_;
};

//! Reads a TOML tool file (`[[tool]]` tables; see docs/gcode-mill.md). Errors carry FILE:LINE:COL.
[[nodiscard]] Result<ToolTable> parse_tool_toml(std::string_view text, const std::string& file_name);
//! Reads LinuxCNC's tool.tbl (`T1 P1 Z12.5 D6 ;comment`); values in mm unless `inch_values`.
[[nodiscard]] Result<ToolTable> parse_tool_tbl(std::string_view text, const std::string& file_name,
                                               bool inch_values = false);
//! Loads a tool file: `.toml` as TOML, anything else as LinuxCNC's tool.tbl.
[[nodiscard]] Result<ToolTable> load_tool_table(const std::filesystem::path& path);

}  // namespace nckit
