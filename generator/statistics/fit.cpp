#include "statistics/fit.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::statistics {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();
// GEV shape bounds of EQ-STAT-7 [-].
constexpr double kShapeMin = -0.95;
constexpr double kShapeMax = 1.5;
// Below |xi z| = kSeriesLimit, log1p(a)/a and its xi-derivative use their
// Taylor series (truncation error ~ a^5 < 1e-15).
constexpr double kSeriesLimit = 1e-3;
// Relative step of the central-difference Hessian (standardised parameters ~ 1).
constexpr double kHessianStep = 1e-5;

struct Standardised {
  double mean = 0.0;
  double sd = 1.0;
  std::vector<double> y;
};

Standardised standardise(std::span<const double> sample) {
  Standardised s;
  const double n = static_cast<double>(sample.size());
  for (double x : sample) s.mean += x;
  s.mean /= n;
  double ss = 0.0;
  for (double x : sample) ss += (x - s.mean) * (x - s.mean);
  s.sd = std::sqrt(ss / (n - 1.0));
  s.y.reserve(sample.size());
  for (double x : sample) s.y.push_back((x - s.mean) / s.sd);
  return s;
}

// L(a) = log1p(a)/a and M(a) = (1/(1+a) - L(a))/a, so that with a = xi z:
// t = z L(a) and dt/dxi = z^2 M(a) (EQ-STAT-5, 7).
void log_ratio(double a, double& l, double& m) {
  if (std::abs(a) < kSeriesLimit) {
    l = 1.0 - a * (0.5 - a * (1.0 / 3.0 - a * (0.25 - a * 0.2)));
    m = -0.5 + a * (2.0 / 3.0 - a * (0.75 - a * 0.8));
  } else {
    l = std::log1p(a) / a;
    m = (1.0 / (1.0 + a) - l) / a;
  }
}

using Vec3 = Eigen::Vector3d;

// GEV log-likelihood of standardised data in theta = (mu, ln sigma, xi), with
// its gradient if `grad` is not null. -inf outside the support or the bounds.
double gev_loglik(const std::vector<double>& y, const Vec3& theta, Vec3* grad) {
  const double mu = theta[0];
  const double ls = theta[1];
  const double xi = theta[2];
  if (!(xi >= kShapeMin && xi <= kShapeMax) || !std::isfinite(mu) || !std::isfinite(ls)) return kNegInf;
  const double sigma = std::exp(ls);
  double sum = -static_cast<double>(y.size()) * ls;
  Vec3 g = Vec3::Zero();
  g[1] = -static_cast<double>(y.size());
  for (double yi : y) {
    const double z = (yi - mu) / sigma;
    const double a = xi * z;
    if (!(1.0 + a > 0.0)) return kNegInf;
    double l = 1.0;
    double m = -0.5;
    log_ratio(a, l, m);
    const double t = z * l;
    const double e = std::exp(-t);
    sum += -(1.0 + xi) * t - e;
    if (grad != nullptr) {
      const double d = e - (1.0 + xi);  // dl/dt
      const double dz = d / (1.0 + a);  // dl/dz
      g[0] += -dz / sigma;
      g[1] += -dz * z;
      g[2] += -t + d * z * z * m;
    }
  }
  if (grad != nullptr) *grad = g;
  return sum;
}

