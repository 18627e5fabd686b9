#include "fuzz_support.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

#include "test_support.hpp"

namespace towdb::fuzz {

namespace {

// A whole number >= 1 from the environment, else `fallback`.
std::uint64_t env_count(const char* name, std::uint64_t fallback) {
  const char* s = std::getenv(name);
  if (!s || !*s) return fallback;
  std::uint64_t v = 0;
  const auto r = std::from_chars(s, s + std::char_traits<char>::length(s), v);
  if (r.ec != std::errc() || *r.ptr != '\0') {
    std::cerr << "fuzz: ignoring " << name << " = '" << s << "' (expected a whole number)\n";
    return fallback;
  }
  return v;
}

bool is_ident(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// [begin, end) of every maximal run of characters that can spell a number.
std::vector<std::pair<std::size_t, std::size_t>> number_spans(const std::string& t) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < t.size();) {
    const bool start = std::isdigit(static_cast<unsigned char>(t[i])) &&
                       (i == 0 || !(std::isalpha(static_cast<unsigned char>(t[i - 1])) || t[i - 1] == '_'));
    if (!start) {
      ++i;
      continue;
    }
    std::size_t b = i;
    if (b > 0 && (t[b - 1] == '-' || t[b - 1] == '+')) --b;
    std::size_t e = i;
    while (e < t.size() && (std::isdigit(static_cast<unsigned char>(t[e])) || t[e] == '.' || t[e] == 'e' ||
                            t[e] == 'E' || t[e] == '_' || ((t[e] == '-' || t[e] == '+') && (t[e - 1] == 'e' || t[e - 1] == 'E')))) {
      ++e;
    }
    out.emplace_back(b, e);
    i = e;
  }
  return out;
}

// [begin, end) of the contents of every "..." string on one line.
std::vector<std::pair<std::size_t, std::size_t>> string_spans(const std::string& t) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::size_t i = 0;
  while (i < t.size()) {
    if (t[i] != '"') {
      ++i;
      continue;
    }
    const std::size_t b = i + 1;
    std::size_t e = b;
    while (e < t.size() && t[e] != '"' && t[e] != '\n') e += t[e] == '\\' ? 2 : 1;
    if (e >= t.size() || t[e] != '"') break;
    out.emplace_back(b, e);
    i = e + 1;
  }
  return out;
}

// [begin, end) of every key: an identifier followed by optional blanks and '='.
std::vector<std::pair<std::size_t, std::size_t>> key_spans(const std::string& t) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] != '=') continue;
    std::size_t e = i;
    while (e > 0 && (t[e - 1] == ' ' || t[e - 1] == '\t')) --e;
    std::size_t b = e;
    while (b > 0 && is_ident(t[b - 1])) --b;
    if (b < e) out.emplace_back(b, e);
  }
  return out;
}

std::string odd_byte(RandomStream& rng) {
  static const char kBytes[] = "\"'[]{}=,.#\\\n\t -+_0123456789eEinfaxz";
  if (chance(rng, 0.2)) return std::string(1, static_cast<char>(below(rng, 256)));
  return std::string(1, kBytes[below(rng, sizeof kBytes - 1)]);
}

}  // namespace

int iterations(int base) {
#if defined(TOWDB_FUZZ_SANITIZED)
  base = std::max(1, base / kSanitizerDivisor);
#endif
  const std::uint64_t scale = std::max<std::uint64_t>(1, env_count("TOWDB_FUZZ_SCALE", 1));
  const std::uint64_t n = static_cast<std::uint64_t>(base) * scale;
  return static_cast<int>(std::min<std::uint64_t>(n, std::numeric_limits<int>::max()));
}

std::uint64_t seed(std::uint64_t fixed) { return fixed + env_count("TOWDB_FUZZ_SEED", 0); }

