#pragma once
#include <cstdint>

namespace nckit::interp {

//! A macro variable's content: a number, or vacant (Fanuc's "null", what #0 always holds).
struct MacroValue {
    double number = 0;
    bool vacant = true;

    static MacroValue of(double value) { return MacroValue{value, false}; }
    //! In arithmetic a vacant counts as 0.
    [[nodiscard]] double or_zero() const { return vacant ? 0.0 : number; }
};

}  // namespace nckit::interp
