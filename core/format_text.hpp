#pragma once
// printf-style formatting into a std::string, for the text reports libraries return.

#include <cstdarg>
#include <string>

namespace rheomag {

/// The text printf would print for `format` and the arguments.
[[gnu::format(printf, 1, 2)]] std::string format_text(const char* format, ...);

/// The same with a va_list (for other variadic printers).
std::string format_text_v(const char* format, va_list args);

}  // namespace rheomag
