// The seeded random-mutation driver shared by the fuzzers of tests/fuzz/
// (docs/hardening.md). Deterministic: iteration i of a fuzzer draws from
// RandomStream(seed, i) (common/random.hpp), so every input can be rebuilt
// from (seed, iteration) alone, on any machine, in any order.
//
// Budget: each fuzzer states its default iteration count (about 10-20 s on
// 2 cores in Release). It is
//   divided by kSanitizerDivisor in a TOWDB_SANITIZE build (the ASan + UBSan
//   run of the README's test command stays short and runs the same first
//   iterations), and
//   multiplied by $TOWDB_FUZZ_SCALE (a whole number >= 1, default 1) to run
//   longer on demand.
// $TOWDB_FUZZ_SEED (default 0) is added to every fuzzer's fixed seed to
// explore other inputs. A failing input is written to
// $TOWDB_BINARY_DIR/fuzz-failures/<fuzzer>/ (or the temporary directory) and
// its path printed, so it can be kept under tests/fuzz/regressions/.
#ifndef TOWDB_TESTS_FUZZ_FUZZ_SUPPORT_HPP
#define TOWDB_TESTS_FUZZ_FUZZ_SUPPORT_HPP

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "common/random.hpp"

namespace towdb::fuzz {

// A TOWDB_SANITIZE build runs 1/kSanitizerDivisor of the iterations: ASan +
// UBSan make the fuzzed code 2-5x slower (measured: ship parser 2.3x, query
// API 4.3x), and the sanitizer run of the README's test command, already the
// longest step, should grow by seconds, not minutes.
inline constexpr int kSanitizerDivisor = 8;

// The iteration count of a fuzzer whose default (Release) budget is `base`.
int iterations(int base);
// The fuzzer's fixed seed plus $TOWDB_FUZZ_SEED.
std::uint64_t seed(std::uint64_t fixed);

struct Input {
  std::string name;  // file name, for messages
  std::string text;  // bytes
};
// The files of tests/fuzz/<sub> (corpus/... or regressions/...), sorted by name;
// README.md files are skipped. Empty when the directory does not exist.
std::vector<Input> load_dir(const std::string& sub);

// A uniform integer in [0, n) from the stream (n >= 1).
std::size_t below(RandomStream& rng, std::size_t n);
// True with probability p.
bool chance(RandomStream& rng, double p);

// Mutates text: bit flips, byte and range edits, splices of lines from other
// corpus files, and token-aware edits: a number replaced by an extreme value
// (nan, inf, 1e308, -0, huge integers, ...), a string by an odd string, a key
// by another key of the dictionary. 1-4 edits per call.
class Mutator {
 public:
  // `corpus` supplies splice lines and, with `extra_words`, the dictionary of
  // keys (identifiers before '=') and quoted strings.
  Mutator(const std::vector<Input>& corpus, const std::vector<std::string>& extra_words = {});
  std::string mutate(RandomStream& rng, std::string text) const;
  const std::vector<std::string>& words() const { return words_; }

 private:
  void mutate_once(RandomStream& rng, std::string& text) const;
  std::vector<std::string> lines_;  // every line of every corpus file
  std::vector<std::string> words_;  // keys and string contents
};

// Values that break numeric code: non-finite, extreme, signed zero,
// subnormal, integer limits, and the TOML spellings of them.
const std::vector<std::string>& odd_numbers();
// Strings that break text code: empty, blank, very long, control bytes,
// invalid UTF-8, quotes and separators.
const std::vector<std::string>& odd_strings();
// The same numeric edge cases as doubles.
const std::vector<double>& odd_doubles();

// Writes a failing input for reproduction; returns its path.
std::filesystem::path save_failure(const std::string& fuzzer, const std::string& name, std::string_view bytes);

// Counts outcomes of one fuzzer for its closing line (printed to stdout and
// read by docs/hardening.md's table).
struct Tally {
  int executions = 0;
  int accepted = 0;  // parsed / answered
  int refused = 0;   // the documented input error
  std::set<std::string> distinct_messages;  // first 60 characters, for coverage feel
  void print(const std::string& fuzzer, double seconds) const;
};

}  // namespace towdb::fuzz

#endif  // TOWDB_TESTS_FUZZ_FUZZ_SUPPORT_HPP
