// Deterministic, portable random streams (one per (seed, stream) pair).
//
// Generator: SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom
// number generators", OOPSLA 2014; the finaliser is Stafford's "Mix13"):
//   state_{n+1} = state_n + 0x9E3779B97F4A7C15   (mod 2^64)
//   out_n       = mix64(state_{n+1})
// A stream is keyed by (seed, stream): its starting state is
//   state_0 = mix64(mix64(seed) + 0xD1B54A32D192ED03 * (stream + 1)),
// so day d of a case with seed s is RandomStream(s, d) and needs no knowledge
// of the other days: days can be simulated in any order, on any thread, and
// give bit-identical results.
//
// Uniform doubles are built from the raw bits here (std::uniform_real_distribution
// is not specified bit-for-bit across standard libraries):
//   uniform01()      = (out >> 11) * 2^-53            in [0, 1)
//   uniform_open01() = ((out >> 11) + 0.5) * 2^-53    in (0, 1), never 0 or 1
#ifndef TOWDB_COMMON_RANDOM_HPP
#define TOWDB_COMMON_RANDOM_HPP

#include <cstdint>

namespace towdb {

// Stafford's Mix13 64-bit finaliser (bijective on 64-bit integers).
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t stream)
      : state_(mix64(mix64(seed) + 0xD1B54A32D192ED03ULL * (stream + 1))) {}

  std::uint64_t next_u64() {
    state_ += 0x9E3779B97F4A7C15ULL;
    return mix64(state_);
  }
  // Uniform on [0, 1) with 53 random bits.
  double uniform01() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
  // Uniform on the open interval (0, 1): safe for log(u) and quantile(u).
  double uniform_open01() { return (static_cast<double>(next_u64() >> 11) + 0.5) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

}  // namespace towdb

#endif  // TOWDB_COMMON_RANDOM_HPP
