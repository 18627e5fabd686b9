// The C API of towdb/query.h over the engine: every entry point catches every
// exception once and keeps its message in the handle (sqlite3_errmsg rule).
#include <cmath>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "common/version.hpp"
#include "engine.hpp"
#include "towdb/query.h"

struct towdb_query_db {
  std::unique_ptr<towdb::query::Engine> engine;
  int code = TOWDB_QUERY_OK;
  std::string errmsg;
  std::vector<towdb::query::Warning> warnings;
  std::vector<towdb::query::NearCase> nearest;
  std::string tug, tow;  // names of the last answer's vessels (towdb_query_names)
};

namespace {

using towdb::query::Answer;
using towdb::query::Engine;
using towdb::query::Request;

int fail(towdb_query_db* db, int code, const std::string& message) {
  db->code = code;
  db->errmsg = message;
  return code;
}

int ok(towdb_query_db* db) {
  db->code = TOWDB_QUERY_OK;
  db->errmsg.clear();
  return TOWDB_QUERY_OK;
}

// Runs `fn` and maps every exception to a code and a stored message.
template <typename Fn>
int guarded(towdb_query_db* db, Fn&& fn) {
  if (!db) return TOWDB_QUERY_MISUSE;
  try {
    fn();
    return ok(db);
  } catch (const towdb::query::DatabaseError& e) {
    return fail(db, TOWDB_QUERY_DATABASE, e.what());
  } catch (const towdb::query::OutOfRangeError& e) {
    return fail(db, TOWDB_QUERY_RANGE, e.what());
  } catch (const towdb::InputError& e) {
    return fail(db, TOWDB_QUERY_INPUT, e.what());
  } catch (const towdb::NumericalError& e) {
    return fail(db, TOWDB_QUERY_NUMERICAL, e.what());
  } catch (const towdb::StorageError& e) {
    return fail(db, TOWDB_QUERY_DATABASE, e.what());
  } catch (const std::bad_alloc&) {
    return fail(db, TOWDB_QUERY_NOMEM, "out of memory");
  } catch (const std::exception& e) {
    return fail(db, TOWDB_QUERY_ERROR, std::string("internal error: ") + e.what());
  } catch (...) {
    return fail(db, TOWDB_QUERY_ERROR, "internal error: unknown exception");
  }
}

Request to_request(const towdb_query_request* r) {
  Request q;
  q.tug = r->tug ? r->tug : "";
  q.tow = r->tow ? r->tow : "";
  q.line = r->line ? r->line : "";
  q.spectrum = r->spectrum ? r->spectrum : "";
  q.speed_kt = r->speed_kt;
  q.wind_kt = r->wind_kt;
  q.hs_ft = r->hs_ft;
  q.tp_s = r->tp_s;
  q.heading_deg = r->heading_deg;
  q.length_ft = r->length_ft;
  q.mean_tension_lbf = r->mean_tension_lbf;
  q.probability = r->probability;
  q.tow_days = r->tow_days;
  q.extrapolate = r->extrapolate != 0;
  q.on_brake = r->on_brake != 0;
  return q;
}

void to_result(const Answer& a, towdb_query_result* out) {
  out->dynamic_tension_kips = a.dynamic_tension_kips;
  out->dynamic_999_kips = a.dynamic_999_kips;
  out->mean_tension_lbf = a.mean_tension_lbf;
  out->extreme_tension_lbf = a.extreme_tension_lbf;
  out->breaking_strength_lbf = a.breaking_strength_lbf;
  out->extreme_limit_lbf = a.extreme_limit_lbf;
  out->mean_limit_lbf = a.mean_limit_lbf;
  out->extreme_check_passed = a.extreme_check_passed ? 1 : 0;
  out->mean_check_passed = a.mean_check_passed ? 1 : 0;
  out->gumbel_u_kips = a.gumbel_u_kips;
  out->gumbel_alpha_per_kip = a.gumbel_alpha_per_kip;
  out->interpolation_error_kips = a.interpolation_error_kips;
  out->ci_level = a.ci_level;
  out->ci_low_kips = a.ci_low_kips;
  out->ci_high_kips = a.ci_high_kips;
  out->uncertainty_kips = a.uncertainty_kips;
  out->slack_fraction = a.slack_fraction;
  out->interpolation_space = static_cast<int>(a.space);
  out->extrapolated = a.extrapolated ? 1 : 0;
  out->warning_count = static_cast<int>(a.warnings.size());
  out->nearest_count = static_cast<int>(a.nearest.size());
  out->calculated_mean_tension_lbf = a.calculated_mean_tension_lbf;
  out->mean_tension_factor = a.mean_tension_factor;
  out->catenary_sag_ft = a.catenary_sag_ft;
  out->catenary_depth_ft = a.catenary_depth_ft;
  out->equivalent_wind_kt = a.equivalent_wind_kt;
}

int run_search(towdb_query_db* db, const towdb_query_request* request, towdb_query_search* search,
               towdb_query_result* at_value, bool speed) {
  if (!db) return TOWDB_QUERY_MISUSE;
  if (!request || !search) return fail(db, TOWDB_QUERY_MISUSE, "towdb_query search: request and search must not be NULL");
  if (!db->engine) return fail(db, TOWDB_QUERY_MISUSE, "the database is not open (towdb_query_open failed)");
  return guarded(db, [&] {
    db->warnings.clear();
    db->nearest.clear();
    db->tug.clear();
    db->tow.clear();
    Request q = to_request(request);
    const towdb::query::SearchResult s = speed ? db->engine->max_speed(q) : db->engine->min_length(q);
    search->found = s.found ? 1 : 0;
    search->value = s.found ? s.value : towdb::query::kNaN;
    search->range_low = s.range_low;
    search->range_high = s.range_high;
    search->evaluations = s.evaluations;
    std::vector<towdb::query::Warning> warnings = s.warnings;
    if (at_value) {
      std::memset(at_value, 0, sizeof *at_value);
      if (s.found) {
        (speed ? q.speed_kt : q.length_ft) = s.value;
        q.extrapolate = false;  // as the search answered it: never extrapolated (query.h)
        Answer a = db->engine->query(q);
        to_result(a, at_value);
        db->tug = a.tug;
        db->tow = a.tow;
        warnings.insert(warnings.end(), a.warnings.begin(), a.warnings.end());
        db->nearest = std::move(a.nearest);
        at_value->warning_count = static_cast<int>(warnings.size());
      }
    }
    db->warnings = std::move(warnings);
  });
}

}  // namespace

