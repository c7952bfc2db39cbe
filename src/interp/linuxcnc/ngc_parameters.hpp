#pragma once
// LinuxCNC's parameters: numbered #1-#5601 (unset ones read 0; #1-#30 are saved and restored
// around every O-word call), named ones local to a call (`#<depth>`) or global (`#<_depth>`),
// and the predefined read-only `#<_x>`, `#<_metric>`, ... that describe the machine state.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace nckit::interp::ngc {

inline constexpr std::int64_t max_parameter = 5601;  //!< LinuxCNC: RS274NGC_MAX_PARAMETERS - 1
inline constexpr std::size_t call_arguments = 30;    //!< #1-#30 carry a call's arguments

class NgcParameters {
public:
    using Values = std::array<double, max_parameter + 1>;
    //! State-backed values: numbered ones LinuxCNC keeps current itself (positions #5420-, work
    //! offsets #5221-, tool #5400-), and predefined names (`_x`, `_metric`, ...).
    struct Live {
        std::function<std::optional<double>(std::int64_t)> numbered;
        std::function<std::optional<double>(const std::string&)> named;
    };

    NgcParameters() {
        values_.fill(0.0);
        frames_.emplace_back();
    }

    void set_live(Live live) { live_ = std::move(live); }
    [[nodiscard]] bool in_range(std::int64_t n) const { return n >= 1 && n <= max_parameter; }

    [[nodiscard]] double read(std::int64_t n) const;
    void write(std::int64_t n, double value) { values_[static_cast<std::size_t>(n)] = value; }
    [[nodiscard]] const Values& values() const { return values_; }

    //! Nothing when the name is not defined (an error in LinuxCNC).
    [[nodiscard]] std::optional<double> read_named(const std::string& name) const;
    [[nodiscard]] bool exists(const std::string& name) const { return read_named(name).has_value(); }
    //! False for a predefined (read-only) name.
    [[nodiscard]] bool write_named(const std::string& name, double value);

    //! A call: the caller's #1-#30 are kept, the arguments take their place, named locals start empty.
    void enter_call(const std::vector<double>& arguments);
    //! An M98 call: named locals start empty, #1-#30 stay the caller's (LinuxCNC's Fanuc-style subs).
    void enter_shared_call() { frames_.push_back(Frame{{}, {}, true}); }
    void leave_call();
    [[nodiscard]] std::size_t depth() const { return frames_.size() - 1; }

    void set_return_value(std::optional<double> value) {
        return_value_ = value.value_or(0.0);
        value_returned_ = value.has_value();
    }

private:
    struct Frame {
        std::array<double, call_arguments> saved{};
        std::unordered_map<std::string, double> locals;
        bool shares_numbered = false;  //!< M98: #1-#30 are not restored on return
    };
    Values values_{};
    std::vector<Frame> frames_;
    std::unordered_map<std::string, double> globals_;
    Live live_;
    double return_value_ = 0;
    bool value_returned_ = false;
};

}  // namespace nckit::interp::ngc
