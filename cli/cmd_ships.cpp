// towdb ships list | show NAME: the bundled vessels and towline components.
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "common/units.hpp"
#include "model/hull_form.hpp"
#include "output.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;

const char* role_name(model::VesselRole r) { return r == model::VesselRole::kTug ? "tug" : "tow"; }

ordered_json vessel_summary_json(const io::VesselFile& vf) {
  const model::Vessel& v = vf.vessel;
  const model::Hull& h = v.hull;
  ordered_json j;
  j["name"] = v.name;
  j["aliases"] = v.aliases;
  j["role"] = role_name(v.role);
  j["description"] = vf.description;
  j["length_overall_ft"] = units::m_to_ft(h.length_overall_m);
  j["length_pp_ft"] = units::m_to_ft(h.length_pp_m);
  j["beam_ft"] = units::m_to_ft(h.beam_m);
  j["draft_ft"] = units::m_to_ft(h.draft_m);
  j["displacement_lt"] = units::kg_to_long_tons(h.displacement_kg);
  j["block_coefficient"] = h.block_coefficient();
  j["propellers"] = v.propellers ? v.propellers->count : 0;
  j["file"] = v.source_path;
  j["sha256"] = v.content_sha256;
  return j;
}

ordered_json component_summary_json(const io::TowlineFile& tf) {
  const model::TowlineComponent& c = tf.component;
  ordered_json j;
  j["name"] = c.name;
  j["kind"] = model::to_string(c.kind);
  j["description"] = tf.description;
  j["ea_lbf"] = units::n_to_lbf(c.ea_n);
  j["hydrodynamic_diameter_ft"] = units::m_to_ft(c.hydrodynamic_diameter_m);
  j["weight_in_water_lb_per_ft"] = units::n_per_m_to_lbf_per_ft(c.weight_in_water_n_m);
  j["breaking_strength_lbf"] = units::n_to_lbf(c.breaking_strength_n);
  if (c.fixed_length_m > 0) j["fixed_length_ft"] = units::m_to_ft(c.fixed_length_m);
  j["file"] = c.source_path;
  j["sha256"] = c.content_sha256;
  return j;
}

