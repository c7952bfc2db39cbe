#pragma once
#include <cassert>
#include <utility>
#include <variant>

#include "nckit/core/diagnostic.hpp"

namespace nckit {

//! A stage's answer: its value, or the diagnostics that stopped it (never both).
template <class T>
class Result {
public:
    Result(T value) : state_(std::move(value)) {}                                  // NOLINT: implicit by design
    Result(Diagnostic diagnostic) : state_(Diagnostics{std::move(diagnostic)}) {}  // NOLINT
    Result(Diagnostics diagnostics) : state_(std::move(diagnostics)) {             // NOLINT
        assert(!std::get<Diagnostics>(state_).empty());
    }

    [[nodiscard]] bool ok() const { return std::holds_alternative<T>(state_); }
    explicit operator bool() const { return ok(); }

    [[nodiscard]] T& value() & { return std::get<T>(state_); }
    [[nodiscard]] const T& value() const& { return std::get<T>(state_); }
    [[nodiscard]] T&& value() && { return std::get<T>(std::move(state_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    [[nodiscard]] const Diagnostics& diagnostics() const { return std::get<Diagnostics>(state_); }

private:
    std::variant<T, Diagnostics> state_;
};

}  // namespace nckit
