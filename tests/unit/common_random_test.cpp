// The deterministic random streams of common/random.hpp.
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "common/random.hpp"
#include "test_support.hpp"

namespace towdb {
namespace {

TEST(CommonRandom, Mix64MatchesSplitMix64ReferenceOutputs) {
  // SplitMix64 from state 0 (Steele, Lea & Flood 2014; Vigna's reference
  // splitmix64.c): outputs mix64(k * 0x9E3779B97F4A7C15) for k = 1..4.
  const std::uint64_t expected[] = {0xE220A8397B1DCDAFULL, 0x6E789E6AA1B965F4ULL, 0x06C45D188009454FULL,
                                    0xF88BB8A8724C81ECULL};
  std::uint64_t state = 0;
  for (std::uint64_t e : expected) {
    state += 0x9E3779B97F4A7C15ULL;
    EXPECT_EQ(mix64(state), e);
  }
}

TEST(CommonRandom, UniformMomentsAndStreamIndependence) {
  // Uniform on [0, 1): mean 1/2, variance 1/12. N = 1e6 draws: standard errors
  // 2.9e-4 (mean) and 7.5e-5 (variance); tolerance 5 standard errors. Two
  // streams (days) of one seed are uncorrelated: |r| < 5 / sqrt(N).
  constexpr int kDraws = 1000000;
  RandomStream a(1997, 0);
  RandomStream b(1997, 1);
  double sa = 0.0, saa = 0.0, sab = 0.0, sb = 0.0, sbb = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = a.uniform01();
    const double y = b.uniform_open01();
    ASSERT_TRUE(x >= 0.0 && x < 1.0);
    ASSERT_TRUE(y > 0.0 && y < 1.0);
    sa += x;
    saa += x * x;
    sb += y;
    sbb += y * y;
    sab += x * y;
  }
  const double n = kDraws;
  const double mean = sa / n;
  const double var = saa / n - mean * mean;
  EXPECT_ABS_CLOSE(mean, 0.5, 5.0 * 2.9e-4);
  EXPECT_ABS_CLOSE(var, 1.0 / 12.0, 5.0 * 7.5e-5);
  const double mb = sb / n;
  const double cov = sab / n - mean * mb;
  const double r = cov / std::sqrt(var * (sbb / n - mb * mb));
  EXPECT_LT(std::abs(r), 5.0 / std::sqrt(n));
}

TEST(CommonRandom, SameKeySameBitsOtherKeyOtherBits) {
  RandomStream a(7, 3);
  RandomStream b(7, 3);
  RandomStream c(7, 4);
  RandomStream d(8, 3);
  for (int i = 0; i < 100; ++i) {
    const std::uint64_t x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    EXPECT_NE(x, c.next_u64());
    EXPECT_NE(x, d.next_u64());
  }
}

}  // namespace
}  // namespace towdb
