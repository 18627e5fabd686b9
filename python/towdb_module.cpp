// The Python module `towdb` (pybind11) over the C API of towdb/query.h: open a
// database, ask one question or a list of them, get dicts (or a pandas
// DataFrame). Equations, units and conventions are those of towdb/query.h;
// every key carries its unit (speed_kt, extreme_tension_lbf, ...), as in
// `towdb query --json`. Only the public C API is used, never the engine.
//
// Errors: the C API's codes become exceptions, each carrying .code (the
// TOWDB_QUERY_* value), .field (the request field named by the message, or
// None) and the library's message, which names the field, the value and what
// is allowed:
//   towdb.Error                     base (RuntimeError); codes 1, 6, 7
//   towdb.InputError(Error, ValueError)   TOWDB_QUERY_INPUT, and bad Python
//                                   input (unknown key, a string for a number)
//   towdb.OutOfRangeError(InputError)     TOWDB_QUERY_RANGE
//   towdb.DatabaseError(Error)      TOWDB_QUERY_DATABASE
//   towdb.NumericalError(Error)     TOWDB_QUERY_NUMERICAL
// A handle is used under the GIL, so one Database is never used from two
// threads at once (the C API's rule).
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "towdb/query.h"
#include "towdb/query.hpp"

namespace py = pybind11;
using towdb::query::warning_kind_name;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- exceptions ---------------------------------------------------------------

struct Exceptions {
  py::object error, input, range, database, numerical;
};
Exceptions& exceptions() {
  static Exceptions e;
  return e;
}

// The request fields, as named in messages, batch CSV columns and dict keys.
const std::vector<std::string>& field_names() {
  static const std::vector<std::string> names = {
      "tug",         "tow",       "line",             "spectrum",    "speed_kt", "wind_kt",     "hs_ft", "tp_s",
      "heading_deg", "length_ft", "mean_tension_lbf", "probability", "tow_days", "extrapolate", "brake"};
  return names;
}

// The field a message names: its first word when that is a request field
// ("speed_kt = 12 is outside ...", "tug 'x' is not in the database").
py::object field_of(const std::string& message) {
  const std::size_t end = message.find_first_of(" =:'");
  const std::string first = message.substr(0, end);
  for (const auto& f : field_names()) {
    if (f == first) return py::str(f);
  }
  return py::none();
}

[[noreturn]] void throw_error(int code, const std::string& message, const py::object& field = py::none()) {
  const Exceptions& e = exceptions();
  py::object cls = code == TOWDB_QUERY_INPUT       ? e.input
                   : code == TOWDB_QUERY_RANGE     ? e.range
                   : code == TOWDB_QUERY_DATABASE  ? e.database
                   : code == TOWDB_QUERY_NUMERICAL ? e.numerical
                                                   : e.error;
  py::object exc = cls(message);
  exc.attr("code") = code;
  exc.attr("field") = field.is_none() ? field_of(message) : field;
  PyErr_SetObject(cls.ptr(), exc.ptr());
  throw py::error_already_set();
}

[[noreturn]] void raise_input(const std::string& message) { throw_error(TOWDB_QUERY_INPUT, message); }

