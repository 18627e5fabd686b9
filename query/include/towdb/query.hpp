// towdb/query.hpp -- a thin, header-only C++17 wrapper over the C API of
// towdb/query.h (equations, units and conventions are documented there).
// Owns the handle (RAII), copies every string the library returns, and turns
// error codes into towdb::query::QueryError carrying the code and message.
#ifndef TOWDB_QUERY_HPP
#define TOWDB_QUERY_HPP

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "towdb/query.h"

namespace towdb::query {

class QueryError : public std::runtime_error {
 public:
  QueryError(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }
  // A problem with the caller's input or database (the CLI's exit code 2).
  bool is_input() const {
    return code_ == TOWDB_QUERY_INPUT || code_ == TOWDB_QUERY_RANGE || code_ == TOWDB_QUERY_DATABASE ||
           code_ == TOWDB_QUERY_NUMERICAL;
  }

 private:
  int code_;
};

// A request; strings are owned here, numbers as in towdb_query_request.
struct QueryRequest {
  std::string tug, tow, line, spectrum;
  towdb_query_request values;
  QueryRequest() { towdb_query_request_init(&values); }
  towdb_query_request c_request() const {
    towdb_query_request r = values;
    r.tug = tug.c_str();
    r.tow = tow.c_str();
    r.line = line.c_str();
    r.spectrum = spectrum.empty() ? nullptr : spectrum.c_str();
    return r;
  }
};

struct QueryWarning {
  int kind;
  std::string message;
};

// The name of a TOWDB_QUERY_WARN_* kind as the JSON outputs write it (the
// CLI's `warnings[].kind`, the Python module's "kind"); "other" for a kind
// this header does not know.
inline const char* warning_kind_name(int kind) {
  switch (kind) {
    case TOWDB_QUERY_WARN_EXTRAPOLATED: return "extrapolated";
    case TOWDB_QUERY_WARN_ABOVE_BREAKING: return "above_breaking_strength";
    case TOWDB_QUERY_WARN_SLACK: return "slack_prone";
    case TOWDB_QUERY_WARN_NOT_MONOTONE: return "not_monotone";
    case TOWDB_QUERY_WARN_INCOMPLETE_GRID: return "incomplete_grid";
    case TOWDB_QUERY_WARN_HIGH_TENSION: return "high_tension";
    case TOWDB_QUERY_WARN_BREAKING_DIFFERS: return "breaking_strength_differs";
    case TOWDB_QUERY_WARN_ABOVE_CAPACITY: return "above_tug_capacity";
    case TOWDB_QUERY_WARN_EQUIVALENT_WIND: return "equivalent_wind";
    default: return "other";
  }
}

struct QueryResult {
  std::string tug, tow;  // the database's names of the matched vessels (towdb_query_names)
  towdb_query_result values{};
  std::vector<QueryWarning> warnings;
  std::vector<towdb_query_case> nearest;
};

struct InverseResult {
  towdb_query_search search{};
  QueryResult at_value;  // the answer at search.value (when found)
};

class Database {
 public:
  explicit Database(const std::string& path, int space = TOWDB_QUERY_SPACE_AUTO) {
    towdb_query_db* raw = nullptr;
    const int rc = towdb_query_open(path.c_str(), space, &raw);
    db_.reset(raw);
    if (rc != TOWDB_QUERY_OK) throw QueryError(rc, towdb_query_errmsg(raw));
  }

  int space() const { return towdb_query_space(db_.get()); }
  int case_count() const { return towdb_query_case_count(db_.get()); }

  QueryResult query(const QueryRequest& request) {
    const towdb_query_request r = request.c_request();
    QueryResult out;
    check(towdb_query_run(db_.get(), &r, &out.values));
    collect(&out);
    return out;
  }

  InverseResult max_speed(const QueryRequest& request) { return inverse(request, true); }
  InverseResult min_length(const QueryRequest& request) { return inverse(request, false); }

  towdb_query_loo leave_one_out(int space, int axis = TOWDB_QUERY_AXIS_ALL) {
    towdb_query_loo out{};
    check(towdb_query_leave_one_out(db_.get(), space, axis, &out));
    return out;
  }

  towdb_query_db* handle() { return db_.get(); }

 private:
  struct Closer {
    void operator()(towdb_query_db* db) const { towdb_query_close(db); }
  };

  void check(int rc) const {
    if (rc != TOWDB_QUERY_OK) throw QueryError(rc, towdb_query_errmsg(db_.get()));
  }

  void collect(QueryResult* out) const {
    int kind = 0;
    for (int i = 0; const char* w = towdb_query_warning(db_.get(), i, &kind); ++i) {
      out->warnings.push_back({kind, w});
    }
    towdb_query_case c{};
    for (int i = 0; towdb_query_nearest(db_.get(), i, &c) == TOWDB_QUERY_OK; ++i) out->nearest.push_back(c);
    const char* tug = nullptr;
    const char* tow = nullptr;
    if (towdb_query_names(db_.get(), &tug, &tow) == TOWDB_QUERY_OK) {
      out->tug = tug;
      out->tow = tow;
    }
  }

  InverseResult inverse(const QueryRequest& request, bool speed) {
    const towdb_query_request r = request.c_request();
    InverseResult out;
    check(speed ? towdb_query_max_speed(db_.get(), &r, &out.search, &out.at_value.values)
                : towdb_query_min_length(db_.get(), &r, &out.search, &out.at_value.values));
    collect(&out.at_value);
    return out;
  }

  std::unique_ptr<towdb_query_db, Closer> db_;
};

}  // namespace towdb::query

#endif  // TOWDB_QUERY_HPP
