// printf-style formatting into a std::ostream.

#include "identify/printf_stream.hpp"

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace rheomag::identify {

void vprint_to(std::ostream& out, const char* format, va_list args) {
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  if (n > 0) {
    std::vector<char> text(static_cast<std::size_t>(n) + 1);
    std::vsnprintf(text.data(), text.size(), format, args);
    out.write(text.data(), n);
  }
}

void print_to(std::ostream& out, const char* format, ...) {
  va_list args;
  va_start(args, format);
  vprint_to(out, format, args);
  va_end(args);
}

}  // namespace rheomag::identify
