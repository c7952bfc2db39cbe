#pragma once
// Where each sequence number of one program stands, read once, so that a GOTO costs a lookup
// instead of a scan of the lines between it and its target (a program jumping back and forth
// over 10,000 lines re-read them on every jump). Also where each ENDm stands: a jump forward
// out of a loop passes its END, and the loop is over.
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace nckit::interp {

class SequenceIndex {
public:
    struct Target {
        std::uint64_t offset = 0;  //!< byte offset of the line in its file
        std::uint32_t line = 0;    //!< 1-based line number
    };

    //! Programs with more numbered lines than this are searched line by line instead (each
    //! line counts against the runaway budget): the index stays within a few tens of MB.
    static constexpr std::size_t max_entries = 1'000'000;

    //! Lines must be added in file order.
    void add_number(std::int64_t number, std::uint64_t offset, std::uint32_t line);
    void add_loop_end(int loop, std::uint64_t offset);
    //! All lines added: sorts the numbers for lookups.
    void seal();
    [[nodiscard]] bool full() const { return entries_.size() >= max_entries; }

    //! The first line numbered `number` at or after `from` (a search forward to the program's
    //! end), else the first one before `from` (the search then goes on from the program's start).
    [[nodiscard]] std::optional<Target> find(std::int64_t number, std::uint64_t from) const;
    //! An END`loop` stands in [from, to).
    [[nodiscard]] bool loop_end_between(int loop, std::uint64_t from, std::uint64_t to) const;

private:
    struct Entry {
        std::int64_t number;
        std::uint64_t offset;
        std::uint32_t line;
    };
    std::vector<Entry> entries_;                           // by number, then offset, once sealed
    std::map<int, std::vector<std::uint64_t>> loop_ends_;  // offsets in file order
};

}  // namespace nckit::interp
