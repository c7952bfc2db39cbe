#include "sequence_index.hpp"

#include <algorithm>

namespace nckit::interp {

void SequenceIndex::add_number(std::int64_t number, std::uint64_t offset, std::uint32_t line) {
    entries_.push_back(Entry{number, offset, line});
}

void SequenceIndex::add_loop_end(int loop, std::uint64_t offset) {
    loop_ends_[loop].push_back(offset);
}

void SequenceIndex::seal() {
    // Added in file order: a stable sort by number keeps each number's lines in file order.
    std::stable_sort(entries_.begin(), entries_.end(),
                     [](const Entry& a, const Entry& b) { return a.number < b.number; });
}

std::optional<SequenceIndex::Target> SequenceIndex::find(std::int64_t number, std::uint64_t from) const {
    auto by_number = [](const Entry& e, std::int64_t n) { return e.number < n; };
    const auto first = std::lower_bound(entries_.begin(), entries_.end(), number, by_number);
    if (first == entries_.end() || first->number != number) return std::nullopt;
    const auto last =
        std::upper_bound(first, entries_.end(), number, [](std::int64_t n, const Entry& e) { return n < e.number; });
    const auto ahead =
        std::lower_bound(first, last, from, [](const Entry& e, std::uint64_t o) { return e.offset < o; });
    const Entry& hit = ahead != last ? *ahead : *first;
    return Target{hit.offset, hit.line};
}

bool SequenceIndex::loop_end_between(int loop, std::uint64_t from, std::uint64_t to) const {
    const auto it = loop_ends_.find(loop);
    if (it == loop_ends_.end()) return false;
    const auto at = std::lower_bound(it->second.begin(), it->second.end(), from);
    return at != it->second.end() && *at < to;
}

}  // namespace nckit::interp