int run_list(const Context& ctx, bool json) {
  const io::ShipCatalog cat = load_catalog(ctx);
  if (json) {
    ordered_json j;
    j["vessels"] = ordered_json::array();
    for (const auto& vf : cat.vessels()) j["vessels"].push_back(vessel_summary_json(vf));
    j["towline_components"] = ordered_json::array();
    for (const auto& tf : cat.components()) j["towline_components"].push_back(component_summary_json(tf));
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  TextTable vt({"vessel", "role", "LOA ft", "LPP ft", "beam ft", "draft ft", "displ. LT", "Cb", "props"});
  for (const auto& vf : cat.vessels()) {
    const auto& v = vf.vessel;
    const auto& h = v.hull;
    vt.add_row({v.name, role_name(v.role), fmt(units::m_to_ft(h.length_overall_m), 1),
                fmt(units::m_to_ft(h.length_pp_m), 1), fmt(units::m_to_ft(h.beam_m), 1),
                fmt(units::m_to_ft(h.draft_m), 1), fmt_grouped(units::kg_to_long_tons(h.displacement_kg)),
                fmt(h.block_coefficient(), 3), std::to_string(v.propellers ? v.propellers->count : 0)});
  }
  vt.print(std::cout);
  std::cout << "\n";
  TextTable ct({"towline component", "kind", "EA lbf", "breaking lbf", "wet weight lb/ft", "diameter ft", "length ft"});
  for (const auto& tf : cat.components()) {
    const auto& c = tf.component;
    ct.add_row({c.name, model::to_string(c.kind), fmt_grouped(units::n_to_lbf(c.ea_n)),
                fmt_grouped(units::n_to_lbf(c.breaking_strength_n)),
                fmt(units::n_per_m_to_lbf_per_ft(c.weight_in_water_n_m), 3),
                fmt(units::m_to_ft(c.hydrodynamic_diameter_m), 4),
                c.fixed_length_m > 0 ? fmt(units::m_to_ft(c.fixed_length_m), 1) : "per case"});
  }
  ct.print(std::cout);
  return 0;
}

ordered_json provenance_json(const std::vector<io::Provenance>& prov) {
  ordered_json a = ordered_json::array();
  for (const auto& p : prov) a.push_back({{"key", p.key}, {"value", p.value}, {"status", p.status}, {"source", p.source}});
  return a;
}

void print_provenance(const std::vector<io::Provenance>& prov) {
  TextTable t({"key", "value", "status", "source"});
  for (const auto& p : prov) t.add_row({p.key, p.value, p.status, p.source});
  t.print(std::cout);
}

int run_show(const Context& ctx, const std::string& name, bool json) {
  const io::ShipCatalog cat = load_catalog(ctx);
  // A vessel first; a towline component if no vessel has that name.
  const io::VesselFile* vf = cat.find_vessel(name);
  if (!vf && !cat.find_component(name)) {
    cat.vessel(name);  // throws InputError listing the known vessels
  }
  if (!vf) {
    const io::TowlineFile& tf = cat.component(name);
    if (json) {
      ordered_json j = component_summary_json(tf);
      j["particulars"] = provenance_json(tf.provenance);
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << tf.component.name << " (" << model::to_string(tf.component.kind) << "): " << tf.description
                << "\nfile: " << tf.component.source_path << "\n\n";
      print_provenance(tf.provenance);
    }
    return 0;
  }
  const model::Vessel& v = vf->vessel;
  if (json) {
    ordered_json j = vessel_summary_json(*vf);
    j["particulars"] = provenance_json(vf->provenance);
    ordered_json st = ordered_json::array();
    for (const auto& s : v.hull.stations) {
      st.push_back({{"x_ft", units::m_to_ft(s.x_m)}, {"beam_ft", units::m_to_ft(s.beam_m)},
                    {"draft_ft", units::m_to_ft(s.draft_m)}, {"area_coefficient", s.area_coefficient}});
    }
    j["stations"] = st;
    ordered_json drag = ordered_json::array();
    for (std::size_t i = 0; i < v.drag.speed_m_s.size(); ++i) {
      drag.push_back({{"speed_kt", units::m_s_to_kt(v.drag.speed_m_s[i])},
                      {"total_resistance_coefficient", v.drag.total_resistance_coefficient[i]},
                      {"resistance_lbf", units::n_to_lbf(v.hull_resistance_n(v.drag.speed_m_s[i]))}});
    }
    j["drag"] = drag;
    if (v.role == model::VesselRole::kTug) {
      j["towlines"] = {{"wire_hawser", v.wire_hawser}, {"fiber_hawser", v.fiber_hawser}, {"pendant", v.pendant}};
    }
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << v.name << " (" << role_name(v.role) << "): " << vf->description << "\nfile: " << v.source_path
            << "\nsha256: " << v.content_sha256 << "\nblock coefficient from displacement: "
            << fmt(v.hull.block_coefficient(), 4) << "\n\n";
  print_provenance(vf->provenance);
  std::cout << "\nstations (x from midships, + forward)\n";
  TextTable st({"x ft", "beam ft", "draft ft", "area coeff"});
  for (const auto& s : v.hull.stations) {
    st.add_row({fmt(units::m_to_ft(s.x_m), 2), fmt(units::m_to_ft(s.beam_m), 2), fmt(units::m_to_ft(s.draft_m), 2),
                fmt(s.area_coefficient, 4)});
  }
  st.print(std::cout);
  std::cout << "\nhull resistance (no margin)\n";
  TextTable dt({"speed kt", "C_T", "resistance lbf"});
  for (std::size_t i = 0; i < v.drag.speed_m_s.size(); ++i) {
    dt.add_row({fmt(units::m_s_to_kt(v.drag.speed_m_s[i]), 1), fmt(v.drag.total_resistance_coefficient[i]),
                fmt_grouped(units::n_to_lbf(v.hull_resistance_n(v.drag.speed_m_s[i])))});
  }
  dt.print(std::cout);
  if (v.role == model::VesselRole::kTug) {
    std::cout << "\ntowlines: wire '" << v.wire_hawser << "', fiber '" << v.fiber_hawser << "', pendant '"
              << v.pendant << "'\n";
  }
  return 0;
}

struct StationsArgs {
  double length_pp_ft = 0.0, beam_ft = 0.0, draft_ft = 0.0, block_coefficient = 0.0;
  double midship_coefficient = 0.0, lcb_ft = 0.0, waterplane_coefficient = 0.0;
  int stations = 21;
};

// Prints a [hull.stations] table for a ship file, generated from particulars.
int run_stations(const StationsArgs& a) {
  model::HullFormParticulars p;
  p.length_pp_m = units::ft_to_m(a.length_pp_ft);
  p.beam_m = units::ft_to_m(a.beam_ft);
  p.draft_m = units::ft_to_m(a.draft_ft);
  p.block_coefficient = a.block_coefficient;
  p.midship_coefficient = a.midship_coefficient;
  p.lcb_m = units::ft_to_m(a.lcb_ft);
  p.waterplane_coefficient = a.waterplane_coefficient;
  model::HullFormOptions o;
  o.station_count = a.stations;
  const model::HullForm form = model::generate_hull_form(p, o);
  auto list = [&](auto get, int decimals) {
    std::string out;
    for (const auto& s : form.stations) out += (out.empty() ? "" : ", ") + fmt(get(s), decimals);
    return "[" + out + "]";
  };
  std::cout << "[hull.stations]\nstatus = \"E\"\nsource = \"estimate: towdb ships stations --length-pp-ft "
            << fmt(a.length_pp_ft) << " --beam-ft " << fmt(a.beam_ft) << " --draft-ft " << fmt(a.draft_ft)
            << " --block-coefficient " << fmt(a.block_coefficient) << " --midship-coefficient "
            << fmt(a.midship_coefficient) << " --lcb-ft " << fmt(a.lcb_ft) << " --waterplane-coefficient "
            << fmt(form.waterplane_coefficient, 4) << " --stations " << a.stations
            << " (power-law area and waterline curves, docs in generator/model/hull_form.hpp)\"\n";
  std::cout << "x_ft = " << list([](const model::Station& s) { return units::m_to_ft(s.x_m); }, 3) << "\n";
  std::cout << "beam_ft = " << list([](const model::Station& s) { return units::m_to_ft(s.beam_m); }, 3) << "\n";
  std::cout << "draft_ft = " << list([](const model::Station& s) { return units::m_to_ft(s.draft_m); }, 3) << "\n";
  std::cout << "area_coefficient = " << list([](const model::Station& s) { return s.area_coefficient; }, 4)
            << "\n";
  return 0;
}

}  // namespace

void add_ships_command(CLI::App& app, Context& ctx) {
  CLI::App* ships = app.add_subcommand("ships", "List and show the vessels and towline components");
  ships->require_subcommand(1);

  struct ListArgs { bool json = false; };
  auto list_args = std::make_shared<ListArgs>();
  CLI::App* list = ships->add_subcommand("list", "Table of vessels and towline components");
  list->add_flag("--json", list_args->json, "JSON output");
  list->callback([&ctx, list_args] { ctx.action = [&ctx, list_args] { return run_list(ctx, list_args->json); }; });

  struct ShowArgs { std::string name; bool json = false; };
  auto show_args = std::make_shared<ShowArgs>();
  CLI::App* show = ships->add_subcommand("show", "Every particular of one vessel or towline component, with sources");
  show->add_option("name", show_args->name, "Vessel or component name (case, spaces and hyphens ignored: ffg7, T-ATF)")
      ->required();
  show->add_flag("--json", show_args->json, "JSON output");
  show->callback([&ctx, show_args] {
    ctx.action = [&ctx, show_args] { return run_show(ctx, show_args->name, show_args->json); };
  });

  auto st = std::make_shared<StationsArgs>();
  CLI::App* stations = ships->add_subcommand(
      "stations", "Generate a [hull.stations] table (Lewis sections) from principal particulars");
  stations->add_option("--length-pp-ft", st->length_pp_ft, "Length between perpendiculars [ft]")->required()->check(number_in(10.0, 1500.0));
  stations->add_option("--beam-ft", st->beam_ft, "Waterline beam [ft]")->required()->check(number_in(5.0, 200.0));
  stations->add_option("--draft-ft", st->draft_ft, "Hull draft [ft]")->required()->check(number_in(0.5, 60.0));
  stations->add_option("--block-coefficient", st->block_coefficient, "C_b [-]")->required()->check(number_in(0.3, 1.0));
  stations->add_option("--midship-coefficient", st->midship_coefficient, "C_m [-]")->required()->check(number_in(0.3, 1.0));
  stations->add_option("--lcb-ft", st->lcb_ft, "LCB from midships, + forward [ft]")->required()->check(number_in(-400.0, 400.0));
  stations->add_option("--waterplane-coefficient", st->waterplane_coefficient,
                       "C_wp [-]; 0 or omitted: estimated from C_b")
      ->check(number_in(0.0, 1.0));
  stations->add_option("--stations", st->stations, "Number of stations (default 21)")->check(CLI::Range(5, 1001));
  stations->callback([&ctx, st] { ctx.action = [st] { return run_stations(*st); }; });
}

}  // namespace towdb::cli
