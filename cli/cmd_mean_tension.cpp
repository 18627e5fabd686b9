// towdb mean-tension: the steady towline tension of a tow and its parts
// (thesis ch. 2; U.S. Navy Towing Manual App. G; generator/sweep EQ-SWEEP-1,
// -2), with the grid tensions a sweep would run at.
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "output.hpp"
#include "sweep/spec/grid_tension.hpp"
#include "sweep/build/simulation_runner.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;

struct MeanTensionArgs {
  std::string tow;
  double speed_kt = 0.0;
  double wind_kt = 0.0;
  double heading_deg = 180.0;
  double margin = 0.10;
  std::string propeller = "locked";
  double sea_head_lbf = 0.0;
  std::string sea_resistance = "given";  // given (--sea-head-lbf) | strip-theory | strip-theory-head
  bool json = false;
};

// Thesis ch. 5 grid: +-15 % of the calculated value.
constexpr double kUpperFactor = 1.15;
constexpr double kLowerFactor = 0.85;

int run_mean_tension(const Context& ctx, const MeanTensionArgs& a) {
  const io::ShipCatalog catalog = load_catalog(ctx);
  const model::Vessel& tow = catalog.vessel(a.tow).vessel;
  sweep::MeanTensionModel model;
  model.hull_margin = a.margin;
  model.propeller = a.propeller == "locked" ? propulsion::TowPropellerState::kLocked
                    : a.propeller == "free" ? propulsion::TowPropellerState::kFreeSpinning
                                            : propulsion::TowPropellerState::kRemoved;
  model.wind = sweep::MeanTensionWind::kHeading;  // the heading given here is the wind's and the sea's
  const double heading_rad = units::deg_to_rad(a.heading_deg);
  double sea_n = 0.0;
  std::string sea_note;
  if (a.sea_resistance == "given") {
    // EQ-PROPULSION-11 (thesis eq. 2.9): a head-seas value corrected for direction.
    sea_n = propulsion::direction_corrected_added_resistance_n(units::lbf_to_n(a.sea_head_lbf), heading_rad);
    sea_note = a.sea_head_lbf > 0.0 ? "head-seas value given, corrected for direction (thesis eq. 2.9)"
                                    : "0: no sea-state added resistance given (--sea-head-lbf or --sea-resistance)";
  } else {
    // Thesis eq. 2.2 by strip theory in the fully developed sea of the wind, as
    // the sweep's sea_resistance setting computes it (EQ-SWEEP-1).
    if (a.sea_head_lbf > 0.0) {
      throw InputError("--sea-head-lbf = " + fmt(a.sea_head_lbf) + " is given with --sea-resistance " +
                       a.sea_resistance + "; allowed: one source of the sea-state resistance");
    }
    sweep::SeaSpec sea;
    sea.wind_kt = a.wind_kt;
    const bool head = a.sea_resistance == "strip-theory-head";
    sea_n = a.wind_kt > 0.0 ? sweep::strip_theory_sea_resistance(simulation::CaseOptions{})(
                                  tow, a.speed_kt, sea, head ? 180.0 : a.heading_deg)
                            : 0.0;
    sea_note = head ? "strip theory (thesis eq. 2.2), head seas" : "strip theory (thesis eq. 2.2) at this heading";
  }
  const propulsion::MeanTensionBreakdown b =
      sweep::calculated_mean_tension(tow, a.speed_kt, a.wind_kt, a.heading_deg, sea_n, model);
  const double total_lbf = units::n_to_lbf(b.total_n);
  const double lower_lbf = sweep::hull_half_propeller_tension_lbf(tow, a.speed_kt, model);
  if (a.json) {
    ordered_json j;
    j["tow"] = tow.name;
    j["speed_kt"] = a.speed_kt;
    j["wind_kt"] = a.wind_kt;
    j["heading_deg"] = a.heading_deg;
    j["hull_margin"] = a.margin;
    j["propeller"] = a.propeller;
    j["hull_lbf"] = units::n_to_lbf(b.hull_n);
    j["propeller_lbf"] = units::n_to_lbf(b.propeller_n);
    j["wind_lbf"] = units::n_to_lbf(b.wind_n);
    j["sea_lbf"] = units::n_to_lbf(b.sea_n);
    j["sea_note"] = sea_note;
    j["tow_resistance_lbf"] = units::n_to_lbf(b.tow_resistance_n);
    j["towline_lbf"] = units::n_to_lbf(b.towline_n);
    j["total_lbf"] = total_lbf;
    j["relative_wind_kt"] = units::m_s_to_kt(b.relative_wind_m_s);
    j["grid_calculated_plus_15_lbf"] = kUpperFactor * total_lbf;
    j["grid_calculated_minus_15_lbf"] = kLowerFactor * total_lbf;
    j["grid_hull_half_propeller_lbf"] = lower_lbf;
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << "mean towline tension: " << tow.name << " at " << fmt(a.speed_kt) << " kt, wind " << fmt(a.wind_kt)
            << " kt at " << fmt(a.heading_deg) << " deg (0 following, 180 head), hull margin " << fmt(a.margin)
            << ", propeller " << a.propeller << "\n\n";
  TextTable t({"component", "lbf", "note"});
  t.add_row({"hull", fmt_grouped(units::n_to_lbf(b.hull_n)), "(1 + margin) R_H, drag file"});
  t.add_row({"propeller", fmt_grouped(units::n_to_lbf(b.propeller_n)), a.propeller});
  t.add_row({"wind", fmt_grouped(units::n_to_lbf(b.wind_n)),
             "relative wind " + fmt(units::m_s_to_kt(b.relative_wind_m_s), 1) + " kt"});
  t.add_row({"sea", fmt_grouped(units::n_to_lbf(b.sea_n)), sea_note});
  t.add_row({"tow resistance", fmt_grouped(units::n_to_lbf(b.tow_resistance_n)), "sum of the above"});
  t.add_row({"towline", fmt_grouped(units::n_to_lbf(b.towline_n)), "10 % of the tow resistance"});
  t.add_row({"total", fmt_grouped(total_lbf), "mean towline tension"});
  t.print(std::cout);
  std::cout << "\nsweep grid tensions (thesis ch. 5): calculated +15% " << fmt_grouped(kUpperFactor * total_lbf)
            << " lbf, -15% " << fmt_grouped(kLowerFactor * total_lbf) << " lbf; hull + half propeller "
            << fmt_grouped(lower_lbf) << " lbf\n";
  return 0;
}

}  // namespace

