#pragma once
// The CLI's stdout behind the non-finite guard: every line a command prints is checked before it
// reaches the user; a line holding "nan" or "inf" is held back and ends the command with exit 3.

#include <cstdarg>
#include <optional>
#include <ostream>
#include <streambuf>
#include <string>

#include "core/finite_output.hpp"

namespace rheomag::app {

/// A stream buffer that passes whole lines to `target` once find_non_finite_token found nothing
/// in them; from the first line that holds a non-finite number on, nothing more is passed on.
class FiniteLineGuard : public std::streambuf {
 public:
  explicit FiniteLineGuard(std::streambuf* target) : target_(target) {}

  /// Checks and passes on the unfinished last line; the first offending line, if any.
  const std::optional<NonFiniteToken>& finish();

  /// The first line held back, if any.
  const std::optional<NonFiniteToken>& offending() const { return offending_; }

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;
  int sync() override;

 private:
  void pass_line();

  std::streambuf* target_;
  std::string line_;
  std::size_t line_number_ = 0;
  std::optional<NonFiniteToken> offending_;
};

/// Installs a FiniteLineGuard on std::cout for its lifetime; `check()` throws
/// NonFiniteOutputError naming the line held back and `command` (the command line).
class GuardedStdout {
 public:
  GuardedStdout();
  ~GuardedStdout();
  GuardedStdout(const GuardedStdout&) = delete;
  GuardedStdout& operator=(const GuardedStdout&) = delete;

  /// Passes on the last line; throws if any line held a non-finite number.
  void check(const std::string& command);

  /// Passes on the last line (when the command ended with an exception).
  void finish() { guard_.finish(); }

 private:
  std::streambuf* original_;
  FiniteLineGuard guard_;
};

/// Prints `j` with its "version" (core/version.hpp; indent as nlohmann's dump, -1 is one line)
/// and a newline on std::cout once
/// require_finite_json passed: NonFiniteOutputError naming the key otherwise.
void print_json(const nlohmann::json& j, int indent = -1);

/// printf to std::cout (so the guard sees it): every command prints through std::cout.
[[gnu::format(printf, 1, 2)]] void print(const char* format, ...);

}  // namespace rheomag::app
