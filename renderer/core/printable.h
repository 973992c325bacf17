#pragma once
// Text from input (names, descriptions, file names, attribute names) made safe for a terminal.
#include <string>
#include <string_view>

namespace isotrace {

// Control characters are spelled out as \xHH: a NUL would end a C string early, an escape sequence could rewrite the
// terminal. Line breaks and tabs stay.
std::string printable(std::string_view text);

}  // namespace isotrace