extern "C" {

const char* towdb_query_version(void) { return towdb::kVersion; }

int towdb_query_open(const char* path, int space, towdb_query_db** out) {
  if (!out) return TOWDB_QUERY_MISUSE;
  *out = new (std::nothrow) towdb_query_db;
  if (!*out) return TOWDB_QUERY_NOMEM;
  towdb_query_db* db = *out;
  if (!path) return fail(db, TOWDB_QUERY_MISUSE, "towdb_query_open: path must not be NULL");
  if (space != TOWDB_QUERY_SPACE_AUTO && space != TOWDB_QUERY_SPACE_LINEAR && space != TOWDB_QUERY_SPACE_LOG) {
    return fail(db, TOWDB_QUERY_INPUT,
                "space = " + std::to_string(space) + ": must be TOWDB_QUERY_SPACE_AUTO, _LINEAR or _LOG (0, 1, 2)");
  }
  return guarded(db, [&] {
    db->engine = std::make_unique<Engine>(Engine::open(path, static_cast<towdb::query::Space>(space)));
  });
}

void towdb_query_close(towdb_query_db* db) { delete db; }

const char* towdb_query_errmsg(const towdb_query_db* db) {
  if (!db) return "out of memory or NULL handle";
  return db->errmsg.c_str();
}

int towdb_query_errcode(const towdb_query_db* db) { return db ? db->code : TOWDB_QUERY_MISUSE; }

int towdb_query_case_count(const towdb_query_db* db) { return db && db->engine ? db->engine->case_count() : 0; }

int towdb_query_space(const towdb_query_db* db) {
  return db && db->engine ? static_cast<int>(db->engine->space()) : TOWDB_QUERY_SPACE_AUTO;
}

void towdb_query_request_init(towdb_query_request* r) {
  if (!r) return;
  const double nan = towdb::query::kNaN;
  r->tug = r->tow = r->line = r->spectrum = nullptr;
  r->speed_kt = r->wind_kt = r->hs_ft = r->tp_s = r->heading_deg = r->length_ft = r->mean_tension_lbf = nan;
  r->probability = 0.001;
  r->tow_days = 1.0;
  r->extrapolate = 0;
  r->on_brake = 0;
}

int towdb_query_run(towdb_query_db* db, const towdb_query_request* request, towdb_query_result* result) {
  if (!db) return TOWDB_QUERY_MISUSE;
  if (!request || !result) return fail(db, TOWDB_QUERY_MISUSE, "towdb_query_run: request and result must not be NULL");
  if (!db->engine) return fail(db, TOWDB_QUERY_MISUSE, "the database is not open (towdb_query_open failed)");
  return guarded(db, [&] {
    db->warnings.clear();
    db->nearest.clear();
    db->tug.clear();
    db->tow.clear();
    Answer a = db->engine->query(to_request(request));
    to_result(a, result);
    db->warnings = std::move(a.warnings);
    db->nearest = std::move(a.nearest);
    db->tug = std::move(a.tug);
    db->tow = std::move(a.tow);
  });
}

int towdb_query_names(const towdb_query_db* db, const char** tug, const char** tow) {
  if (!db || !tug || !tow || db->tug.empty()) return TOWDB_QUERY_MISUSE;
  *tug = db->tug.c_str();
  *tow = db->tow.c_str();
  return TOWDB_QUERY_OK;
}

const char* towdb_query_warning(const towdb_query_db* db, int index, int* kind) {
  if (!db || index < 0 || static_cast<std::size_t>(index) >= db->warnings.size()) return nullptr;
  const auto& w = db->warnings[static_cast<std::size_t>(index)];
  if (kind) *kind = static_cast<int>(w.kind);
  return w.message.c_str();
}

int towdb_query_nearest(const towdb_query_db* db, int index, towdb_query_case* out) {
  if (!db || !out || index < 0 || static_cast<std::size_t>(index) >= db->nearest.size()) return TOWDB_QUERY_MISUSE;
  const auto& n = db->nearest[static_cast<std::size_t>(index)];
  out->case_id = n.case_id;
  out->speed_kt = n.speed_kt;
  out->wind_kt = n.wind_kt;
  out->hs_ft = n.hs_ft;
  out->tp_s = n.tp_s;
  out->heading_deg = n.heading_deg;
  out->length_ft = n.length_ft;
  out->mean_tension_lbf = n.mean_tension_lbf;
  out->days = n.days;
  out->dynamic_999_kips = n.dynamic_999_kips;
  out->dynamic_tension_kips = n.dynamic_tension_kips;
  out->distance = n.distance;
  return TOWDB_QUERY_OK;
}

int towdb_query_max_speed(towdb_query_db* db, const towdb_query_request* request, towdb_query_search* search,
                          towdb_query_result* at_value) {
  return run_search(db, request, search, at_value, true);
}

int towdb_query_min_length(towdb_query_db* db, const towdb_query_request* request, towdb_query_search* search,
                           towdb_query_result* at_value) {
  return run_search(db, request, search, at_value, false);
}

int towdb_query_leave_one_out(towdb_query_db* db, int space, int axis, towdb_query_loo* out) {
  if (!db) return TOWDB_QUERY_MISUSE;
  if (!out) return fail(db, TOWDB_QUERY_MISUSE, "towdb_query_leave_one_out: out must not be NULL");
  if (!db->engine) return fail(db, TOWDB_QUERY_MISUSE, "the database is not open (towdb_query_open failed)");
  if (space != TOWDB_QUERY_SPACE_LINEAR && space != TOWDB_QUERY_SPACE_LOG) {
    return fail(db, TOWDB_QUERY_INPUT, "space = " + std::to_string(space) + ": must be TOWDB_QUERY_SPACE_LINEAR (1) or _LOG (2)");
  }
  return guarded(db, [&] {
    const towdb::query::LooStats s = db->engine->leave_one_out(static_cast<towdb::query::Space>(space), axis);
    out->space = static_cast<int>(s.space);
    out->axis = s.axis;
    out->samples = s.samples;
    out->median_rel_error = s.median_rel_error;
    out->p90_rel_error = s.p90_rel_error;
    out->max_rel_error = s.max_rel_error;
    out->median_abs_error_kips = s.median_abs_error_kips;
  });
}

}  // extern "C"