// Levenberg-damped Newton ascent from theta; returns false if it does not converge.
bool gev_newton(const std::vector<double>& y, Vec3& theta, const MlOptions& options, int& iterations,
                double& loglik) {
  Vec3 grad;
  loglik = gev_loglik(y, theta, &grad);
  if (!std::isfinite(loglik)) return false;
  double lambda = 1e-3;
  const double n = static_cast<double>(y.size());
  for (int it = 1; it <= options.max_iterations; ++it) {
    iterations = it;
    Eigen::Matrix3d hess;
    for (int c = 0; c < 3; ++c) {
      Vec3 tp = theta;
      Vec3 tm = theta;
      tp[c] += kHessianStep;
      tm[c] -= kHessianStep;
      Vec3 gp;
      Vec3 gm;
      const double lp = gev_loglik(y, tp, &gp);
      const double lm = gev_loglik(y, tm, &gm);
      if (!std::isfinite(lp) || !std::isfinite(lm)) {
        // At a support or shape bound: one-sided difference.
        if (std::isfinite(lp)) {
          hess.col(c) = (gp - grad) / kHessianStep;
        } else if (std::isfinite(lm)) {
          hess.col(c) = (grad - gm) / kHessianStep;
        } else {
          return false;
        }
      } else {
        hess.col(c) = (gp - gm) / (2.0 * kHessianStep);
      }
    }
    hess = 0.5 * (hess + hess.transpose()).eval();
    bool improved = false;
    Vec3 step = Vec3::Zero();
    // An active shape bound (xi at a limit, gradient pushing outward): Newton
    // in (mu, ln sigma) only, xi held.
    const bool hold_shape =
        (theta[2] <= kShapeMin && grad[2] <= 0.0) || (theta[2] >= kShapeMax && grad[2] >= 0.0);
    for (int tries = 0; tries < 40; ++tries) {
      Eigen::Matrix3d a = -hess;
      for (int c = 0; c < 3; ++c) a(c, c) += lambda * std::max(std::abs(hess(c, c)), 1.0);
      Vec3 rhs = grad;
      if (hold_shape) {
        a.row(2).setZero();
        a.col(2).setZero();
        a(2, 2) = 1.0;
        rhs[2] = 0.0;
      }
      step = a.ldlt().solve(rhs);
      if (!step.allFinite()) {
        lambda = std::max(lambda * 10.0, 1e-6);
        continue;
      }
      Vec3 trial = theta + step;
      trial[2] = std::clamp(trial[2], kShapeMin, kShapeMax);
      step = trial - theta;
      Vec3 trial_grad;
      const double trial_ll = gev_loglik(y, trial, &trial_grad);
      if (std::isfinite(trial_ll) && trial_ll >= loglik - 1e-12 * std::abs(loglik)) {
        theta = trial;
        grad = trial_grad;
        loglik = trial_ll;
        lambda = std::max(lambda * 0.1, 1e-12);
        improved = true;
        break;
      }
      lambda = std::max(lambda * 10.0, 1e-6);
    }
    if (!improved) return false;
    // Converged: a negligible step with a gradient that is small (or pushes
    // against an active shape bound).
    const bool at_bound = (theta[2] <= kShapeMin && grad[2] < 0.0) || (theta[2] >= kShapeMax && grad[2] > 0.0);
    const double grad_norm = at_bound ? grad.head<2>().lpNorm<Eigen::Infinity>() : grad.lpNorm<Eigen::Infinity>();
    if (step.lpNorm<Eigen::Infinity>() < options.relative_tolerance && grad_norm < 1e-6 * n) return true;
    if (grad_norm < 1e-9 * n && step.lpNorm<Eigen::Infinity>() < 1e-6) return true;
  }
  return false;
}

// Nelder-Mead simplex maximisation (fallback), Lagarias et al. (1998) coefficients.
bool gev_nelder_mead(const std::vector<double>& y, Vec3& theta, int max_evaluations, double& loglik,
                     int& evaluations) {
  std::array<Vec3, 4> simplex;
  std::array<double, 4> value;
  simplex[0] = theta;
  for (int c = 0; c < 3; ++c) {
    simplex[static_cast<std::size_t>(c) + 1] = theta;
    simplex[static_cast<std::size_t>(c) + 1][c] += 0.1;
  }
  auto f = [&](const Vec3& t) { return -gev_loglik(y, t, nullptr); };  // minimise
  for (std::size_t i = 0; i < 4; ++i) value[i] = f(simplex[i]);
  evaluations = 4;
  while (evaluations < max_evaluations) {
    std::array<std::size_t, 4> order = {0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return value[a] < value[b]; });
    const std::size_t best = order[0];
    const std::size_t worst = order[3];
    const std::size_t second = order[2];
    if (std::isfinite(value[worst]) && value[worst] - value[best] < 1e-13 * (1.0 + std::abs(value[best]))) {
      theta = simplex[best];
      loglik = -value[best];
      return std::isfinite(loglik);
    }
    Vec3 centroid = Vec3::Zero();
    for (std::size_t i = 0; i < 4; ++i) {
      if (i != worst) centroid += simplex[i] / 3.0;
    }
    const Vec3 reflected = centroid + (centroid - simplex[worst]);
    const double fr = f(reflected);
    ++evaluations;
    if (fr < value[best]) {
      const Vec3 expanded = centroid + 2.0 * (centroid - simplex[worst]);
      const double fe = f(expanded);
      ++evaluations;
      if (fe < fr) {
        simplex[worst] = expanded;
        value[worst] = fe;
      } else {
        simplex[worst] = reflected;
        value[worst] = fr;
      }
    } else if (fr < value[second]) {
      simplex[worst] = reflected;
      value[worst] = fr;
    } else {
      const bool outside = fr < value[worst];
      const Vec3 contracted = outside ? centroid + 0.5 * (reflected - centroid)
                                      : centroid + 0.5 * (simplex[worst] - centroid);
      const double fc = f(contracted);
      ++evaluations;
      if (fc < (outside ? fr : value[worst])) {
        simplex[worst] = contracted;
        value[worst] = fc;
      } else {
        for (std::size_t i = 0; i < 4; ++i) {
          if (i == best) continue;
          simplex[i] = simplex[best] + 0.5 * (simplex[i] - simplex[best]);
          value[i] = f(simplex[i]);
          ++evaluations;
        }
      }
    }
  }
  return false;
}

}  // namespace

