#include "sweep/build/writer.hpp"

#include <ctime>
#include <map>
#include <set>

#include "common/error.hpp"
#include "common/units.hpp"
#include "io/file_bytes.hpp"
#include "store/key_bytes.hpp"
#include "store/packed_days.hpp"

namespace towdb::sweep {

namespace {

const char* role_text(model::VesselRole role) { return role == model::VesselRole::kTug ? "tug" : "tow"; }

const char* line_text(model::LineKind kind) {
  switch (kind) {
    case model::LineKind::kWire: return "wire";
    case model::LineKind::kFiber: return "fiber";
    case model::LineKind::kChain: return "chain";
  }
  return "?";
}

// a_mn [N s^n / m^(m+n)] -> [lbf s^n / ft^(m+n)].
double coefficient_to_user(double a_si, int length_power) {
  double a = units::n_to_lbf(a_si);
  for (int i = 0; i < length_power; ++i) a *= kMetersPerFoot;
  return a;
}

// (m + n) of a10, a01, a20, a11, a02, a30, a21, a12, a03.
constexpr int kCoefficientLengthPower[9] = {1, 1, 2, 2, 2, 3, 3, 3, 3};

// Binds every input column of `cases` (parameters 1..26 in this order).
void bind_case_inputs(store::Statement& st, const CaseSpec& s, const CaseKeys& k, std::int64_t tug_id,
                      std::int64_t tow_id) {
  st.bind_blob(1, store::key_bytes(k.case_key, "case_key"))
      .bind_blob(2, store::key_bytes(k.inputs_sha256, "inputs_sha256"))
      .bind(3, s.sweep_label)
      .bind(4, s.tug)
      .bind(5, s.tow)
      .bind(6, tug_id)
      .bind(7, tow_id)
      .bind(8, s.speed_kt)
      .bind(9, s.sea.spectrum_text())
      .bind(10, s.sea.wind_kt)
      .bind(11, s.sea.hs_ft)
      .bind(12, s.sea.tp_s)
      .bind(13, s.sea.gamma)
      .bind(14, s.sea.swell ? std::optional<double>(s.sea.swell->hs_ft) : std::nullopt)
      .bind(15, s.sea.swell ? std::optional<double>(s.sea.swell->tp_s) : std::nullopt)
      .bind(16, s.sea.swell ? std::optional<double>(s.sea.swell->heading_deg) : std::nullopt)
      .bind(17, s.heading_deg)
      .bind(18, line_text(s.line))
      .bind(19, s.length_ft)
      .bind(20, s.mean_tension_lbf)
      .bind(21, s.mean_tension_label)
      .bind(22, s.days)
      .bind(23, s.seed)
      .bind_blob(24, store::key_bytes(s.condition_key, "condition_key"))
      .bind(25, s.nominal_speed_kt)
      .bind(26, s.calculated_mean_tension_lbf);
}

}  // namespace

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

const char* to_string(CaseState state) {
  switch (state) {
    case CaseState::kNew: return "new";
    case CaseState::kChanged: return "changed";
    case CaseState::kUnfinished: return "unfinished";
    case CaseState::kFailed: return "failed";
    case CaseState::kDone: return "done";
  }
  return "?";
}

CaseState state_of_stored(std::string_view status) {
  if (status == "done") return CaseState::kDone;
  if (status == "failed") return CaseState::kFailed;
  return CaseState::kUnfinished;
}

bool computes(CaseState state, bool retry_failed) {
  return state == CaseState::kFailed ? retry_failed : state != CaseState::kDone;
}

std::vector<std::int64_t> DatabaseWriter::unfinished_builds() {
  std::vector<std::int64_t> ids;
  store::Statement st = db_.prepare("SELECT build_id FROM builds WHERE status = 'running' ORDER BY build_id");
  while (st.step()) ids.push_back(st.column_int(0));
  return ids;
}

void DatabaseWriter::mark_interrupted(const std::vector<std::int64_t>& build_ids) {
  db_.transaction([&] {
    store::Statement st = db_.prepare("UPDATE builds SET status = 'interrupted' WHERE build_id = ?");
    for (std::int64_t id : build_ids) {
      st.bind(1, id);
      st.run();
    }
  });
}

std::int64_t DatabaseWriter::begin_build(const BuildProvenance& p) {
  std::int64_t id = 0;
  db_.transaction([&] {
    store::Statement st = db_.prepare(
        "INSERT INTO builds (code_version, command_line, sweep_file, sweep_sha256, host, threads, mpi_ranks, "
        "started_utc, status) VALUES (?, ?, ?, ?, ?, ?, ?, ?, 'running')");
    st.bind(1, p.code_version)
        .bind(2, p.command_line)
        .bind(3, p.sweep_file)
        .bind(4, p.sweep_sha256)
        .bind(5, p.host)
        .bind(6, p.threads)
        .bind(7, p.mpi_ranks)
        .bind(8, utc_now());
    st.run();
    id = db_.last_insert_rowid();
  });
  return id;
}

void DatabaseWriter::record_coverage(std::int64_t build_id, const std::string& sweep_file,
                                     const std::vector<CoverageNote>& notes,
                                     const std::vector<SkippedCondition>& skipped) {
  db_.transaction([&] {
    store::Statement del = db_.prepare(
        "DELETE FROM coverage_notes WHERE build_id IN (SELECT build_id FROM builds WHERE sweep_file = ?)");
    del.bind(1, sweep_file).run();
    store::Statement ins = db_.prepare(
        "INSERT INTO coverage_notes (build_id, kind, sweep_label, tug_name, tow_name, nominal_speed_kt, sea, "
        "heading_deg, note) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
    for (const CoverageNote& n : notes) {
      ins.reset();
      ins.bind(1, build_id).bind(2, "grid_note").bind(3, n.sweep_label).bind(4, n.tug).bind(5, n.tow);
      ins.bind_null(6).bind_null(7).bind_null(8).bind(9, n.note).run();
    }
    for (const SkippedCondition& k : skipped) {
      ins.reset();
      ins.bind(1, build_id).bind(2, "skipped").bind(3, k.sweep_label).bind(4, k.tug).bind(5, k.tow);
      ins.bind(6, k.nominal_speed_kt).bind(7, k.sea).bind(8, k.heading_deg).bind(9, k.reason).run();
    }
  });
}

void DatabaseWriter::finish_build(std::int64_t build_id, const std::string& status, int cases_done,
                                  int cases_failed) {
  db_.transaction([&] {
    store::Statement st = db_.prepare(
        "UPDATE builds SET status = ?, finished_utc = ?, cases_done = ?, cases_failed = ? WHERE build_id = ?");
    st.bind(1, status).bind(2, utc_now()).bind(3, cases_done).bind(4, cases_failed).bind(5, build_id);
    st.run();
  });
}

bool fit_is_stored(store::Database& db, std::int64_t fit_id, const std::string& fit_key) {
  store::Statement find = db.prepare("SELECT fit_key FROM towline_fits WHERE fit_id = ?");
  find.bind(1, fit_id);
  if (!find.step()) return false;
  if (find.column_text(0) != fit_key) {
    throw StorageError("towline_fits: fit_id " + std::to_string(fit_id) + " of key " + fit_key + " is taken by key " +
                       find.column_text(0) + " (60-bit id collision)");
  }
  return true;
}

std::int64_t DatabaseWriter::register_vessel(const io::VesselFile& vf) {
  const model::Vessel& v = vf.vessel;
  {
    store::Statement find = db_.prepare("SELECT vessel_id FROM vessels WHERE name = ? AND content_sha256 = ?");
    find.bind(1, v.name).bind(2, v.content_sha256);
    if (find.step()) return find.column_int(0);
  }
  const std::string text = io::read_file_bytes(v.source_path);
  if (io::sha256_hex(text) != v.content_sha256) {
    throw InputError(v.source_path + ": the ship file changed while the build was starting; run it again");
  }
  store::Statement st = db_.prepare(
      "INSERT INTO vessels (name, role, file_path, content_sha256, file_text) VALUES (?, ?, ?, ?, ?)");
  st.bind(1, v.name).bind(2, role_text(v.role)).bind(3, v.source_path).bind(4, v.content_sha256).bind(5, text);
  st.run();
  return db_.last_insert_rowid();
}

void DatabaseWriter::register_component(const model::TowlineComponent& c) {
  {
    store::Statement find =
        db_.prepare("SELECT component_id FROM towline_components WHERE name = ? AND content_sha256 = ?");
    find.bind(1, c.name).bind(2, c.content_sha256);
    if (find.step()) return;
  }
  const std::string text = io::read_file_bytes(c.source_path);
  if (io::sha256_hex(text) != c.content_sha256) {
    throw InputError(c.source_path + ": the towline file changed while the build was starting; run it again");
  }
  store::Statement st = db_.prepare(
      "INSERT INTO towline_components (name, kind, file_path, content_sha256, file_text) VALUES (?, ?, ?, ?, ?)");
  st.bind(1, c.name).bind(2, line_text(c.kind)).bind(3, c.source_path).bind(4, c.content_sha256).bind(5, text);
  st.run();
}

std::vector<RegisteredCase> DatabaseWriter::register_cases(const std::vector<CaseSpec>& specs,
                                                           const std::vector<CaseKeys>& keys,
                                                           const io::ShipCatalog& catalog, std::int64_t build_id,
                                                           bool retry_failed, EarlierShipFiles* earlier) {
  TOWDB_ASSERT(specs.size() == keys.size());
  std::vector<RegisteredCase> out(specs.size());
  db_.transaction([&] {
    std::map<std::string, std::int64_t> vessel_ids;
    auto vessel_id = [&](const std::string& name) {
      auto it = vessel_ids.find(name);
      if (it != vessel_ids.end()) return it->second;
      const std::int64_t id = register_vessel(catalog.vessel(name));
      vessel_ids.emplace(name, id);
      return id;
    };
    std::set<std::string> components_done;
    store::Statement by_key = db_.prepare("SELECT case_id, status FROM cases WHERE case_key = ?");
    store::Statement by_condition = db_.prepare("SELECT case_id FROM cases WHERE condition_key = ?");
    const std::string now = utc_now();
    store::Statement insert = db_.prepare(
        "INSERT INTO cases (case_key, inputs_sha256, sweep_label, tug_name, tow_name, tug_vessel_id, tow_vessel_id, "
        "speed_kt, spectrum, wind_kt, hs_ft, tp_s, gamma, swell_hs_ft, swell_tp_s, swell_heading_deg, heading_deg, "
        "line_type, length_ft, mean_tension_lbf, mean_tension_label, days, seed, condition_key, nominal_speed_kt, "
        "calculated_mean_tension_lbf, status, build_id, updated_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
        "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, 'pending', ?, ?)");
    store::Statement replace = db_.prepare(
        "UPDATE cases SET case_key = ?, inputs_sha256 = ?, sweep_label = ?, tug_name = ?, tow_name = ?, "
        "tug_vessel_id = ?, tow_vessel_id = ?, speed_kt = ?, spectrum = ?, wind_kt = ?, hs_ft = ?, tp_s = ?, "
        "gamma = ?, swell_hs_ft = ?, swell_tp_s = ?, swell_heading_deg = ?, heading_deg = ?, line_type = ?, "
        "length_ft = ?, mean_tension_lbf = ?, mean_tension_label = ?, days = ?, seed = ?, condition_key = ?, "
        "nominal_speed_kt = ?, calculated_mean_tension_lbf = ?, status = 'pending', error_message = NULL, fit_id = NULL, profile_id = NULL, build_id = ?, "
        "updated_utc = ? WHERE case_id = ?");
    store::Statement drop_results = db_.prepare("DELETE FROM results WHERE case_id = ?");
    store::Statement drop_days = db_.prepare("DELETE FROM case_days WHERE case_id = ?");
    store::Statement to_pending = db_.prepare(
        "UPDATE cases SET status = 'pending', error_message = NULL, build_id = ?, updated_utc = ? WHERE case_id = ?");

    // A stored case stays: its state, and pending again when this build computes it.
    auto keep = [&](std::size_t i, std::int64_t id, const std::string& status, bool rekeyed) {
      out[i] = {id, state_of_stored(status), rekeyed};
      if (computes(out[i].state, retry_failed)) {
        to_pending.bind(1, build_id).bind(2, now).bind(3, id);
        to_pending.run();
      }
    };
    std::vector<std::int64_t> moved_fits;
    for (std::size_t i = 0; i < specs.size(); ++i) {
      const CaseSpec& s = specs[i];
      const CaseKeys& k = keys[i];
      const std::int64_t tug_id = vessel_id(s.tug);
      const std::int64_t tow_id = vessel_id(s.tow);
      const model::Towline line = catalog.towline(catalog.vessel(s.tug).vessel, s.line, s.length_m());
      for (const model::TowlineSegment& seg : line.segments) {
        if (components_done.insert(seg.component.name + "@" + seg.component.content_sha256).second) {
          register_component(seg.component);
        }
      }
      by_key.bind_blob(1, store::key_bytes(k.case_key, "case_key"));
      if (by_key.step()) {
        const std::int64_t id = by_key.column_int(0);
        const std::string status = by_key.column_text(1);
        by_key.reset();
        keep(i, id, status, false);
        continue;
      }
      by_key.reset();
      if (earlier != nullptr && !earlier->empty()) {
        if (const std::optional<StoredCase> stored = earlier->stored_case(s)) {
          earlier->rekey(*stored, k, tug_id, tow_id, now);
          if (stored->fit_id && *stored->fit_id != k.fit_id) moved_fits.push_back(*stored->fit_id);
          keep(i, stored->case_id, stored->status, true);
          continue;
        }
      }
      by_condition.bind_blob(1, store::key_bytes(s.condition_key, "condition_key"));
      if (by_condition.step()) {
        const std::int64_t id = by_condition.column_int(0);
        by_condition.reset();
        drop_results.bind(1, id);
        drop_results.run();
        drop_days.bind(1, id);
        drop_days.run();
        bind_case_inputs(replace, s, k, tug_id, tow_id);
        replace.bind(27, build_id).bind(28, now).bind(29, id);
        replace.run();
        out[i] = {id, CaseState::kChanged};
        continue;
      }
      by_condition.reset();
      bind_case_inputs(insert, s, k, tug_id, tow_id);
      insert.bind(27, build_id).bind(28, now);
      insert.run();
      out[i] = {db_.last_insert_rowid(), CaseState::kNew};
    }
    drop_unused_fits(db_, moved_fits);
  });
  return out;
}

void DatabaseWriter::mark_running(std::int64_t case_id, std::int64_t build_id) {
  db_.transaction([&] {
    store::Statement st =
        db_.prepare("UPDATE cases SET status = 'running', build_id = ?, updated_utc = ? WHERE case_id = ?");
    st.bind(1, build_id).bind(2, utc_now()).bind(3, case_id);
    st.run();
  });
}

void DatabaseWriter::write_result(std::int64_t case_id, const CaseSpec& spec, const CaseKeys& keys,
                                  const CaseOutcome& outcome, double runtime_s, const std::string& code_version,
                                  std::int64_t build_id) {
  using units::m_to_ft;
  using units::n_to_kips;
  using units::n_to_lbf;
  using units::rad_to_deg;
  const double newtons_per_kip = units::kips_to_n(1.0);
  db_.transaction([&] {
    // The fit (shared by every case with the same fit_key; EQ-SWEEP-7 id).
    {
      if (!fit_is_stored(db_, keys.fit_id, keys.fit_key)) {
        const TowlineFitOutcome& f = outcome.fit;
        store::Statement st = db_.prepare(
            "INSERT INTO towline_fits (fit_id, fit_key, tug_name, line_type, length_ft, mean_tension_lbf, "
            "towline_model, span_ft, sag_ft, end_angle_tug_deg, end_angle_tow_deg, static_stiffness_lbf_per_ft, "
            "breaking_strength_lbf, a10_lbf_per_ft, a01_lbf_s_per_ft, a20_lbf_per_ft2, a11_lbf_s_per_ft2, "
            "a02_lbf_s2_per_ft2, a30_lbf_per_ft3, a21_lbf_s_per_ft3, a12_lbf_s2_per_ft3, a03_lbf_s3_per_ft3, "
            "fit_rms_lbf, fit_max_error_lbf, fit_samples, lowest_elevation_ft) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, "
            "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
        st.bind(1, keys.fit_id)
            .bind(2, keys.fit_key)
            .bind(3, spec.tug)
            .bind(4, line_text(spec.line))
            .bind(5, spec.length_ft)
            .bind(6, spec.mean_tension_lbf)
            .bind(7, f.towline_model)
            .bind(8, m_to_ft(f.span_m))
            .bind(9, m_to_ft(f.sag_m))
            .bind(10, rad_to_deg(f.end_angle_tug_rad))
            .bind(11, rad_to_deg(f.end_angle_tow_rad))
            .bind(12, units::n_per_m_to_lbf_per_ft(f.static_stiffness_n_per_m))
            .bind(13, n_to_lbf(f.breaking_strength_n));
        for (int c = 0; c < 9; ++c) {
          st.bind(14 + c, coefficient_to_user(f.coefficients_si[static_cast<std::size_t>(c)],
                                              kCoefficientLengthPower[c]));
        }
        st.bind(23, n_to_lbf(f.fit_rms_n)).bind(24, n_to_lbf(f.fit_max_error_n)).bind(25, f.fit_samples);
        st.bind(26, m_to_ft(f.lowest_elevation_m));
        st.run();
      }
    }
    // The statistics.
    {
      const CaseStatistics& s = outcome.statistics;
      auto kips = [](const std::optional<double>& n) {
        return n ? std::optional<double>(units::n_to_kips(*n)) : std::nullopt;
      };
      store::Statement del = db_.prepare("DELETE FROM results WHERE case_id = ?");
      del.bind(1, case_id);
      del.run();
      store::Statement st = db_.prepare(
          "INSERT INTO results (case_id, gumbel_u_kips, gumbel_alpha_per_kip, daily_max_mean_kips, "
          "daily_max_variance_kips2, dynamic_999_kips, dynamic_99_kips, empirical_999_kips, empirical_99_kips, "
          "ci_level, ci_low_kips, ci_high_kips, gumbel_ml_u_kips, gumbel_ml_alpha_per_kip, gev_mu_kips, "
          "gev_sigma_kips, gev_xi, anderson_darling, ppcc, max_daily_max_kips, breaking_strength_lbf, "
          "above_breaking_strength, slack_fraction, snatch_events_per_day, runtime_s, code_version) VALUES (?, ?, "
          "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
      st.bind(1, case_id)
          .bind(2, n_to_kips(s.gumbel_u_n))
          .bind(3, s.gumbel_alpha_per_n * newtons_per_kip)
          .bind(4, n_to_kips(s.daily_max_mean_n))
          .bind(5, n_to_kips(n_to_kips(s.daily_max_variance_n2)))
          .bind(6, n_to_kips(s.dynamic_999_n))
          .bind(7, n_to_kips(s.dynamic_99_n))
          .bind(8, kips(s.empirical_999_n))
          .bind(9, kips(s.empirical_99_n))
          .bind(10, s.ci_level)
          .bind(11, n_to_kips(s.ci_low_n))
          .bind(12, n_to_kips(s.ci_high_n))
          .bind(13, kips(s.gumbel_ml_u_n))
          .bind(14, s.gumbel_ml_alpha_per_n ? std::optional<double>(*s.gumbel_ml_alpha_per_n * newtons_per_kip)
                                            : std::nullopt)
          .bind(15, kips(s.gev_mu_n))
          .bind(16, kips(s.gev_sigma_n))
          .bind(17, s.gev_xi)
          .bind(18, s.anderson_darling)
          .bind(19, s.ppcc)
          .bind(20, n_to_kips(s.max_daily_max_n))
          .bind(21, n_to_lbf(s.breaking_strength_n))
          .bind(22, s.above_breaking_strength ? 1 : 0)
          .bind(23, s.slack_fraction)
          .bind(24, s.snatch_events_per_day)
          .bind(25, runtime_s)
          .bind(26, code_version);
      st.run();
    }
    // Every day, packed into one row (schema/004_case_days.sql).
    {
      store::CaseDays days;
      days.slack_snatch_stored = day_records_ == DayRecords::kAll;
      days.maxima_bytes = maxima_precision_ == MaximaPrecision::kBinary16 ? 2 : 4;
      for (const DayOutcome& day : outcome.days) {
        days.max_dynamic_kips.push_back(n_to_kips(day.max_dynamic_n));
        if (!days.slack_snatch_stored) continue;
        days.slack_time_s.push_back(day.slack_time_s);
        days.snatch_events.push_back(day.snatch_events);
      }
      store::write_case_days(db_, case_id, days);
    }
    store::Statement done = db_.prepare(
        "UPDATE cases SET status = 'done', error_message = NULL, fit_id = ?, build_id = ?, updated_utc = ? "
        "WHERE case_id = ?");
    done.bind(1, keys.fit_id).bind(2, build_id).bind(3, utc_now()).bind(4, case_id);
    done.run();
  });
}

int DatabaseWriter::drop_slack_snatch_days() {
  int dropped = 0;
  db_.transaction([&] { dropped = store::drop_slack_snatch_days(db_); });
  return dropped;
}

int DatabaseWriter::pack_maxima_binary16() {
  int changed = 0;
  db_.transaction([&] { changed = store::pack_maxima_binary16(db_); });
  return changed;
}

void DatabaseWriter::write_failure(std::int64_t case_id, const std::string& message, std::int64_t build_id) {
  db_.transaction([&] {
    store::Statement del = db_.prepare("DELETE FROM results WHERE case_id = ?");
    del.bind(1, case_id);
    del.run();
    store::Statement days = db_.prepare("DELETE FROM case_days WHERE case_id = ?");
    days.bind(1, case_id);
    days.run();
    store::Statement st = db_.prepare(
        "UPDATE cases SET status = 'failed', error_message = ?, fit_id = NULL, build_id = ?, updated_utc = ? "
        "WHERE case_id = ?");
    st.bind(1, message.empty() ? std::string("unknown error (no message)") : message)
        .bind(2, build_id)
        .bind(3, utc_now())
        .bind(4, case_id);
    st.run();
  });
}

std::vector<FitWithoutLowestPoint> DatabaseWriter::fits_without_lowest_point() {
  std::vector<FitWithoutLowestPoint> out;
  store::Statement st = db_.prepare(
      "SELECT f.fit_id, c.case_id FROM towline_fits f JOIN cases c ON c.fit_id = f.fit_id "
      "WHERE f.lowest_elevation_ft IS NULL AND c.status = 'done' ORDER BY f.fit_id, c.case_id");
  while (st.step()) out.push_back({st.column_int(0), st.column_int(1)});
  return out;
}

void DatabaseWriter::set_lowest_points(const std::vector<std::pair<std::int64_t, double>>& fit_id_elevation_m) {
  db_.transaction([&] {
    store::Statement st = db_.prepare("UPDATE towline_fits SET lowest_elevation_ft = ? WHERE fit_id = ?");
    for (const auto& [fit_id, elevation_m] : fit_id_elevation_m) {
      st.reset();
      st.bind(1, units::m_to_ft(elevation_m)).bind(2, fit_id);
      st.run();
    }
  });
}

}  // namespace towdb::sweep
