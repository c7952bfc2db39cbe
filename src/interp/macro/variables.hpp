#pragma once
// Macro B variables: #0 (always vacant), locals #1-#33 (a fresh set per macro call), common
// #100-#499 (cleared when a run starts), retained #500-#999 (kept across runs in a file), and
// system variables #1000 and up, which belong to the interpreter and are reached through
// SystemVariables.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "macro_value.hpp"

namespace nckit::interp {

//! What a variable number names.
enum class VariableKind { null, local, common, retained, system, illegal };
[[nodiscard]] VariableKind variable_kind(std::int64_t number);

inline constexpr int first_retained = 500;
inline constexpr int last_retained = 999;
inline constexpr std::size_t retained_count = last_retained - first_retained + 1;
using RetainedValues = std::array<MacroValue, retained_count>;

//! The interpreter's side of the system variables (#1000 and up).
class SystemVariables {
public:
    virtual ~SystemVariables() = default;
    //! The value, or nothing when no such system variable exists.
    [[nodiscard]] virtual std::optional<MacroValue> read_system(std::int64_t number) const = 0;
    //! Empty on success; otherwise why not ("read-only", "no such variable", an alarm text).
    struct WriteError {
        int alarm = 0;
        std::string message;
    };
    [[nodiscard]] virtual std::optional<WriteError> write_system(std::int64_t number, double value) = 0;
};

class Variables {
public:
    static constexpr std::size_t local_count = 34;  // #0..#33; #0 is unused here
    using Locals = std::array<MacroValue, local_count>;

    Variables();

    void set_system(SystemVariables* system) { system_ = system; }
    void set_retained(const RetainedValues& values) { retained_ = values; }
    [[nodiscard]] const RetainedValues& retained() const { return retained_; }
    [[nodiscard]] bool retained_changed() const { return retained_changed_; }
    //! Counts writes to #500-#999: a run journal records the values only when this moves.
    [[nodiscard]] std::uint64_t retained_writes() const { return retained_writes_; }

    //! Reads a variable; nothing when the number names no variable.
    [[nodiscard]] std::optional<MacroValue> read(std::int64_t number) const;

    struct WriteError {
        int alarm = 0;
        std::string message;
    };
    [[nodiscard]] std::optional<WriteError> write(std::int64_t number, MacroValue value);

    //! A macro call (G65/G66) gets its own locals; a subprogram (M98) shares its caller's.
    void push_locals(const Locals& arguments) { locals_.push_back(arguments); }
    void pop_locals() { locals_.pop_back(); }
    [[nodiscard]] std::size_t local_levels() const { return locals_.size(); }

private:
    std::vector<Locals> locals_;            // back() is the running level; level 0 is the main program
    std::array<MacroValue, 400> common_{};  // #100..#499
    RetainedValues retained_{};
    bool retained_changed_ = false;
    std::uint64_t retained_writes_ = 0;
    SystemVariables* system_ = nullptr;
};

}  // namespace nckit::interp
