#pragma once
// printf-style formatting into a caller's stream: the text reports of identify/ are written with
// the same format strings the CLI used, so their output stays byte for byte what it was.

#include <cstdarg>
#include <ostream>

namespace rheomag::identify {

/// Writes `format` with the arguments `args` (as std::vprintf would) to `out`.
void vprint_to(std::ostream& out, const char* format, va_list args);

/// Writes `format` with its arguments (as std::printf would) to `out`.
[[gnu::format(printf, 2, 3)]] void print_to(std::ostream& out, const char* format, ...);

}  // namespace rheomag::identify
