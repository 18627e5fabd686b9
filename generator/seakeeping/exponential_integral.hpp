// Complex exponential integral E1(w) and the scaled function G(w) = e^w E1(w),
// used by the free-surface wave source of the Ursell-Tasai section solver.
//
//   E1(w) = integral_w^inf e^-t / t dt, principal branch, cut on the negative
//   real axis; on the cut itself (Im w = +0) the upper-side value is returned
//   (arg w = +pi), which is what the section solver needs (see section.hpp).
// Methods (Abramowitz & Stegun 1964, 5.1.11 and 5.1.22):
//   series      E1(w) = -gamma - ln w - sum_{n>=1} (-w)^n / (n n!)
//   continued fraction (even form, modified Lentz)
//               e^w E1(w) = 1/(w+1- 1/(w+3- 4/(w+5- 9/(w+7- ...))))
// The series loses about (|w| + Re w)/ln 10 digits to cancellation, the
// fraction converges slowly near the negative real axis; the cheaper accurate
// one is chosen by that loss estimate.
#ifndef TOWDB_SEAKEEPING_EXPONENTIAL_INTEGRAL_HPP
#define TOWDB_SEAKEEPING_EXPONENTIAL_INTEGRAL_HPP

#include <complex>

namespace towdb::seakeeping {

// G(w) = e^w E1(w) for w != 0 (throws InputError at w = 0, NumericalError if
// the continued fraction does not converge).
std::complex<double> scaled_exponential_integral(std::complex<double> w);

// E1(w) = e^-w G(w).
std::complex<double> exponential_integral_e1(std::complex<double> w);

}  // namespace towdb::seakeeping

#endif  // TOWDB_SEAKEEPING_EXPONENTIAL_INTEGRAL_HPP
