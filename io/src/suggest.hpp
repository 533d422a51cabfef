#pragma once
// "Did you mean": the known name a mistyped one was most likely meant to be (`coincidence` for
// `coincident`, `orientaton` for `orientation`, `tcp2` for `tcp`), for the messages of the spec
// reader. Hand-written (an edit distance of short names): no library of the project's has one.
#include <string>
#include <string_view>
#include <vector>

namespace relpos::detail {

// The candidate nearest `word` by edit distance (insertions, deletions, substitutions and
// swaps of neighbours; letter case ignored), when it is near enough to be a slip — at most 1 edit
// for words of up to 4 letters, 2 up to 8, 3 beyond — and no other candidate is as near; else "".
std::string closestName(std::string_view word, const std::vector<std::string_view>& candidates);

// "; did you mean 'NAME'?" for closestName, or "" when there is none.
std::string didYouMean(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace relpos::detail
