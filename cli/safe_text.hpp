#pragma once
// Text the command writes on behalf of its input (names, paths, messages that quote the input):
// always valid UTF-8, and one line where it must be one line. Input may hold any byte: a file name
// with 0xFF, a spec name with a newline, a parser message that quotes half a UTF-8 sequence.
#include <string>
#include <string_view>

namespace relpos::cli {

// Whether s is valid UTF-8 (Unicode §3.9 Table 3-7: no overlong forms, no surrogates, nothing
// above U+10FFFF).
bool isValidUtf8(std::string_view s);

// s with each byte that does not belong to a valid UTF-8 sequence replaced by U+FFFD.
std::string validUtf8(std::string_view s);

// s as one line of text for stderr or a table: valid UTF-8, with control characters written as
// \n, \r, \t or \xHH, so that a name holding a newline cannot split a message in two.
std::string oneLine(std::string_view s);

// s as a JSON string (quoted, escaped like nlohmann's dump, invalid UTF-8 replaced), appended.
void appendJsonString(std::string& out, std::string_view s);

}  // namespace relpos::cli