void MlOptions::validate() const {
  require_input(max_iterations >= 5 && max_iterations <= 10000, "ml.max_iterations", max_iterations,
                "must be an integer from 5 to 10000");
  require_in_range("ml.relative_tolerance", relative_tolerance, 1e-15, 1e-3);
}

Gumbel gumbel_from_moments(double mean, double variance) {
  require_input(std::isfinite(mean), "gumbel moments: mean", mean, "must be finite");
  require_input(std::isfinite(variance) && variance > 0.0, "gumbel moments: variance", variance,
                "must be finite and > 0");
  // EQ-STAT-3: alpha = pi / (sigma sqrt 6), u = mean - gamma_E / alpha.
  const double alpha = kPi / (std::sqrt(variance) * std::sqrt(6.0));
  return Gumbel{mean - kEulerGamma / alpha, 1.0 / alpha};
}

Gumbel fit_gumbel_moments(std::span<const double> sample) {
  require_fit_sample(sample, 3, "gumbel moment fit");
  const Standardised s = standardise(sample);
  return gumbel_from_moments(s.mean, s.sd * s.sd);
}

double gumbel_log_likelihood(std::span<const double> sample, const Gumbel& dist) {
  dist.validate();
  double sum = 0.0;
  for (double x : sample) {
    const double z = (x - dist.location) / dist.scale;
    sum += -std::log(dist.scale) - z - std::exp(-z);
  }
  return sum;
}

double gev_log_likelihood(std::span<const double> sample, const Gev& dist) {
  dist.validate();
  double sum = 0.0;
  for (double x : sample) {
    const double p = dist.pdf(x);
    if (!(p > 0.0)) return kNegInf;
    sum += std::log(p);
  }
  return sum;
}

GumbelFit fit_gumbel_ml(std::span<const double> sample, const MlOptions& options) {
  options.validate();
  require_fit_sample(sample, 3, "gumbel ML fit");
  const Standardised s = standardise(sample);
  const double y_min = *std::min_element(s.y.begin(), s.y.end());
  // EQ-STAT-6 on standardised data (mean 0): g(beta) and g'(beta), weights
  // exp(-(y - y_min)/beta) <= 1 so that nothing overflows.
  double sum_w = 0.0;
  auto eval = [&](double beta, double& deriv) {
    double sw = 0.0;
    double swy = 0.0;
    double swyy = 0.0;
    for (double yi : s.y) {
      const double d = yi - y_min;
      const double w = std::exp(-d / beta);
      sw += w;
      swy += w * d;
      swyy += w * d * d;
    }
    const double wmean = swy / sw;
    const double wvar = std::max(0.0, swyy / sw - wmean * wmean);
    deriv = 1.0 + wvar / (beta * beta);
    sum_w = sw;
    return beta + y_min + wmean;  // beta - mean(y) + weighted mean of y, mean(y) = 0
  };
  double deriv = 0.0;
  double lo = 1e-3;
  double hi = 1.0;
  int guard = 0;
  while (eval(lo, deriv) >= 0.0 && guard++ < 60) lo *= 0.5;
  guard = 0;
  while (eval(hi, deriv) <= 0.0 && guard++ < 60) hi *= 2.0;
  double beta = std::clamp(std::sqrt(6.0) / kPi, lo, hi);  // moments estimate (sd = 1)
  double g = eval(beta, deriv);
  int it = 0;
  for (it = 1; it <= options.max_iterations; ++it) {
    if (g < 0.0) {
      lo = beta;
    } else {
      hi = beta;
    }
    double next = beta - g / deriv;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // bisection safeguard
    const double change = std::abs(next - beta);
    beta = next;
    g = eval(beta, deriv);
    if (change < options.relative_tolerance * beta || hi - lo < options.relative_tolerance * beta) break;
  }
  if (it > options.max_iterations || !std::isfinite(beta)) {
    throw NumericalError("gumbel ML (safeguarded Newton on EQ-STAT-6): no convergence after " +
                         std::to_string(options.max_iterations) + " iterations, residual g(beta) = " +
                         format_value(g));
  }
  eval(beta, deriv);
  const double mu_y = y_min - beta * std::log(sum_w / static_cast<double>(s.y.size()));
  GumbelFit fit;
  fit.distribution = Gumbel{s.mean + s.sd * mu_y, s.sd * beta};
  fit.log_likelihood = gumbel_log_likelihood(sample, fit.distribution);
  fit.iterations = it;
  return fit;
}

