// Gauss-Legendre quadrature nodes and weights on an interval (Golub-Welsch
// is not needed for the small orders used here: Newton iteration on P_n).
#ifndef TOWDB_SEAKEEPING_GAUSS_LEGENDRE_HPP
#define TOWDB_SEAKEEPING_GAUSS_LEGENDRE_HPP

#include <vector>

namespace towdb::seakeeping {

struct QuadratureRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

// n-point rule on [lo, hi], nodes increasing; exact for polynomials of degree
// 2n - 1 (Abramowitz & Stegun 25.4.29). Throws InputError for n < 1.
QuadratureRule gauss_legendre(int n, double lo, double hi);

// The same rule, computed once per (n, lo, hi) for the whole process and kept:
// the section solver asks for the same few rules at every section and
// frequency. Thread-safe; the reference stays valid until exit.
const QuadratureRule& cached_gauss_legendre(int n, double lo, double hi);

}  // namespace towdb::seakeeping

#endif  // TOWDB_SEAKEEPING_GAUSS_LEGENDRE_HPP
