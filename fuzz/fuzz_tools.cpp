// Tool tables: the first byte picks the reader (even: TOML, odd: LinuxCNC's tool.tbl, read in
// inch when bit 1 is set too); the rest is the file. Every input is a table whose rows are
// finite and in range, or FILE:LINE:COL diagnostics; never a crash.
#include <cmath>

#include "fuzz_support.hpp"
#include "nckit/core/tool_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
    using namespace nckit;
    if (size < 1 || size > 64 * 1024) return 0;
    const unsigned kind = data[0];
    const std::string_view text = fuzz::text_of(data + 1, size - 1);
    Result<ToolTable> table =
        (kind & 1) == 0 ? parse_tool_toml(text, "fuzz.toml") : parse_tool_tbl(text, "fuzz.tbl", (kind & 2) != 0);
    if (!table) {
        fuzz::require(!table.diagnostics().empty(), "a refused tool table without a diagnostic");
        for (const Diagnostic& d : table.diagnostics()) {
            fuzz::require(!d.message.empty(), "a diagnostic without a message");
        }
        return 0;
    }
    for (const auto& [number, tool] : table->rows()) {
        fuzz::require(number == tool.number, "a row filed under another number");
        fuzz::require(number >= 0 && number <= max_tool_number, "a tool number out of range");
        fuzz::require(tool.pocket >= 0, "a negative pocket");
        fuzz::require(tool.orientation >= 0 && tool.orientation <= 9, "a tip orientation out of 0..9");
        for (double value : {tool.length_mm, tool.length_wear_mm, tool.radius_mm, tool.radius_wear_mm, tool.x_offset_mm,
                             tool.front_angle_deg, tool.back_angle_deg}) {
            fuzz::require(std::isfinite(value), "a tool value that is not finite");
        }
        fuzz::require(tool.radius_mm >= 0, "a negative tool radius");
        const std::optional<double> radius = table->radius_mm(number);
        const std::optional<double> length = table->length_mm(number);
        fuzz::require(radius && std::isfinite(*radius) && length && std::isfinite(*length),
                      "a row's offsets cannot be looked up");
    }
    return 0;
}