Gev fit_gev_lmoments(std::span<const double> sample) {
  require_fit_sample(sample, 3, "GEV L-moment fit");
  std::vector<double> x(sample.begin(), sample.end());
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  // Unbiased probability-weighted moments b0, b1, b2 (Hosking et al. 1985).
  double b0 = 0.0;
  double b1 = 0.0;
  double b2 = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = static_cast<double>(i);  // i-1 in 1-based notation
    b0 += x[i];
    b1 += x[i] * r / (n - 1.0);
    b2 += x[i] * r * (r - 1.0) / ((n - 1.0) * (n - 2.0));
  }
  b0 /= n;
  b1 /= n;
  b2 /= n;
  const double l1 = b0;
  const double l2 = 2.0 * b1 - b0;
  const double l3 = 6.0 * b2 - 6.0 * b1 + b0;
  const double tau3 = l3 / l2;
  // Hosking's approximation for k = -xi (accurate to 9e-4 for tau3 in [-0.5, 0.5]).
  const double c = 2.0 / (3.0 + tau3) - std::log(2.0) / std::log(3.0);
  double k = 7.8590 * c + 2.9554 * c * c;
  k = std::clamp(k, -kShapeMax, -kShapeMin);
  if (std::abs(k) < 1e-8) {
    const double scale = l2 / std::log(2.0);
    return Gev{l1 - kEulerGamma * scale, scale, 0.0};
  }
  const double g1k = std::tgamma(1.0 + k);
  const double scale = l2 * k / ((1.0 - std::pow(2.0, -k)) * g1k);
  return Gev{l1 - scale * (1.0 - g1k) / k, scale, -k};
}

GevFit fit_gev_ml(std::span<const double> sample, const MlOptions& options) {
  options.validate();
  require_fit_sample(sample, 10, "GEV ML fit");
  const Standardised s = standardise(sample);
  auto to_theta = [&](const Gev& d) {
    return Vec3((d.location - s.mean) / s.sd, std::log(d.scale / s.sd), d.shape);
  };
  // Start 1: L-moments; start 2: Gumbel ML (xi = 0 always covers the data).
  std::vector<Vec3> starts;
  const Vec3 lmom = to_theta(fit_gev_lmoments(sample));
  if (std::isfinite(gev_loglik(s.y, lmom, nullptr))) starts.push_back(lmom);
  const GumbelFit gum = fit_gumbel_ml(sample, options);
  starts.push_back(to_theta(Gev{gum.distribution.location, gum.distribution.scale, 0.0}));

  GevFit fit;
  Vec3 theta;
  double ll = kNegInf;
  bool ok = false;
  for (const Vec3& start : starts) {
    theta = start;
    int iterations = 0;
    if (gev_newton(s.y, theta, options, iterations, ll)) {
      ok = true;
      fit.iterations = iterations;
      break;
    }
  }
  if (!ok) {
    theta = starts.back();
    int evaluations = 0;
    ok = gev_nelder_mead(s.y, theta, 200 * options.max_iterations, ll, evaluations);
    fit.iterations = evaluations;
    fit.used_fallback = true;
    if (!ok) {
      throw NumericalError("GEV ML (damped Newton, then Nelder-Mead, EQ-STAT-7): no convergence after " +
                           std::to_string(evaluations) + " evaluations, log-likelihood " + format_value(ll));
    }
  }
  fit.distribution = Gev{s.mean + s.sd * theta[0], s.sd * std::exp(theta[1]), theta[2]};
  fit.shape_at_bound = theta[2] <= kShapeMin || theta[2] >= kShapeMax;
  fit.log_likelihood = ll - static_cast<double>(s.y.size()) * std::log(s.sd);
  return fit;
}

}  // namespace towdb::statistics
