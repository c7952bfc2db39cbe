#pragma once
// Fanuc-style alarm numbers of Custom Macro B (0i numbering; 30i prefixes them PS). A
// Diagnostic's `alarm` carries one of these, or 3000 + n for a user alarm from #3000.
namespace nckit::alarm {

inline constexpr int too_many_blocks = 100;  //!< nckit's own: block budget used up (runaway loop)
inline constexpr int division_by_zero = 112;
inline constexpr int format = 114;              //!< format error in a macro statement
inline constexpr int illegal_variable = 115;    //!< no such variable number
inline constexpr int protected_variable = 116;  //!< write to a read-only variable
inline constexpr int bracket_nesting = 118;     //!< more than 5 nested brackets
inline constexpr int argument_range = 119;      //!< SQRT of a negative, ASIN of 2, BCD of -1, ...
inline constexpr int call_nesting = 122;        //!< macro or subprogram calls nested too deep
inline constexpr int loop_mismatch = 124;       //!< missing END / DO-END mismatch
inline constexpr int call_format = 125;         //!< format error in a G65/G66 block
inline constexpr int loop_number = 126;         //!< DOm with m not 1..3, overlapping loops
inline constexpr int sequence_not_found = 128;  //!< GOTO / M99 P target not found
inline constexpr int address_p_missing = 76;    //!< M98 / G65 / G66 without P
inline constexpr int program_not_found = 78;    //!< M98 / G65 program number not found
inline constexpr int user_base = 3000;          //!< #3000 = n raises 3000 + n

}  // namespace nckit::alarm
