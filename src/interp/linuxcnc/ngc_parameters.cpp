#include "ngc_parameters.hpp"

namespace nckit::interp::ngc {

double NgcParameters::read(std::int64_t n) const {
    if (live_.numbered) {
        if (std::optional<double> v = live_.numbered(n)) return *v;
    }
    return values_[static_cast<std::size_t>(n)];
}

std::optional<double> NgcParameters::read_named(const std::string& name) const {
    if (name == "_value") return return_value_;
    if (name == "_value_returned") return value_returned_ ? 1.0 : 0.0;
    if (!name.empty() && name[0] == '_') {
        if (auto it = globals_.find(name); it != globals_.end()) return it->second;
        if (live_.named) return live_.named(name);
        return std::nullopt;
    }
    const auto& locals = frames_.back().locals;
    if (auto it = locals.find(name); it != locals.end()) return it->second;
    return std::nullopt;
}

bool NgcParameters::write_named(const std::string& name, double value) {
    if (!name.empty() && name[0] == '_') {
        // A predefined name is read-only; a global the program made is not.
        if (!globals_.contains(name) &&
            (name == "_value" || name == "_value_returned" || (live_.named && live_.named(name).has_value()))) {
            return false;
        }
        globals_[name] = value;
        return true;
    }
    frames_.back().locals[name] = value;
    return true;
}

void NgcParameters::enter_call(const std::vector<double>& arguments) {
    Frame frame;
    for (std::size_t i = 0; i < call_arguments; ++i) {
        frame.saved[i] = values_[i + 1];
        values_[i + 1] = i < arguments.size() ? arguments[i] : 0.0;
    }
    frames_.push_back(std::move(frame));
}

void NgcParameters::leave_call() {
    if (frames_.size() <= 1) return;
    const Frame& frame = frames_.back();
    if (!frame.shares_numbered) {
        for (std::size_t i = 0; i < call_arguments; ++i) values_[i + 1] = frame.saved[i];
    }
    frames_.pop_back();
}

}  // namespace nckit::interp::ngc
