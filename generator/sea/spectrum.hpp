// Wave spectra of one wave system and a sea state made of several systems.
// The equations, conventions and sources are in sea/sea.hpp (EQ-SEA-1..6).
#ifndef TOWDB_SEA_SPECTRUM_HPP
#define TOWDB_SEA_SPECTRUM_HPP

#include <vector>

namespace towdb::sea {

enum class SpectrumKind {
  kPiersonMoskowitz,  // EQ-SEA-1, one parameter: wind speed at 19.5 m
  kBretschneider,     // EQ-SEA-2, two parameters: Hs and a period (ITTC 1978 form)
  kJonswap,           // EQ-SEA-3, three parameters: Hs, Tp and gamma
};

// One-sided frequency spectrum S(w) [m^2 s/rad] of the wave elevation. Every
// kind shares the base shape S0(w) = A w^-5 exp(-B w^-4) (EQ-SEA-1/2); JONSWAP
// multiplies it by a normalised peak enhancement (EQ-SEA-3). Immutable value
// type; construct with the named factories, which validate their inputs.
class Spectrum {
 public:
  // EQ-SEA-1: fully developed sea for wind speed U [m/s] at 19.5 m above the sea.
  static Spectrum pierson_moskowitz(double wind_speed_m_s);
  // EQ-SEA-2 with B set from the mean period T1 = 2 pi m0/m1 [s] (ITTC, thesis eq. 6.2-6.3).
  static Spectrum bretschneider_mean_period(double significant_height_m, double mean_period_s);
  // EQ-SEA-2 with B set from the peak (modal) period Tp = 2 pi / w_p [s].
  static Spectrum bretschneider_peak_period(double significant_height_m, double peak_period_s);
  // EQ-SEA-3: JONSWAP with peak period Tp [s] and peak enhancement gamma [-] in [1, 10].
  static Spectrum jonswap(double significant_height_m, double peak_period_s, double gamma);

  SpectrumKind kind() const { return kind_; }
  // S(w) [m^2 s/rad]; 0 for w <= 0.
  double density_m2_s(double omega_rad_s) const;
  // Spectral moment m_n = integral_0^inf w^n S(w) dw [m^2 (rad/s)^n] for n = 0..3
  // (m4 diverges for the w^-5 tail). Closed form (EQ-SEA-4) when gamma = 1,
  // adaptive quadrature otherwise.
  double moment(int n) const;
  // m0 [m^2], Hs = 4 sqrt(m0) [m], mean period T1 = 2 pi m0/m1 [s],
  // zero-crossing period T2 = 2 pi sqrt(m0/m2) [s], peak frequency [rad/s].
  double variance_m2() const { return m0_m2_; }
  double significant_height_m() const;
  double mean_period_s() const;
  double zero_crossing_period_s() const;
  double peak_omega_rad_s() const { return peak_omega_rad_s_; }
  // integral_{w_lo}^{w_hi} S(w) dw [m^2], 0 <= w_lo <= w_hi (w_hi may be +inf).
  double energy_between_m2(double omega_lo_rad_s, double omega_hi_rad_s) const;
  // The frequency [rad/s] above which a fraction `fraction` (0 < f < 1) of m0 lies.
  double tail_omega_rad_s(double fraction) const;

  // Parameters of the base shape (EQ-SEA-1/2), for tests and reports.
  double base_a_m2_rad4_s4() const { return a_; }
  double base_b_rad4_s4() const { return b_; }
  double gamma() const { return gamma_; }
  // JONSWAP normalising factor C(gamma) of EQ-SEA-3 (1 for the other kinds).
  double jonswap_normalisation() const { return norm_; }

 private:
  Spectrum(SpectrumKind kind, double a, double b, double gamma);
  // S(w) without the normalisation check; used while computing norm_.
  double raw_density(double omega_rad_s) const;
  double numeric_moment(int n) const;

  SpectrumKind kind_;
  double a_;      // A [m^2 rad^4/s^4]
  double b_;      // B [rad^4/s^4]
  double gamma_;  // peak enhancement [-], 1 for PM and Bretschneider
  double norm_ = 1.0;
  double peak_omega_rad_s_;
  double m0_m2_ = 0.0;
};

// One wave system: a spectrum and the heading of its waves relative to the
// vessel's course (0 = following seas, pi = head seas; EQ-SEA-6).
struct WaveSystem {
  Spectrum spectrum;
  double heading_rad = 0.0;
};

// A sea state: one wind sea, optionally plus swell (thesis 7.1), each with its
// own heading. The systems are independent (their phases are drawn separately).
struct SeaState {
  std::vector<WaveSystem> systems;

  // Throws InputError unless there are 1..8 systems with finite headings.
  void validate() const;
  // Sum of the systems' m0 [m^2] and Hs = 4 sqrt(sum m0) [m].
  double variance_m2() const;
  double significant_height_m() const;
};

// Helpers for the common cases.
SeaState single_system(const Spectrum& spectrum, double heading_rad);
SeaState wind_sea_and_swell(const Spectrum& wind_sea, double wind_sea_heading_rad,
                            const Spectrum& swell, double swell_heading_rad);

}  // namespace towdb::sea

#endif  // TOWDB_SEA_SPECTRUM_HPP
