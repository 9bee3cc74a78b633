// Drive signal generators for simulate --signal.

#include "lumped/signals.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>

#include "core/error.hpp"
#include "lumped/recording_io.hpp"

namespace rheomag::lumped {

namespace {

double number(const std::map<std::string, std::string>& kv, const std::string& key,
              const std::string& text, std::optional<double> fallback = std::nullopt) {
  auto it = kv.find(key);
  if (it == kv.end()) {
    if (fallback) return *fallback;
    throw InputError("--signal '" + text + "': missing " + key + "=");
  }
  double v = 0.0;
  const auto& s = it->second;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
    throw InputError("--signal '" + text + "': " + key + "=" + s + " is not a number");
  return v;
}

}  // namespace

std::vector<double> uniform_times(double duration, double rate) {
  if (!(duration > 0) || !(rate > 0) || duration * rate > 1e8)
    throw InputError("--duration and --rate must be > 0 (and at most 1e8 samples)");
  const std::size_t n = static_cast<std::size_t>(std::llround(duration * rate));
  std::vector<double> t(std::max<std::size_t>(n, 2));
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<double>(k) / rate;
  return t;
}

void add_signal(Recording& rec, const std::string& text) {
  const auto eq = text.find('='), colon = text.find(':');
  if (eq == std::string::npos || colon == std::string::npos || colon < eq)
    throw InputError("--signal '" + text + "': expected COLUMN=KIND:key=value,...");
  const std::string column = text.substr(0, eq), kind = text.substr(eq + 1, colon - eq - 1);
  const auto& known = known_columns();
  if (column == "t" || std::find(known.begin(), known.end(), column) == known.end())
    throw InputError("--signal '" + text + "': '" + column + "' is not a recording column");
  std::map<std::string, std::string> kv;
  std::size_t start = colon + 1;
  while (start < text.size()) {
    std::size_t comma = text.find(',', start);
    std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    auto e = item.find('=');
    if (e == std::string::npos) throw InputError("--signal '" + text + "': '" + item + "' lacks =");
    kv[item.substr(0, e)] = item.substr(e + 1);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const double pi = 3.14159265358979323846;
  std::vector<double> v(rec.t.size());
  if (kind == "sine") {
    const double a = number(kv, "amplitude", text), f = number(kv, "frequency", text),
                 x0 = number(kv, "offset", text, 0.0);
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = x0 + a * std::sin(2 * pi * f * rec.t[k]);
    if (column == "displacement") {
      std::vector<double> vel(rec.t.size());
      for (std::size_t k = 0; k < v.size(); ++k)
        vel[k] = a * 2 * pi * f * std::cos(2 * pi * f * rec.t[k]);
      rec.columns["velocity"] = vel;
    }
  } else if (kind == "constant") {
    const double c = number(kv, "value", text);
    std::fill(v.begin(), v.end(), c);
  } else if (kind == "steps" || kind == "square") {
    std::vector<double> levels;
    if (kind == "square") {
      levels = {number(kv, "low", text), number(kv, "high", text)};
    } else {
      auto it = kv.find("levels");
      if (it == kv.end()) throw InputError("--signal '" + text + "': missing levels=a/b/...");
      std::size_t s = 0;
      const std::string& lv = it->second;
      while (s <= lv.size()) {
        std::size_t slash = lv.find('/', s);
        std::map<std::string, std::string> one{
            {"level", lv.substr(s, slash == std::string::npos ? std::string::npos : slash - s)}};
        levels.push_back(number(one, "level", text));
        if (slash == std::string::npos) break;
        s = slash + 1;
      }
    }
    const double period = number(kv, "period", text);
    if (!(period > 0)) throw InputError("--signal '" + text + "': period must be > 0");
    const double hold = kind == "square" ? period / 2 : period;
    for (std::size_t k = 0; k < v.size(); ++k)
      v[k] = levels[static_cast<std::size_t>(std::floor(rec.t[k] / hold)) % levels.size()];
  } else {
    throw InputError("--signal '" + text + "': unknown kind '" + kind +
                     "' (sine, constant, steps, square)");
  }
  rec.columns[column] = v;
}

}  // namespace rheomag::lumped
