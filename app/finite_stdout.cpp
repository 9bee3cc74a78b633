// The non-finite guard of the CLI's stdout (see finite_stdout.hpp).

#include "app/finite_stdout.hpp"

#include <iostream>

#include "core/format_text.hpp"
#include "core/version.hpp"

namespace rheomag::app {

void FiniteLineGuard::pass_line() {
  ++line_number_;
  if (!offending_) {
    if (auto bad = find_non_finite_token(line_)) {
      bad->line = line_number_;
      offending_ = std::move(bad);
    } else {
      target_->sputn(line_.data(), static_cast<std::streamsize>(line_.size()));
    }
  }
  line_.clear();
}

FiniteLineGuard::int_type FiniteLineGuard::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  line_.push_back(traits_type::to_char_type(c));
  if (line_.back() == '\n') pass_line();
  return c;
}

std::streamsize FiniteLineGuard::xsputn(const char* s, std::streamsize n) {
  for (std::streamsize k = 0; k < n; ++k) {
    line_.push_back(s[k]);
    if (s[k] == '\n') pass_line();
  }
  return n;
}

int FiniteLineGuard::sync() {
  return target_->pubsync();
}

const std::optional<NonFiniteToken>& FiniteLineGuard::finish() {
  if (!line_.empty()) pass_line();
  target_->pubsync();
  return offending_;
}

GuardedStdout::GuardedStdout() : original_(std::cout.rdbuf()), guard_(original_) {
  std::cout.rdbuf(&guard_);
}

GuardedStdout::~GuardedStdout() {
  guard_.finish();
  std::cout.rdbuf(original_);
}

void GuardedStdout::check(const std::string& command) {
  const auto& bad = guard_.finish();
  if (!bad) return;
  std::string line = bad->line_text;
  if (!line.empty() && line.back() == '\n') line.pop_back();
  throw NonFiniteOutputError(
      "stdout line " + std::to_string(bad->line) + " holds a non-finite number ('" + bad->token +
      "' in \"" + line +
      "\"); it and the rest of the output were held back; produced by: " + command);
}

void print_json(const nlohmann::json& j, int indent) {
  nlohmann::json document = j;
  stamp_version(document);
  std::cout << finite_json_text(document, "stdout (JSON)", indent) << std::endl;
}

void print(const char* format, ...) {
  va_list args;
  va_start(args, format);
  const std::string text = format_text_v(format, args);
  va_end(args);
  std::cout << text;
}

}  // namespace rheomag::app
