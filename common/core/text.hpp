// Text from users (file names, --set values) shown in messages and written into reports.
#pragma once

#include <string>

namespace shadows {

// `text` safe to print on one line: newline, carriage return and tab as \n \r \t, other
// control bytes and bytes that are not UTF-8 as \xNN, bidirectional formatting characters
// (U+202E and its kin) as \uNNNN. Other valid UTF-8 passes unchanged, and so
// does a text it already escaped (it adds no backslash of its own to a backslash), so every
// message can go through it once more where it is printed.
std::string printable(const std::string& text);

// The length of the UTF-8 sequence starting at text[i] (1..4), or 0 when the byte there does
// not start a complete, well-formed one (overlong forms and surrogates are not well-formed).
size_t utf8SequenceLength(const std::string& text, size_t i);

// The shortest decimal that reads back as `f` (what std::to_chars gives, found digit by digit:
// emscripten 3.1's libc++ has no float to_chars), e.g. "0.1" for 0.1f, "1e-05" for 1e-5f.
std::string shortestDecimal(float f);

}  // namespace shadows
