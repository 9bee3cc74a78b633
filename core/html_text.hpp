// Text for the HTML reports: escaped strings and short numbers.
#pragma once

#include <sstream>
#include <string>

namespace rheomag {

/// `text` with <, > and & escaped for HTML element content and attribute values in quotes.
inline std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '\'')
      out += "&#39;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

/// `value` with `digits` significant digits, as a report shows it.
inline std::string html_number(double value, int digits = 4) {
  std::ostringstream o;
  o.precision(digits);
  o << value;
  return o.str();
}

}  // namespace rheomag
