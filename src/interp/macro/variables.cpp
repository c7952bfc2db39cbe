#include "variables.hpp"

#include "nckit/gcode/macro_alarms.hpp"

namespace nckit::interp {

VariableKind variable_kind(std::int64_t number) {
    if (number == 0) return VariableKind::null;
    if (number >= 1 && number <= 33) return VariableKind::local;
    if (number >= 100 && number <= 499) return VariableKind::common;
    if (number >= first_retained && number <= last_retained) return VariableKind::retained;
    if (number >= 1000) return VariableKind::system;
    return VariableKind::illegal;
}

Variables::Variables() {
    locals_.emplace_back();
}

std::optional<MacroValue> Variables::read(std::int64_t number) const {
    switch (variable_kind(number)) {
        case VariableKind::null:
            return MacroValue{};
        case VariableKind::local:
            return locals_.back()[static_cast<std::size_t>(number)];
        case VariableKind::common:
            return common_[static_cast<std::size_t>(number - 100)];
        case VariableKind::retained:
            return retained_[static_cast<std::size_t>(number - first_retained)];
        case VariableKind::system:
            return system_ != nullptr ? system_->read_system(number) : std::nullopt;
        case VariableKind::illegal:
            return std::nullopt;
    }
    return std::nullopt;
}

std::optional<Variables::WriteError> Variables::write(std::int64_t number, MacroValue value) {
    switch (variable_kind(number)) {
        case VariableKind::null:
            return WriteError{alarm::protected_variable, "#0 is always vacant and cannot be written"};
        case VariableKind::local:
            locals_.back()[static_cast<std::size_t>(number)] = value;
            return std::nullopt;
        case VariableKind::common:
            common_[static_cast<std::size_t>(number - 100)] = value;
            return std::nullopt;
        case VariableKind::retained:
            retained_[static_cast<std::size_t>(number - first_retained)] = value;
            retained_changed_ = true;
            ++retained_writes_;
            return std::nullopt;
        case VariableKind::system: {
            if (system_ == nullptr) return WriteError{alarm::illegal_variable, "no system variables here"};
            if (value.vacant) {
                return WriteError{alarm::protected_variable, "a system variable cannot be made vacant"};
            }
            if (auto e = system_->write_system(number, value.number)) return WriteError{e->alarm, e->message};
            return std::nullopt;
        }
        case VariableKind::illegal:
            break;
    }
    return WriteError{alarm::illegal_variable, "illegal variable number"};
}

}  // namespace nckit::interp
