// towdb::statistics -- extreme-value statistics of the daily maximum dynamic
// tensions (thesis chapter 4 and Appendix B; docs/physics.md section 7).
//
// ============================================================================
// GOVERNING EQUATIONS
// ============================================================================
// Units: the module is unit-agnostic. Every location, scale, quantile and
// sample value carries the unit of the sample (towdb passes tensions in N);
// alpha has the inverse unit; probabilities and the GEV shape are [-].
//
// EQ-STAT-1  Empirical distribution of N ordered maxima x_(1) <= ... <= x_(N)
//            (Weibull plotting position, thesis eq. 4-1):
//              F_i = i / (N + 1);
//            about N = 5 / (1 - F) samples are needed at probability F (eq. 4-2).
//            Quantiles between plotting positions: linear in F.
// EQ-STAT-2  Gumbel (Type I asymptotic distribution of maxima, Gumbel 1958):
//              F(x) = exp(-exp(-alpha (x - u))),     alpha = 1/scale > 0
//              mean = u + gamma_E/alpha,   variance = pi^2 / (6 alpha^2)
//              x_F  = u - ln(-ln F) / alpha          (gamma_E = 0.5772156649)
// EQ-STAT-3  Method of moments (thesis eq. 4-5, 4-6; Rao 1992), sample mean mu
//            and unbiased variance sigma^2 = sum (x - mu)^2 / (N - 1):
//              alpha = pi / (sigma sqrt 6),   u = mu - gamma_E / alpha.
//            Check (thesis Appendix A, calcstat output): mu = 41.06, sigma^2 = 10.80
//            -> x_0.999 = 57.27 (kips).
// EQ-STAT-4  Maximum over D independent blocks (a tow of D days): F_D = F^D, so
//              Gumbel:  u_D = u + ln(D) / alpha,  same alpha;
//              GEV:     mu_D = mu + sigma (D^xi - 1)/xi,  sigma_D = sigma D^xi,  same xi.
// EQ-STAT-5  Generalised extreme value (Jenkinson 1955; Coles 2001 eq. 3.2):
//              F(x) = exp(-(1 + xi z)^(-1/xi)),  z = (x - mu)/sigma,  1 + xi z > 0,
//              xi -> 0 gives EQ-STAT-2 (u = mu, alpha = 1/sigma);
//              x_F = mu + sigma ((-ln F)^(-xi) - 1) / xi.
//            Numerically, t = log1p(xi z)/xi (t = z at xi = 0) so that
//              (1 + xi z)^(-1/xi) = exp(-t),  continuous through xi = 0.
// EQ-STAT-6  Gumbel maximum likelihood (Coles 2001 3.3.2): with beta = 1/alpha,
//              g(beta) = beta - mean(x) + sum x e^(-x/beta) / sum e^(-x/beta) = 0,
//              u = -beta ln( mean(e^(-x/beta)) ).
//            g' = 1 + Var_w(x)/beta^2 > 0: one root, bracketed between 0+ (g < 0)
//            and a beta with g > 0; safeguarded Newton (bisection fallback).
// EQ-STAT-7  GEV maximum likelihood, parameters (mu, ln sigma, xi):
//              l = -N ln sigma - (1 + xi) sum t_i - sum exp(-t_i),
//            maximised by Levenberg-damped Newton (analytic gradient, Hessian by
//            central differences of the gradient), started from the L-moment
//            estimates of Hosking, Wallis & Wood (1985); Nelder-Mead restart as
//            the fallback. xi is confined to [-0.95, 1.5] (l is unbounded for
//            xi < -1; xi > 1.5 has no finite mean); at an active bound the
//            Newton step holds xi and the fit reports shape_at_bound (small
//            samples of bounded tails do this). Data are standardised first.
// EQ-STAT-8  Parametric bootstrap percentile interval for x_F (Efron &
//            Tibshirani 1993 ch. 13): fit; draw R samples of size N from the fit
//            with RandomStream(seed, replicate) and x = quantile(U), U in (0,1);
//            refit each; the interval is the ((1-level)/2, (1+level)/2) quantiles
//            (linear interpolation, Hyndman & Fan type 7) of the R estimates.
// EQ-STAT-9  Goodness of fit of a fitted F to the ordered sample:
//              Anderson-Darling (1954) A^2 = -N - (1/N) sum_{i=1}^N (2i - 1)
//                                 [ln F(x_(i)) + ln(1 - F(x_(N+1-i)))];
//              for a fully specified F, E[A^2] = 1 for every N (and P(A^2 > 2.492) = 5%
//              asymptotically, Stephens 1974);
//              probability-plot correlation r = corr(x_(i), x_F(F_i)), F_i of EQ-STAT-1.
//
// SOURCES
//   Desroches (1997) MIT thesis ch. 4, Appendix A/B; Gumbel (1958) Statistics
//   of Extremes; Coles (2001) An Introduction to Statistical Modeling of
//   Extreme Values, Springer (ch. 3); Hosking, Wallis & Wood (1985)
//   Technometrics 27(3); Stephens (1974) JASA 69(347); Efron & Tibshirani (1993).
//
// CONVENTIONS
//   Upper tails (maxima). F is a non-exceedance probability in (0, 1). Errors:
//   bad samples or options throw towdb::InputError naming field, value and what
//   is allowed; a fit that does not converge throws towdb::NumericalError.
#ifndef TOWDB_STATISTICS_STATISTICS_HPP
#define TOWDB_STATISTICS_STATISTICS_HPP

#include "statistics/bootstrap.hpp"
#include "statistics/distributions.hpp"
#include "statistics/fit.hpp"
#include "statistics/goodness_of_fit.hpp"

#endif  // TOWDB_STATISTICS_STATISTICS_HPP
