#pragma once
// Deterministic fuzzing of input readers for the tests: mutants of a valid input (truncations,
// byte flips, token injection, line deletion and duplication) from a fixed seed, and the check
// that a reader only ever accepts an input or refuses it with an InputError - never another
// exception, a crash or undefined behaviour (the *_asan test targets run the same code under
// AddressSanitizer + UBSan). Bounded: the count of mutants is fixed, so CI time is too.

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace rheomag::testing {

/// The whole content of a file ("" if it cannot be read).
inline std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Mutations: truncation, byte replacement, token injection, line deletion and duplication.
inline std::vector<std::string> mutants(const std::string& text, unsigned seed, int count) {
  std::vector<std::string> out;
  std::mt19937 random(seed);
  const std::vector<std::string> tokens{"nan",
                                        "inf",
                                        "-1",
                                        "0",
                                        "1e999",
                                        "-1e308",
                                        "\"",
                                        "[",
                                        "]",
                                        "<",
                                        ">",
                                        "=",
                                        "\n",
                                        "\r",
                                        "[[region]]",
                                        "999999",
                                        "<BeginBlock>",
                                        "[NumPoints] = 3",
                                        "\t",
                                        "#",
                                        "{",
                                        "}",
                                        ",",
                                        ";",
                                        "\xEF\xBB\xBF",
                                        "1e309",
                                        "-0"};
  for (std::size_t cut = 0; cut < text.size(); cut += std::max<std::size_t>(1, text.size() / 150))
    out.push_back(text.substr(0, cut));
  for (int i = 0; i < count; ++i) {
    std::string m = text;
    const int edits = 1 + static_cast<int>(random() % 3);
    for (int e = 0; e < edits && !m.empty(); ++e) {
      const std::size_t at = random() % m.size();
      switch (random() % 4) {
        case 0:
          m[at] = static_cast<char>(random() % 256);
          break;
        case 1:
          m.insert(at, tokens[random() % tokens.size()]);
          break;
        case 2: {  // delete the line containing `at`
          const std::size_t begin = m.rfind('\n', at);
          const std::size_t end = m.find('\n', at);
          m.erase(begin == std::string::npos ? 0 : begin,
                  end == std::string::npos ? std::string::npos : end - begin);
          break;
        }
        default: {  // duplicate the line containing `at`
          const std::size_t begin = m.rfind('\n', at);
          const std::size_t end = m.find('\n', at);
          const std::size_t b = begin == std::string::npos ? 0 : begin;
          m.insert(b, m.substr(b, (end == std::string::npos ? m.size() : end) - b));
          break;
        }
      }
    }
    out.push_back(m);
  }
  return out;
}

/// Runs `parse` on every mutant; counts outcomes; fails on any non-InputError exception.
inline void expect_only_input_errors(const std::vector<std::string>& inputs,
                                     const std::function<void(const std::string&)>& parse) {
  int parsed = 0, rejected = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    try {
      parse(inputs[i]);
      ++parsed;
    } catch (const rheomag::InputError& e) {
      ++rejected;
      EXPECT_GT(std::string(e.what()).size(), 10u) << "message too short: " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "input " << i << " threw a non-InputError: " << e.what() << "\n---\n"
                    << inputs[i].substr(0, 2000);
    }
  }
  // Both outcomes occur: the mutations reach the parser's checks, not just its first line.
  EXPECT_GT(parsed, 0);
  EXPECT_GT(rejected, static_cast<int>(inputs.size()) / 4);
}

}  // namespace rheomag::testing
