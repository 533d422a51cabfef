#pragma once
// The shortest text that reads back as exactly a double, spelled as std::to_chars(first, last, v)
// spells it (docs/spec.md §2.8), in a third of its time: a batch line writes about fifty numbers,
// and libstdc++'s to_chars (Ryu, then a second pass choosing the fixed or the scientific form) was
// a fifth of the whole line. The digits come from fmt's Dragonbox (the shortest, nearest the
// value, ties to even: the digits Ryu gives); the layout is to_chars's: fixed or scientific,
// whichever is shorter, fixed on a tie.

namespace relpos::detail {

// Writes v at `first` (at most 24 characters; up to 40 bytes from `first` may be overwritten) and
// returns the end of the text; exactly the characters
// std::to_chars(first, first + 24, v) writes (shortest_double_test compares them on millions of
// doubles). Non-finite values and magnitudes from 2^53 (integers that to_chars writes exactly, not
// as their shortest digits and zeros) are std::to_chars's own.
char* writeShortestDouble(char* first, double v);

}  // namespace relpos::detail