py::object make_exception(py::module_& m, const char* name, py::tuple bases, const char* doc) {
  const std::string qualified = std::string("towdb.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  py::object cls = py::reinterpret_steal<py::object>(type);
  m.attr(name) = cls;
  return cls;
}

// ---- request ------------------------------------------------------------------

// A request with its strings owned here (the C request points into them).
using Question = towdb::query::QueryRequest;

std::string repr_text(const py::handle& v) { return py::repr(v).cast<std::string>(); }

// A real number (int, float, numpy scalar; not bool or str); None and NaN mean
// "not given" (NaN), as in a DataFrame row with an empty cell.
double number(const std::string& field, const py::handle& v) {
  if (v.is_none()) return kNaN;
  if (PyBool_Check(v.ptr()) || PyUnicode_Check(v.ptr()) || PyBytes_Check(v.ptr()) || !PyNumber_Check(v.ptr())) {
    raise_input(field + " = " + repr_text(v) + ": not a number; allowed: a real number (int or float)");
  }
  PyObject* f = PyNumber_Float(v.ptr());
  if (!f) {
    PyErr_Clear();
    raise_input(field + " = " + repr_text(v) + ": not a number; allowed: a real number (int or float)");
  }
  const double x = PyFloat_AsDouble(f);
  Py_DECREF(f);
  if (std::isinf(x)) raise_input(field + " = " + repr_text(v) + ": not finite; allowed: a finite number");
  return x;
}

std::string text(const std::string& field, const py::handle& v) {
  if (v.is_none()) return "";
  if (!PyUnicode_Check(v.ptr())) raise_input(field + " = " + repr_text(v) + ": not a string; allowed: a name (str)");
  return v.cast<std::string>();
}

bool flag(const std::string& field, const py::handle& v) {
  if (v.is_none()) return false;
  if (!PyBool_Check(v.ptr()) && !PyLong_Check(v.ptr())) {
    raise_input(field + " = " + repr_text(v) + ": not a flag; allowed: True or False");
  }
  return v.cast<bool>();
}

// Fills a Question from a mapping of field names; unknown keys are refused.
// `needs` lists the numeric fields this call requires (a search leaves out the
// one it searches).
Question to_question(const py::dict& d, const std::vector<std::string>& needs) {
  Question q;
  towdb_query_request& r = q.values;
  for (const auto& [key, value] : d) {
    if (!PyUnicode_Check(key.ptr())) raise_input("question key " + repr_text(key) + ": not a field name (str)");
    const std::string k = key.cast<std::string>();
    if (k == "tug") q.tug = text(k, value);
    else if (k == "tow") q.tow = text(k, value);
    else if (k == "line") q.line = text(k, value);
    else if (k == "spectrum") q.spectrum = text(k, value);
    else if (k == "speed_kt") r.speed_kt = number(k, value);
    else if (k == "wind_kt") r.wind_kt = number(k, value);
    else if (k == "hs_ft") r.hs_ft = number(k, value);
    else if (k == "tp_s") r.tp_s = number(k, value);
    else if (k == "heading_deg") r.heading_deg = number(k, value);
    else if (k == "length_ft") r.length_ft = number(k, value);
    else if (k == "mean_tension_lbf") r.mean_tension_lbf = number(k, value);
    else if (k == "probability") r.probability = value.is_none() ? r.probability : number(k, value);
    else if (k == "tow_days") r.tow_days = value.is_none() ? r.tow_days : number(k, value);
    else if (k == "extrapolate") r.extrapolate = flag(k, value) ? 1 : 0;
    else if (k == "brake") r.on_brake = flag(k, value) ? 1 : 0;
    else {
      std::string known;
      for (const auto& f : field_names()) known += (known.empty() ? "" : ", ") + f;
      throw_error(TOWDB_QUERY_INPUT, k + ": unknown field; allowed: " + known, py::str(k));
    }
  }
  for (const char* s : {"tug", "tow", "line"}) {
    const std::string& v = s == std::string("tug") ? q.tug : s == std::string("tow") ? q.tow : q.line;
    if (v.empty()) raise_input(std::string(s) + ": required (a name)");
  }
  for (const auto& n : needs) {
    const double v = n == "speed_kt" ? r.speed_kt : n == "heading_deg" ? r.heading_deg : r.length_ft;
    if (std::isnan(v)) raise_input(n + ": required (a number)");
  }
  if (std::isnan(r.wind_kt) && std::isnan(r.hs_ft)) raise_input("wind_kt: required (or hs_ft for a two-parameter sea)");
  return q;
}

// ---- answers -------------------------------------------------------------------

py::object nullable(double v) { return std::isfinite(v) ? py::object(py::float_(v)) : py::none(); }

// The answer as a flat dict: the question (vessels named as the database names
// them), the answer's numbers with their units, the two Towing Manual checks
// with margins (limit - value; negative when failed), warnings and the
// nearest stored cases.
py::dict answer_dict(const towdb_query_db* db, const Question& q, const towdb_query_result& v) {
  py::dict d;
  const char* tug = nullptr;
  const char* tow = nullptr;
  const bool named = towdb_query_names(db, &tug, &tow) == TOWDB_QUERY_OK;
  const towdb_query_request& r = q.values;
  d["tug"] = named ? std::string(tug) : q.tug;
  d["tow"] = named ? std::string(tow) : q.tow;
  d["line"] = q.line;
  d["speed_kt"] = nullable(r.speed_kt);
  d["wind_kt"] = nullable(r.wind_kt);
  d["hs_ft"] = nullable(r.hs_ft);
  d["tp_s"] = nullable(r.tp_s);
  d["heading_deg"] = nullable(r.heading_deg);
  d["length_ft"] = nullable(r.length_ft);
  d["probability"] = r.probability;
  d["tow_days"] = r.tow_days;
  d["on_brake"] = r.on_brake != 0;
  d["mean_tension_lbf"] = v.mean_tension_lbf;
  d["calculated_mean_tension_lbf"] = nullable(v.calculated_mean_tension_lbf);
  d["mean_tension_factor"] = nullable(v.mean_tension_factor);
  d["dynamic_tension_kips"] = v.dynamic_tension_kips;
  d["dynamic_999_kips"] = v.dynamic_999_kips;
  d["extreme_tension_lbf"] = v.extreme_tension_lbf;
  d["breaking_strength_lbf"] = v.breaking_strength_lbf;
  d["extreme_limit_lbf"] = v.extreme_limit_lbf;
  d["extreme_check_passed"] = v.extreme_check_passed != 0;
  d["extreme_margin_lbf"] = v.extreme_limit_lbf - v.extreme_tension_lbf;
  d["extreme_margin_percent"] = 100.0 * (v.extreme_limit_lbf - v.extreme_tension_lbf) / v.extreme_limit_lbf;
  d["mean_limit_lbf"] = v.mean_limit_lbf;
  d["mean_check_passed"] = v.mean_check_passed != 0;
  d["mean_margin_lbf"] = v.mean_limit_lbf - v.mean_tension_lbf;
  d["mean_margin_percent"] = 100.0 * (v.mean_limit_lbf - v.mean_tension_lbf) / v.mean_limit_lbf;
  d["gumbel_u_kips"] = v.gumbel_u_kips;
  d["gumbel_alpha_per_kip"] = v.gumbel_alpha_per_kip;
  d["uncertainty_kips"] = v.uncertainty_kips;
  d["interpolation_error_kips"] = v.interpolation_error_kips;
  d["ci_level"] = nullable(v.ci_level);
  d["ci_low_kips"] = nullable(v.ci_low_kips);
  d["ci_high_kips"] = nullable(v.ci_high_kips);
  d["slack_fraction"] = v.slack_fraction;
  d["catenary_sag_ft"] = nullable(v.catenary_sag_ft);
  d["catenary_depth_ft"] = nullable(v.catenary_depth_ft);
  d["equivalent_wind_kt"] = nullable(v.equivalent_wind_kt);
  d["interpolation_space"] = v.interpolation_space == TOWDB_QUERY_SPACE_LOG ? "log" : "linear";
  d["extrapolated"] = v.extrapolated != 0;
  py::list warnings;
  int kind = 0;
  for (int i = 0; const char* w = towdb_query_warning(db, i, &kind); ++i) {
    py::dict x;
    x["kind"] = warning_kind_name(kind);
    x["message"] = std::string(w);
    warnings.append(x);
  }
  d["warnings"] = warnings;
  py::list nearest;
  towdb_query_case c{};
  for (int i = 0; towdb_query_nearest(db, i, &c) == TOWDB_QUERY_OK; ++i) {
    py::dict x;
    x["case_id"] = c.case_id;
    x["speed_kt"] = c.speed_kt;
    x["wind_kt"] = nullable(c.wind_kt);
    x["hs_ft"] = nullable(c.hs_ft);
    x["tp_s"] = nullable(c.tp_s);
    x["heading_deg"] = c.heading_deg;
    x["length_ft"] = c.length_ft;
    x["mean_tension_lbf"] = c.mean_tension_lbf;
    x["days"] = c.days;
    x["dynamic_999_kips"] = c.dynamic_999_kips;
    x["dynamic_tension_kips"] = c.dynamic_tension_kips;
    x["distance"] = c.distance;
    nearest.append(x);
  }
  d["nearest_cases"] = nearest;
  return d;
}

// ---- the database ----------------------------------------------------------------

int space_code(const std::string& space) {
  if (space == "auto") return TOWDB_QUERY_SPACE_AUTO;
  if (space == "linear") return TOWDB_QUERY_SPACE_LINEAR;
  if (space == "log") return TOWDB_QUERY_SPACE_LOG;
  raise_input("space = '" + space + "': allowed: 'auto', 'linear' or 'log'");
}

class Database {
 public:
  Database(const std::string& path, const std::string& space) : path_(path) {
    const int code = space_code(space);
    towdb_query_db* raw = nullptr;
    const int rc = towdb_query_open(path.c_str(), code, &raw);
    db_.reset(raw);
    if (!raw) throw_error(TOWDB_QUERY_NOMEM, "out of memory opening " + path);
    if (rc != TOWDB_QUERY_OK) throw_error(rc, towdb_query_errmsg(raw));
  }

  py::dict query(const py::dict& question) {
    const Question q = to_question(question, {"speed_kt", "heading_deg", "length_ft"});
    const towdb_query_request r = q.c_request();
    towdb_query_result v{};
    check(towdb_query_run(handle(), &r, &v));
    return answer_dict(handle(), q, v);
  }

  // errors = "raise": the first failing question raises (its index in the
  // message); "record": its dict is {"error", "error_code", "error_field"}
  // with the question's own keys, and the others are answered.
  py::list query_many(const py::iterable& questions, const std::string& errors) {
    if (errors != "raise" && errors != "record") {
      raise_input("errors = '" + errors + "': allowed: 'raise' or 'record'");
    }
    py::list out;
    int index = 0;
    for (const py::handle& item : questions) {
      if (!py::isinstance<py::dict>(item)) {
        raise_input("questions[" + std::to_string(index) + "] = " + repr_text(item) + ": not a dict of fields");
      }
      try {
        out.append(query(py::reinterpret_borrow<py::dict>(item)));
      } catch (py::error_already_set& e) {
        if (errors == "raise" || !e.matches(exceptions().error)) throw;
        py::dict failed(py::reinterpret_borrow<py::dict>(item));
        failed["error"] = py::str(e.value());
        failed["error_code"] = e.value().attr("code");
        failed["error_field"] = e.value().attr("field");
        out.append(failed);
      }
      ++index;
    }
    return out;
  }

  // The highest speed (or shortest towline) in the stored range that passes
  // both Towing Manual checks within the tugs' capacity (query.h).
  py::dict search(const py::dict& question, bool speed) {
    const Question q = to_question(question, {speed ? "length_ft" : "speed_kt", "heading_deg"});
    const towdb_query_request r = q.c_request();
    towdb_query_search s{};
    towdb_query_result v{};
    check(speed ? towdb_query_max_speed(handle(), &r, &s, &v) : towdb_query_min_length(handle(), &r, &s, &v));
    py::dict d;
    d["found"] = s.found != 0;
    d[speed ? "max_speed_kt" : "min_length_ft"] = nullable(s.value);
    d[speed ? "searched_speed_kt" : "searched_length_ft"] = py::make_tuple(s.range_low, s.range_high);
    d["evaluations"] = s.evaluations;
    if (s.found) {
      Question at = q;
      (speed ? at.values.speed_kt : at.values.length_ft) = s.value;
      d["at_value"] = answer_dict(handle(), at, v);
    } else {
      d["at_value"] = py::none();
    }
    return d;
  }

  int case_count() { return towdb_query_case_count(handle()); }
  std::string space() { return towdb_query_space(handle()) == TOWDB_QUERY_SPACE_LOG ? "log" : "linear"; }
  const std::string& path() const { return path_; }
  void close() { db_.reset(); }

 private:
  struct Closer {
    void operator()(towdb_query_db* db) const { towdb_query_close(db); }
  };
  towdb_query_db* handle() {
    if (!db_) throw_error(TOWDB_QUERY_MISUSE, "the database " + path_ + " is closed");
    return db_.get();
  }
  void check(int rc) {
    if (rc != TOWDB_QUERY_OK) throw_error(rc, towdb_query_errmsg(db_.get()));
  }
  std::string path_;
  std::unique_ptr<towdb_query_db, Closer> db_;
};

// Keyword arguments or one dict (not both): the question's fields.
py::dict merge_question(const py::object& question, const py::kwargs& fields) {
  if (question.is_none()) return py::dict(fields);
  if (!py::isinstance<py::dict>(question)) raise_input("question = " + repr_text(question) + ": not a dict of fields");
  if (py::len(fields) > 0) raise_input("question: give a dict or keyword fields, not both");
  return py::reinterpret_borrow<py::dict>(question);
}

// One row per answer for a DataFrame: the nested lists flattened to text
// (warnings joined by " | ") or left out (the nearest cases).
py::list frame_rows(const py::list& answers) {
  py::list rows;
  for (const py::handle& a : answers) {
    py::dict row;
    for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(a)) {
      const std::string key = k.cast<std::string>();
      if (key == "nearest_cases") continue;
      if (key == "warnings") {
        std::string joined;
        for (const py::handle& w : v) joined += (joined.empty() ? "" : " | ") + w["message"].cast<std::string>();
        row["warnings"] = joined;
        continue;
      }
      row[k] = v;
    }
    rows.append(row);
  }
  return rows;
}

}  // namespace