void add_mean_tension_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<MeanTensionArgs>();
  CLI::App* c = app.add_subcommand("mean-tension", "Mean (steady) towline tension of a tow and its components");
  c->add_option("--tow", a->tow, "Tow vessel (name or alias)")->required();
  c->add_option("--speed-kt", a->speed_kt, "Tow speed [kt]")->required()->check(number_in(0.1, 30.0));
  c->add_option("--wind-kt", a->wind_kt, "True wind speed [kt]")->required()->check(number_in(0.0, 100.0));
  c->add_option("--heading-deg", a->heading_deg, "Wind and sea heading [deg], 0 = following, 180 = head")
      ->required()
      ->check(number_in(0.0, 360.0));
  c->add_option("--margin", a->margin, "Hull margin: 0.1 thesis (default), 0.25 Towing Manual")
      ->check(number_in(0.0, 1.0));
  c->add_option("--propeller", a->propeller, "Tow propeller: locked (default), free, removed")
      ->check(CLI::IsMember({"locked", "free", "removed"}));
  c->add_option("--sea-head-lbf", a->sea_head_lbf,
                "Head-seas added resistance [lbf] (Towing Manual curve), corrected for heading; default 0")
      ->check(number_in(0.0, 1.0e6));
  c->add_option("--sea-resistance", a->sea_resistance,
                "Sea-state added resistance: given (--sea-head-lbf, default), strip-theory (at --heading-deg) or "
                "strip-theory-head (head seas, as the bundled sweep)")
      ->check(CLI::IsMember({"given", "strip-theory", "strip-theory-head"}));
  c->add_flag("--json", a->json, "JSON output");
  c->callback([&ctx, a] { ctx.action = [&ctx, a] { return run_mean_tension(ctx, *a); }; });
}

}  // namespace towdb::cli
