// Lanes: K doubles that act as one number, for integrating K independent days
// in lock step (simulation/surge.hpp, integrate_days). Lanes<K, W> holds them
// as K/W native vectors of W doubles (GCC vector extensions); the lanes::
// helpers (max, min, clamp, select, any, splat) are written so that double
// and Lanes<K, W> give the same IEEE results lane by lane, which lets a
// tension law be written once as a template on the number type.
//
// Bit-identity needs every target built without fused multiply-add
// (-ffp-contract=off, cmake/TowdbHelpers.cmake).
#ifndef TOWDB_SIMULATION_LANES_HPP
#define TOWDB_SIMULATION_LANES_HPP

#include <cstddef>
#include <cstdint>
#include <type_traits>

// The RK4 loop's helpers must be inlined into it (GCC 12 otherwise keeps
// SurgeKernel::derivative out of line: 25 % slower per step).
#if defined(__GNUC__)
#define TOWDB_SURGE_INLINE [[gnu::always_inline]] inline
#else
#define TOWDB_SURGE_INLINE inline
#endif

namespace towdb::simulation {

// Element-wise arithmetic shared by the scalar and the lock-step paths. Each
// helper is exactly the comparison-and-choice of the std:: function named,
// so double and Lanes<K, W> give the same bits lane by lane.
namespace lanes {

// Native vectors of W doubles and their comparison masks: W = 2 is the
// baseline x86-64 vector (SSE2), W = 4 an AVX register, used only inside
// functions compiled for AVX2 (integrate_days_avx2).
template <std::size_t W>
struct Native;
template <>
struct Native<2> {
  typedef double Vector __attribute__((vector_size(16)));
  typedef std::int64_t Mask __attribute__((vector_size(16)));
  // For loads from double arrays: any alignment, aliasing doubles.
  typedef double Unaligned __attribute__((vector_size(16), aligned(8), may_alias));
};
template <>
struct Native<4> {
  typedef double Vector __attribute__((vector_size(32)));
  typedef std::int64_t Mask __attribute__((vector_size(32)));
  typedef double Unaligned __attribute__((vector_size(32), aligned(8), may_alias));
};

// K doubles as K/W native vectors ("parts"): every operation acts on the
// parts independently, so K = 4 on SSE2 gives the processor two independent
// dependency chains. (GCC's generic K-double vectors are lowered to slow
// code when the target lacks them.)
template <std::size_t K, std::size_t W = 2>
struct Lanes {
  static_assert((W == 2 || W == 4) && K % W == 0 && K >= W && K <= 8, "lanes: K = 2, 4 or 8 doubles in parts of W");
  static constexpr std::size_t kParts = K / W;
  typedef typename Native<W>::Vector Part;
  Part h[kParts];
  double operator[](std::size_t l) const { return h[l / W][l % W]; }
  void set(std::size_t l, double x) { h[l / W][l % W] = x; }
};

// A lane-wise comparison: -1 where it holds, 0 elsewhere (also used as counts).
template <std::size_t K, std::size_t W = 2>
struct LaneMask {
  typename Native<W>::Mask h[K / W];
  std::int64_t operator[](std::size_t l) const { return h[l / W][l % W]; }
  void set(std::size_t l, std::int64_t x) { h[l / W][l % W] = x; }
};

#define TOWDB_LANES_BINARY(OP, RESULT)                                                   \
  template <std::size_t K, std::size_t W>                                                \
  TOWDB_SURGE_INLINE RESULT<K, W> operator OP(const Lanes<K, W>& a, const Lanes<K, W>& b) { \
    RESULT<K, W> r;                                                                      \
    for (std::size_t i = 0; i < K / W; ++i) r.h[i] = a.h[i] OP b.h[i];                   \
    return r;                                                                            \
  }                                                                                      \
  template <std::size_t K, std::size_t W>                                                \
  TOWDB_SURGE_INLINE RESULT<K, W> operator OP(const Lanes<K, W>& a, double b) {          \
    RESULT<K, W> r;                                                                      \
    for (std::size_t i = 0; i < K / W; ++i) r.h[i] = a.h[i] OP b;                        \
    return r;                                                                            \
  }                                                                                      \
  template <std::size_t K, std::size_t W>                                                \
  TOWDB_SURGE_INLINE RESULT<K, W> operator OP(double a, const Lanes<K, W>& b) {          \
    RESULT<K, W> r;                                                                      \
    for (std::size_t i = 0; i < K / W; ++i) r.h[i] = a OP b.h[i];                        \
    return r;                                                                            \
  }
TOWDB_LANES_BINARY(+, Lanes)
TOWDB_LANES_BINARY(-, Lanes)
TOWDB_LANES_BINARY(*, Lanes)
TOWDB_LANES_BINARY(/, Lanes)
TOWDB_LANES_BINARY(<, LaneMask)
TOWDB_LANES_BINARY(<=, LaneMask)
TOWDB_LANES_BINARY(>, LaneMask)
TOWDB_LANES_BINARY(!=, LaneMask)
#undef TOWDB_LANES_BINARY

template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE Lanes<K, W> operator-(const Lanes<K, W>& a) {
  Lanes<K, W> r;
  for (std::size_t i = 0; i < K / W; ++i) r.h[i] = -a.h[i];
  return r;
}
template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE Lanes<K, W>& operator+=(Lanes<K, W>& a, const Lanes<K, W>& b) {
  return a = a + b;
}
template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE LaneMask<K, W> operator&(const LaneMask<K, W>& a, const LaneMask<K, W>& b) {
  LaneMask<K, W> r;
  for (std::size_t i = 0; i < K / W; ++i) r.h[i] = a.h[i] & b.h[i];
  return r;
}
template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE LaneMask<K, W> operator~(const LaneMask<K, W>& a) {
  LaneMask<K, W> r;
  for (std::size_t i = 0; i < K / W; ++i) r.h[i] = ~a.h[i];
  return r;
}
template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE LaneMask<K, W>& operator-=(LaneMask<K, W>& a, const LaneMask<K, W>& b) {
  for (std::size_t i = 0; i < K / W; ++i) a.h[i] -= b.h[i];
  return a;
}

// x in every lane (x itself for double).
template <typename T>
TOWDB_SURGE_INLINE T splat(double x) {
  if constexpr (std::is_same_v<T, double>) {
    return x;
  } else {
    // A vector literal (a broadcast): lane-by-lane stores read back as a
    // vector would stall store forwarding.
    typedef typename T::Part Part;
    T r;
    for (std::size_t i = 0; i < T::kParts; ++i) {
      if constexpr (sizeof(Part) == 2 * sizeof(double)) {
        r.h[i] = Part{x, x};
      } else {
        r.h[i] = Part{x, x, x, x};
      }
    }
    return r;
  }
}
// cond ? a : b, lane by lane.
TOWDB_SURGE_INLINE double select(bool cond, double a, double b) { return cond ? a : b; }
template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE Lanes<K, W> select(const LaneMask<K, W>& cond, const Lanes<K, W>& a, const Lanes<K, W>& b) {
  Lanes<K, W> r;
  for (std::size_t i = 0; i < K / W; ++i) r.h[i] = cond.h[i] ? a.h[i] : b.h[i];
  return r;
}
// The negation of a comparison, lane by lane.
TOWDB_SURGE_INLINE bool negate(bool cond) { return !cond; }
template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE LaneMask<K, W> negate(const LaneMask<K, W>& cond) {
  return ~cond;
}
// Whether any lane of a comparison holds (the comparison itself for double):
// lets a law skip work that no lane needs, as the scalar code's branch does.
TOWDB_SURGE_INLINE bool any(bool cond) { return cond; }
template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE bool any(const LaneMask<K, W>& cond) {
  typename Native<W>::Mask r = cond.h[0];
  for (std::size_t i = 1; i < K / W; ++i) r |= cond.h[i];
  std::int64_t o = r[0];
  for (std::size_t l = 1; l < W; ++l) o |= r[l];
  return o != 0;
}
template <typename T>
TOWDB_SURGE_INLINE T max(T a, T b) {  // std::max: a < b ? b : a
  return select(a < b, b, a);
}
template <typename T>
TOWDB_SURGE_INLINE T min(T a, T b) {  // std::min: b < a ? b : a
  return select(b < a, b, a);
}
template <typename T>
TOWDB_SURGE_INLINE T clamp(T v, double lo, double hi) {  // std::clamp
  const T l = splat<T>(lo), h = splat<T>(hi);
  return select(v < l, l, select(h < v, h, v));
}

}  // namespace lanes

}  // namespace towdb::simulation

#endif  // TOWDB_SIMULATION_LANES_HPP