std::vector<Input> load_dir(const std::string& sub) {
  const auto dir = test::source_dir() / "tests/fuzz" / sub;
  std::vector<Input> out;
  if (!std::filesystem::is_directory(dir)) return out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (!e.is_regular_file() || e.path().filename() == "README.md") continue;
    out.push_back({e.path().filename().string(), test::read_text(e.path())});
  }
  std::sort(out.begin(), out.end(), [](const Input& a, const Input& b) { return a.name < b.name; });
  return out;
}

std::size_t below(RandomStream& rng, std::size_t n) { return n <= 1 ? 0 : rng.next_u64() % n; }

bool chance(RandomStream& rng, double p) { return rng.uniform01() < p; }

const std::vector<std::string>& odd_numbers() {
  static const std::vector<std::string> v = {
      "nan", "+nan", "-nan", "inf", "+inf", "-inf", "0", "-0", "0.0", "-0.0", "1", "-1", "2", "1e308",
      "-1e308", "1.7976931348623157e308", "1e309", "4.9e-324", "1e-320", "2.2250738585072014e-308",
      "9223372036854775807", "-9223372036854775808", "9223372036854775808", "99999999999999999999",
      "2147483647", "4294967296", "0x7fffffff", "0o777", "0b101", "1_000", "360", "361", "-180", "1e9",
      "0.001", "0.5", "1e-9", "1.0e+3", "true", "\"12\"", "[]", "[1, 2]", "{}", "1979-05-27"};
  return v;
}

const std::vector<std::string>& odd_strings() {
  static const std::vector<std::string> v = {"", " ", "\\t", "x", std::string(3000, 'A'), "\\u0000",
                                             "\\u00e9t\\u00e9", "\xff\xfe", "\\\"", ",", "a,b", "T-ATF",
                                             "ARS 50", "tatf166", "FFG 7", "wire", "fiber", "chain", "S", "Q",
                                             "jonswap", "calculated", "given", "strip-theory"};
  return v;
}

const std::vector<double>& odd_doubles() {
  static const std::vector<double> v = {std::numeric_limits<double>::quiet_NaN(),
                                        std::numeric_limits<double>::infinity(),
                                        -std::numeric_limits<double>::infinity(),
                                        0.0,
                                        -0.0,
                                        -1.0,
                                        std::numeric_limits<double>::max(),
                                        -std::numeric_limits<double>::max(),
                                        std::numeric_limits<double>::min(),
                                        std::numeric_limits<double>::denorm_min(),
                                        std::numeric_limits<double>::epsilon(),
                                        1e300,
                                        1e-300,
                                        1.0 + 1e-15,
                                        9.2233720368547758e18};
  return v;
}

Mutator::Mutator(const std::vector<Input>& corpus, const std::vector<std::string>& extra_words) {
  std::set<std::string> words(extra_words.begin(), extra_words.end());
  for (const Input& in : corpus) {
    std::istringstream is(in.text);
    for (std::string line; std::getline(is, line);) {
      lines_.push_back(line + "\n");
      // Table headers ([hull.stations], [[grid]]) name fields too.
      if (line.empty() || line[0] != '[') continue;
      std::string name;
      for (char c : line.substr(0, line.find(']')) + ".") {
        if (is_ident(c)) {
          name += c;
        } else if (!name.empty()) {
          words.insert(name);
          name.clear();
        }
      }
    }
    for (const auto& [b, e] : key_spans(in.text)) words.insert(in.text.substr(b, e - b));
    for (const auto& [b, e] : string_spans(in.text)) {
      if (e - b <= 40) words.insert(in.text.substr(b, e - b));
    }
  }
  words_.assign(words.begin(), words.end());
  if (lines_.empty()) lines_.push_back("\n");
  if (words_.empty()) words_.push_back("x");
}

std::string Mutator::mutate(RandomStream& rng, std::string text) const {
  const std::size_t edits = 1 + below(rng, 4);
  for (std::size_t i = 0; i < edits; ++i) mutate_once(rng, text);
  return text;
}

