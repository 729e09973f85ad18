// Text from users (file names, --set values) shown in messages and written into reports.
#pragma once

#include <string>

namespace shadows {

// `text` safe to print on one line: newline, carriage return and tab as \n \r \t, other
// control bytes and bytes that are not UTF-8 as \xNN. Valid UTF-8 passes unchanged, and so
// does a text it already escaped (it adds no backslash of its own to a backslash), so every
// message can go through it once more where it is printed.
std::string printable(const std::string& text);

// The length of the UTF-8 sequence starting at text[i] (1..4), or 0 when the byte there does
// not start a complete, well-formed one (overlong forms and surrogates are not well-formed).
size_t utf8SequenceLength(const std::string& text, size_t i);

}  // namespace shadows