PYBIND11_MODULE(towdb, m) {
  m.doc() =
      "towdb: extreme towline tension for open-ocean towing, answered from a towdb database through the query "
      "library's C API (towdb/query.h). Units are in every key: kt, ft, lbf, kips, deg, s.";
  m.attr("__version__") = towdb_query_version();

  Exceptions& e = exceptions();
  e.error = make_exception(m, "Error", py::make_tuple(py::handle(PyExc_RuntimeError)),
                           "A towdb query failed; .code is the TOWDB_QUERY_* code, .field the field named (or None).");
  e.input = make_exception(m, "InputError", py::make_tuple(e.error, py::handle(PyExc_ValueError)),
                           "A bad question: the message names the field, the value and what is allowed.");
  e.range = make_exception(m, "OutOfRangeError", py::make_tuple(e.input),
                           "Outside the stored data (extrapolate=True answers with a warning).");
  e.database = make_exception(m, "DatabaseError", py::make_tuple(e.error),
                              "Missing, corrupt or unfinished database.");
  e.numerical = make_exception(m, "NumericalError", py::make_tuple(e.error),
                               "The interpolant is not physical there.");

  py::class_<Database>(m, "Database",
                       "A towdb database opened read-only. Fields of a question: tug, tow, line ('wire' or 'fiber'), "
                       "speed_kt, wind_kt (or hs_ft [, tp_s]), heading_deg (0 = following seas), length_ft; "
                       "optional mean_tension_lbf (default: the calculated mean tension, query.h EQ-QUERY-9), "
                       "probability (0.001), tow_days (1), extrapolate, brake, spectrum.")
      .def(py::init<const std::string&, const std::string&>(), py::arg("path"), py::arg("space") = "auto")
      .def(
          "query",
          [](Database& db, const py::object& question, const py::kwargs& fields) {
            return db.query(merge_question(question, fields));
          },
          py::arg("question") = py::none(),
          "Answers one question (a dict, or keyword fields): a dict of the answer.")
      .def("query_many", &Database::query_many, py::arg("questions"), py::arg("errors") = "raise",
           "Answers a list of questions: a list of dicts. errors='record' keeps going and puts the error in the "
           "failing question's dict (keys error, error_code, error_field).")
      .def(
          "query_frame",
          [](Database& db, const py::iterable& questions, const std::string& errors) {
            py::module_ pandas;
            try {
              pandas = py::module_::import("pandas");
            } catch (py::error_already_set& err) {
              if (!err.matches(PyExc_ImportError)) throw;
              throw py::import_error(
                  "query_frame needs pandas (Debian package python3-pandas); query_many returns plain dicts");
            }
            return pandas.attr("DataFrame")(frame_rows(db.query_many(questions, errors)));
          },
          py::arg("questions"), py::arg("errors") = "record",
          "Answers a list of questions as a pandas DataFrame, one row per question (warnings joined by ' | ', "
          "nearest cases left out; failed rows carry error, error_code, error_field).")
      .def(
          "max_speed",
          [](Database& db, const py::object& question, const py::kwargs& fields) {
            return db.search(merge_question(question, fields), true);
          },
          py::arg("question") = py::none(),
          "Highest speed in the stored range that passes both Towing Manual checks within the tugs' capacity.")
      .def(
          "min_length",
          [](Database& db, const py::object& question, const py::kwargs& fields) {
            return db.search(merge_question(question, fields), false);
          },
          py::arg("question") = py::none(), "Shortest towline in the stored range that passes both checks.")
      .def_property_readonly("case_count", &Database::case_count, "Finished cases loaded.")
      .def_property_readonly("space", &Database::space, "Interpolation space chosen when opening: linear or log.")
      .def_property_readonly("path", &Database::path)
      .def("close", &Database::close, "Closes the handle; later calls raise towdb.Error.")
      .def("__enter__", [](Database& db) -> Database& { return db; }, py::return_value_policy::reference)
      .def("__exit__", [](Database& db, const py::args&) { db.close(); });

  m.def(
      "open", [](const std::string& path, const std::string& space) { return Database(path, space); },
      py::arg("path"), py::arg("space") = "auto", "Opens a towdb database read-only (towdb.Database).");
}