void Mutator::mutate_once(RandomStream& rng, std::string& t) const {
  const std::size_t n = t.size();
  const std::size_t pos = below(rng, n + 1);
  switch (below(rng, 12)) {
    case 0:  // flip one bit
      if (n > 0) t[pos % n] = static_cast<char>(t[pos % n] ^ (1 << below(rng, 8)));
      return;
    case 1:  // replace a byte
      if (n > 0) t.replace(pos % n, 1, odd_byte(rng));
      return;
    case 2:  // insert a byte
      t.insert(pos, odd_byte(rng));
      return;
    case 3:  // delete a range
      t.erase(pos, 1 + below(rng, 32));
      return;
    case 4: {  // duplicate a range
      if (n == 0) return;
      const std::size_t b = below(rng, n);
      t.insert(pos, t.substr(b, 1 + below(rng, 64)));
      return;
    }
    case 5: {  // a number becomes an odd one
      const auto spans = number_spans(t);
      if (spans.empty()) return;
      const auto [b, e] = spans[below(rng, spans.size())];
      t.replace(b, e - b, odd_numbers()[below(rng, odd_numbers().size())]);
      return;
    }
    case 6: {  // a string becomes an odd one, or another dictionary word
      const auto spans = string_spans(t);
      if (spans.empty()) return;
      const auto [b, e] = spans[below(rng, spans.size())];
      const bool odd = chance(rng, 0.5);
      t.replace(b, e - b, odd ? odd_strings()[below(rng, odd_strings().size())] : words_[below(rng, words_.size())]);
      return;
    }
    case 7: {  // a key becomes another key (or a misspelt one)
      const auto spans = key_spans(t);
      if (spans.empty()) return;
      const auto [b, e] = spans[below(rng, spans.size())];
      std::string w = words_[below(rng, words_.size())];
      if (chance(rng, 0.2)) w += chance(rng, 0.5) ? "_m" : "_ft";
      t.replace(b, e - b, w);
      return;
    }
    case 8:  // splice in a line of another corpus file
      t.insert(t.rfind('\n', pos) == std::string::npos ? 0 : t.rfind('\n', pos) + 1,
               lines_[below(rng, lines_.size())]);
      return;
    case 9: {  // delete or duplicate a whole line
      const std::size_t b = t.rfind('\n', pos) == std::string::npos ? 0 : t.rfind('\n', pos) + 1;
      const std::size_t e = t.find('\n', pos) == std::string::npos ? n : t.find('\n', pos) + 1;
      if (chance(rng, 0.5)) {
        t.erase(b, e - b);
      } else {
        t.insert(b, t.substr(b, e - b));
      }
      return;
    }
    case 10:  // truncate
      t.resize(pos);
      return;
    default: {  // a number nudged by a small relative amount (stays plausible, probes bounds)
      const auto spans = number_spans(t);
      if (spans.empty()) return;
      const auto [b, e] = spans[below(rng, spans.size())];
      double v = 0.0;
      const auto r = std::from_chars(t.data() + b + (t[b] == '+' ? 1 : 0), t.data() + e, v);
      if (r.ec != std::errc()) return;
      static const double kFactors[] = {0.0, -1.0, 0.5, 0.999999, 1.000001, 2.0, 10.0, 1000.0};
      std::ostringstream os;
      os.precision(17);
      os << v * kFactors[below(rng, std::size(kFactors))];
      std::string s = os.str();
      if (s.find_first_of(".e") == std::string::npos && chance(rng, 0.5)) s += ".0";
      t.replace(b, e - b, s);
      return;
    }
  }
}

std::filesystem::path save_failure(const std::string& fuzzer, const std::string& name, std::string_view bytes) {
  const char* bin = std::getenv("TOWDB_BINARY_DIR");
  const auto dir = (bin && *bin ? std::filesystem::path(bin) : std::filesystem::temp_directory_path()) /
                   "fuzz-failures" / fuzzer;
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

void Tally::print(const std::string& fuzzer, double seconds) const {
  std::cout << "fuzz " << fuzzer << ": " << executions << " executions in " << seconds << " s (" << accepted
            << " accepted, " << refused << " refused with the documented error, " << distinct_messages.size()
            << " distinct messages)\n";
}

}  // namespace towdb::fuzz
