#pragma once
// Text relpos writes on behalf of its input (names, paths, messages quoting the input): always
// valid UTF-8, and one line where it must be one line. Input may hold any byte: a file name with
// 0xFF, a spec name with a newline, a parser message that quotes half a UTF-8 sequence. One
// reading of UTF-8 for all of it (io/src/utf8.hpp: Unicode's table 3-7 and its "maximal
// subparts"), shared by the reader's diagnostics, the result writer and the command.
#include <string>
#include <string_view>

namespace relpos {

// Whether s is valid UTF-8 (no overlong forms, no surrogates, nothing above U+10FFFF).
bool isValidUtf8(std::string_view s);

// s with each ill-formed subpart replaced by one U+FFFD (what the result writer does to names).
std::string validUtf8(std::string_view s);

// s on one line and in valid UTF-8, for stderr or a table: \n \r \t \0, \xHH for other C0
// controls, DEL and each byte of an ill-formed sequence, \uHHHH for C1 controls and the line and
// paragraph separators. A backslash is left alone, so escaping twice changes nothing (the escaping
// of formatDiagnostic).
std::string oneLine(std::string_view s);

}  // namespace relpos
