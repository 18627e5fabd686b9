#include "model/hull_form.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/error.hpp"

namespace towdb::model {

namespace {

// Prismatic coefficients this close to 1 are the box limit (EQ-HULLFORM-7).
constexpr double kBoxPrismaticThreshold = 1.0 - 1e-12;
// Bracket of the power-law exponents n, p (EQ-HULLFORM-2, -5): 1e-6 is an
// almost empty half (a ~ 0 except at midships), 1e6 an almost full one.
constexpr double kMinExponent = 1e-6;
constexpr double kMaxExponent = 1e6;

// One half of the normalised station grid: |xi_j| in (0, 1] and the
// trapezoid weight of each station in xi (EQ-HULLFORM-1, -4).
struct HalfGrid {
  std::vector<double> abs_xi;
  std::vector<double> weight;
  double midship_weight = 0.0;  // weight of the station at xi = 0 (0 if N is even)

  // sum_j w_j (1 - |xi_j|^n): the half's area sum in units of A_M L/2.
  double area(double exponent) const {
    double sum = 0.0;
    for (std::size_t j = 0; j < abs_xi.size(); ++j) {
      sum += weight[j] * (1.0 - std::pow(abs_xi[j], exponent));
    }
    return sum;
  }
  // sum_j w_j |xi_j| (1 - |xi_j|^n): the half's first moment about midships.
  double moment(double exponent) const {
    double sum = 0.0;
    for (std::size_t j = 0; j < abs_xi.size(); ++j) {
      sum += weight[j] * abs_xi[j] * (1.0 - std::pow(abs_xi[j], exponent));
    }
    return sum;
  }
};

double xi_of(int i, int n) {
  return static_cast<double>(2 * i - (n - 1)) / static_cast<double>(n - 1);
}

HalfGrid make_half_grid(int station_count) {
  HalfGrid grid;
  const double step = 2.0 / static_cast<double>(station_count - 1);
  for (int i = 0; i < station_count; ++i) {
    const double xi = xi_of(i, station_count);
    const bool end = (i == 0 || i == station_count - 1);
    const double w = end ? 0.5 * step : step;
    if (xi == 0.0) {
      grid.midship_weight = w;
    } else if (xi > 0.0) {
      grid.abs_xi.push_back(xi);
      grid.weight.push_back(w);
    }
  }
  return grid;
}

// Inverts the (increasing) half-area sum: the exponent n with area(n) = target.
// Bisection on ln n, deterministic.
double solve_exponent(const HalfGrid& grid, double target, const HullFormOptions& options,
                      const char* what) {
  double lo = std::log(kMinExponent);
  double hi = std::log(kMaxExponent);
  const double tol = options.relative_tolerance * std::max(target, 1e-300);
  double mid = 0.5 * (lo + hi);
  double residual = 0.0;
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    mid = 0.5 * (lo + hi);
    residual = grid.area(std::exp(mid)) - target;
    if (std::abs(residual) <= tol) return std::exp(mid);
    if (residual < 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  throw NumericalError(std::string("hull form: bisection for the ") + what +
                       " exponent did not converge: iteration " +
                       std::to_string(options.max_iterations) + ", residual " +
                       format_value(residual) + " (tolerance " + format_value(tol) + ")");
}

struct AreaFit {
  double exponent_fore = 0.0;
  double exponent_aft = 0.0;
};

// EQ-HULLFORM-4: finds (n_f, n_a) with area_f + area_a = area_halves and
// moment_f - moment_a = moment_target. The fore half's area t is the
// unknown; moment(t) is increasing in t, so bisection on t brackets it.
AreaFit fit_area_curve(const HalfGrid& grid, double area_halves, double moment_target,
                       const HullFormParticulars& p, const HullFormOptions& options) {
  const double area_min = grid.area(kMinExponent);
  const double area_max = grid.area(kMaxExponent);
  const double t_lo = std::max(area_min, area_halves - area_max);
  const double t_hi = std::min(area_max, area_halves - area_min);
  if (!(t_lo < t_hi)) {
    throw InputError("block_coefficient / midship_coefficient = prismatic coefficient " +
                     format_value(p.prismatic_coefficient()) +
                     ": a power-law area curve with pointed ends cannot reach it on " +
                     std::to_string(options.station_count) +
                     " stations (each half's trapezoid fullness is at most 1 - 1/(N-1)); "
                     "use more stations");
  }
  auto moment_of = [&](double t, AreaFit* fit) {
    fit->exponent_fore = solve_exponent(grid, t, options, "fore area");
    fit->exponent_aft = solve_exponent(grid, area_halves - t, options, "aft area");
    return grid.moment(fit->exponent_fore) - grid.moment(fit->exponent_aft);
  };
  AreaFit fit;
  const double m_lo = moment_of(t_lo, &fit);
  const double m_hi = moment_of(t_hi, &fit);
  if (moment_target < m_lo || moment_target > m_hi) {
    const double total = area_halves + grid.midship_weight;
    const double to_lcb_m = 0.5 * p.length_pp_m / total;
    throw InputError("lcb_m = " + format_value(p.lcb_m) +
                     ": with prismatic coefficient " + format_value(p.prismatic_coefficient()) +
                     " the power-law area curve can place the LCB only between " +
                     format_value(m_lo * to_lcb_m) + " and " + format_value(m_hi * to_lcb_m) +
                     " m from midships");
  }
  double lo = t_lo;
  double hi = t_hi;
  const double tol = options.relative_tolerance * (area_halves + grid.midship_weight);
  double residual = 0.0;
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    const double t = 0.5 * (lo + hi);
    residual = moment_of(t, &fit) - moment_target;
    if (std::abs(residual) <= tol) return fit;
    if (residual < 0.0) {
      lo = t;
    } else {
      hi = t;
    }
  }
  throw NumericalError("hull form: bisection for the LCB did not converge: iteration " +
                       std::to_string(options.max_iterations) + ", residual " +
                       format_value(residual) + " (tolerance " + format_value(tol) + ")");
}

}  // namespace

void HullFormParticulars::validate() const {
  require_positive("length_pp_m", length_pp_m);
  require_positive("beam_m", beam_m);
  require_positive("draft_m", draft_m);
  require_input(std::isfinite(block_coefficient) && block_coefficient > 0.0 &&
                    block_coefficient <= 1.0,
                "block_coefficient", block_coefficient, "must be in (0, 1]");
  require_input(std::isfinite(midship_coefficient) && midship_coefficient >= block_coefficient &&
                    midship_coefficient <= 1.0,
                "midship_coefficient", midship_coefficient,
                "must be in [block_coefficient, 1] (prismatic coefficient C_b / C_m <= 1)");
  require_input(std::isfinite(lcb_m) && std::abs(lcb_m) < 0.25 * length_pp_m, "lcb_m", lcb_m,
                "must satisfy |lcb_m| < length_pp_m / 4 = " + format_value(0.25 * length_pp_m));
  const double cp = prismatic_coefficient();
  if (cp > kBoxPrismaticThreshold) {
    require_input(lcb_m == 0.0, "lcb_m", lcb_m,
                  "must be 0 when block_coefficient = midship_coefficient (a prism has its "
                  "centre of buoyancy at midships)");
  }
  if (waterplane_coefficient != 0.0) {
    require_input(std::isfinite(waterplane_coefficient) && waterplane_coefficient >= cp &&
                      waterplane_coefficient <= 1.0,
                  "waterplane_coefficient", waterplane_coefficient,
                  "must be 0 (estimate) or in [C_p, 1] with C_p = C_b / C_m = " +
                      format_value(cp));
    require_input(waterplane_coefficient < 1.0 || cp > kBoxPrismaticThreshold,
                  "waterplane_coefficient", waterplane_coefficient,
                  "may be 1 only for a prism (C_b = C_m); a full waterplane over pointed "
                  "ends would give sigma = 0 at non-zero beam");
  }
}

void HullFormOptions::validate() const {
  require_input(station_count >= 5 && station_count <= 1001, "station_count",
                static_cast<double>(station_count), "must be an integer from 5 to 1001");
  require_in_range("relative_tolerance", relative_tolerance, 1e-15, 1e-3);
  require_input(max_iterations >= 10 && max_iterations <= 10000, "max_iterations",
                static_cast<double>(max_iterations), "must be an integer from 10 to 10000");
}

HullForm generate_hull_form(const HullFormParticulars& p, const HullFormOptions& options) {
  p.validate();
  options.validate();
  const int n = options.station_count;
  const double cp = p.prismatic_coefficient();
  HullForm form;
  form.prismatic_coefficient = cp;
  form.waterplane_coefficient = p.waterplane_coefficient != 0.0
                                    ? p.waterplane_coefficient
                                    : std::max((1.0 + 2.0 * p.block_coefficient) / 3.0, cp);
  form.is_box = cp > kBoxPrismaticThreshold;

  std::vector<double> a(static_cast<std::size_t>(n), 1.0);  // A / A_M
  std::vector<double> b(static_cast<std::size_t>(n), 1.0);  // B(x) / B
  if (form.is_box) {
    const double inf = std::numeric_limits<double>::infinity();
    form.area_exponent_fore = form.area_exponent_aft = inf;
    form.beam_exponent_fore = form.beam_exponent_aft = inf;
  } else {
    const HalfGrid grid = make_half_grid(n);
    // Targets in xi units: sum w a = 2 C_p, sum w xi a = 2 C_p (2 LCB / L).
    const double area_halves = 2.0 * cp - grid.midship_weight;
    const double moment_target = 2.0 * cp * (2.0 * p.lcb_m / p.length_pp_m);
    const AreaFit fit = fit_area_curve(grid, area_halves, moment_target, p, options);
    form.area_exponent_fore = fit.exponent_fore;
    form.area_exponent_aft = fit.exponent_aft;

    // EQ-HULLFORM-5: each half's waterline fullness from its area fullness.
    const double r = (1.0 - form.waterplane_coefficient) / (1.0 - cp);
    const double half_mid = 0.5 * grid.midship_weight;
    const double area_max = grid.area(kMaxExponent);
    auto beam_exponent = [&](double area_exponent, const char* what) {
      const double c_half = grid.area(area_exponent) + half_mid;
      const double target = 1.0 - r * (1.0 - c_half) - half_mid;
      if (!(target < area_max)) {
        throw InputError("waterplane_coefficient = " + format_value(form.waterplane_coefficient) +
                         ": too full for pointed ends on " + std::to_string(n) +
                         " stations (" + what + " half); use more stations");
      }
      return solve_exponent(grid, target, options, what);
    };
    form.beam_exponent_fore = beam_exponent(fit.exponent_fore, "fore waterline");
    form.beam_exponent_aft = beam_exponent(fit.exponent_aft, "aft waterline");

    for (int i = 0; i < n; ++i) {
      const double xi = xi_of(i, n);
      const auto k = static_cast<std::size_t>(i);
      const double na = xi >= 0.0 ? form.area_exponent_fore : form.area_exponent_aft;
      const double pb = xi >= 0.0 ? form.beam_exponent_fore : form.beam_exponent_aft;
      a[k] = 1.0 - std::pow(std::abs(xi), na);
      b[k] = 1.0 - std::pow(std::abs(xi), pb);
    }
  }

  form.stations.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    Station& s = form.stations[k];
    s.x_m = 0.5 * p.length_pp_m * xi_of(i, n);
    if (b[k] > 0.0) {
      // EQ-HULLFORM-6; the min() only absorbs round-off where p_h = n_h.
      s.beam_m = p.beam_m * b[k];
      s.draft_m = p.draft_m;
      s.area_coefficient = std::min(1.0, p.midship_coefficient * a[k] / b[k]);
    } else {
      s.beam_m = 0.0;
      s.draft_m = 0.0;
      s.area_coefficient = 0.0;
    }
  }
  return form;
}

namespace {

template <typename F>
double trapezoid(const std::vector<Station>& s, F f) {
  double sum = 0.0;
  for (std::size_t i = 1; i < s.size(); ++i) {
    sum += 0.5 * (s[i].x_m - s[i - 1].x_m) * (f(s[i - 1]) + f(s[i]));
  }
  return sum;
}

double section_area_m2(const Station& s) { return s.area_coefficient * s.beam_m * s.draft_m; }

}  // namespace

double station_volume_m3(const std::vector<Station>& stations) {
  return trapezoid(stations, section_area_m2);
}

double station_lcb_m(const std::vector<Station>& stations) {
  const double volume = station_volume_m3(stations);
  TOWDB_ASSERT(volume > 0.0);
  return trapezoid(stations, [](const Station& s) { return s.x_m * section_area_m2(s); }) / volume;
}

double station_waterplane_area_m2(const std::vector<Station>& stations) {
  return trapezoid(stations, [](const Station& s) { return s.beam_m; });
}

}  // namespace towdb::model
