// Property checks shared by the fuzzers (docs/hardening.md): what a refusal
// must say, and the loop that reports a failing input once with its file.
#ifndef TOWDB_TESTS_FUZZ_FUZZ_CHECKS_HPP
#define TOWDB_TESTS_FUZZ_FUZZ_CHECKS_HPP

#include <algorithm>
#include <utility>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz_support.hpp"

namespace towdb::fuzz {

// The field names a message may cite: every key of the format and its stem
// without the unit suffix ("beam_ft" -> "beam"), because the model layer
// names fields in SI ("beam_m") or without a unit ("drag speed").
inline std::vector<std::string> field_names(const std::vector<std::string>& keys) {
  std::vector<std::string> out;
  for (const std::string& k : keys) {
    if (k.size() < 2 || !std::all_of(k.begin(), k.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
        })) {
      continue;
    }
    out.push_back(k);
    const auto u = k.rfind('_');
    if (u != std::string::npos && u >= 2) out.push_back(k.substr(0, u));
  }
  return out;
}

// True when `word` occurs in `text` as a whole identifier.
inline bool has_word(std::string_view text, std::string_view word) {
  auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t p = text.find(word); p != std::string_view::npos; p = text.find(word, p + 1)) {
    const bool left = p == 0 || !ident(text[p - 1]);
    const bool right = p + word.size() >= text.size() || !ident(text[p + word.size()]);
    if (left && right) return true;
  }
  return false;
}

// Empty when `message` is a proper refusal of a file: it starts with the file
// name and names a field of the format (or, for a TOML syntax error, gives
// line:column and says "malformed TOML"); else what is wrong.
inline std::string refusal_problem(const std::string& message, const std::string& path,
                                   const std::vector<std::string>& fields) {
  if (message.rfind(path, 0) != 0) return "the message does not start with the file name '" + path + "'";
  if (message.find("malformed TOML") != std::string::npos || message.find("the file is empty") != std::string::npos) {
    return "";
  }
  for (const std::string& f : fields) {
    if (has_word(message, f)) return "";
  }
  return "the message names no field of the format";
}

// Reports a property failure once per fuzzer run (the rest are counted), with
// the input saved for reproduction. Returns false after kMaxReports reports so
// the caller can stop early.
class Findings {
 public:
  explicit Findings(std::string fuzzer) : fuzzer_(std::move(fuzzer)) {}
  static constexpr int kMaxReports = 5;

  bool report(const std::string& input_name, std::string_view bytes, const std::string& problem) {
    ++count_;
    if (count_ <= kMaxReports) {
      const auto path = save_failure(fuzzer_, input_name, bytes);
      ADD_FAILURE() << fuzzer_ << ": " << problem << "\n  input saved as " << path.string();
    }
    return count_ < kMaxReports;
  }
  int count() const { return count_; }

 private:
  std::string fuzzer_;
  int count_ = 0;
};

}  // namespace towdb::fuzz

#endif  // TOWDB_TESTS_FUZZ_FUZZ_CHECKS_HPP
