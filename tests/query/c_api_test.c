/* The C API of towdb/query.h, exercised from C (compiled as C11): every
 * misuse returns a code and a message and never crashes. The C++ driver
 * (c_api_driver_test.cpp) writes the database and checks the failure count.
 * Test plan:
 *   capi-1  version string; NULL-safe close and errmsg
 *   capi-2  open: NULL arguments, missing file, bad space -> codes and messages
 *   capi-3  request_init defaults; a valid query reproduces the stored value
 *   capi-4  bad queries (unknown tug, NaN, heading 400, p = 0 and 1, length < 0,
 *           out of range) -> INPUT or RANGE with a message naming the field
 *   capi-5  accessors out of range -> NULL / MISUSE; errcode resets after success
 *   capi-6  inverse query and leave-one-out through the C API
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "towdb/query.h"

static int failures;
static char* log_buffer;
static size_t log_size;

static void note(const char* fmt, ...) {
  size_t used = strlen(log_buffer);
  va_list ap;
  if (used + 1 >= log_size) return;
  va_start(ap, fmt);
  vsnprintf(log_buffer + used, log_size - used, fmt, ap);
  va_end(ap);
}

#define CHECK(cond)                                          \
  do {                                                       \
    if (!(cond)) {                                           \
      ++failures;                                            \
      note("c_api_test.c:%d: failed: %s\n", __LINE__, #cond); \
    }                                                        \
  } while (0)

static int contains(const char* text, const char* part) { return text != NULL && strstr(text, part) != NULL; }

static towdb_query_request valid_request(void) {
  towdb_query_request r;
  towdb_query_request_init(&r);
  r.tug = "T-ATF 166";
  r.tow = "LHA 1";
  r.line = "wire";
  r.speed_kt = 5.0;
  r.wind_kt = 20.0;
  r.heading_deg = 0.0;
  r.length_ft = 2000.0;
  r.mean_tension_lbf = 60000.0;
  return r;
}

static void expect_query_error(towdb_query_db* db, towdb_query_request r, int code, const char* text) {
  towdb_query_result res;
  int rc = towdb_query_run(db, &r, &res);
  CHECK(rc == code);
  CHECK(towdb_query_errcode(db) == code);
  if (!contains(towdb_query_errmsg(db), text)) {
    ++failures;
    note("expected message containing '%s', got '%s'\n", text, towdb_query_errmsg(db));
  }
}

int towdb_c_api_checks(const char* good_path, const char* missing_path, double expected_999_kips, char* log,
                       size_t size) {
  towdb_query_db* db = NULL;
  towdb_query_request r;
  towdb_query_result res;
  towdb_query_search search;
  towdb_query_loo loo;
  towdb_query_case near_case;
  int kind = 0;
  int rc;
  failures = 0;
  log_buffer = log;
  log_size = size;
  log[0] = '\0';

  /* capi-1 */
  CHECK(towdb_query_version() != NULL && strlen(towdb_query_version()) > 0);
  towdb_query_close(NULL);
  CHECK(towdb_query_errmsg(NULL) != NULL);
  CHECK(towdb_query_errcode(NULL) == TOWDB_QUERY_MISUSE);

  /* capi-2 */
  CHECK(towdb_query_open(good_path, TOWDB_QUERY_SPACE_AUTO, NULL) == TOWDB_QUERY_MISUSE);
  rc = towdb_query_open(NULL, TOWDB_QUERY_SPACE_AUTO, &db);
  CHECK(rc == TOWDB_QUERY_MISUSE && db != NULL);
  towdb_query_close(db);
  db = NULL;
  rc = towdb_query_open(missing_path, TOWDB_QUERY_SPACE_AUTO, &db);
  CHECK(rc == TOWDB_QUERY_DATABASE);
  CHECK(db != NULL && contains(towdb_query_errmsg(db), "database does not exist"));
  r = valid_request();
  CHECK(towdb_query_run(db, &r, &res) == TOWDB_QUERY_MISUSE); /* not open */
  CHECK(towdb_query_case_count(db) == 0);
  towdb_query_close(db);
  db = NULL;
  rc = towdb_query_open(good_path, 42, &db);
  CHECK(rc == TOWDB_QUERY_INPUT && contains(towdb_query_errmsg(db), "space = 42"));
  towdb_query_close(db);
  db = NULL;

  /* capi-3 */
  towdb_query_request_init(NULL);
  towdb_query_request_init(&r);
  CHECK(r.probability == 0.001 && r.tow_days == 1.0 && r.extrapolate == 0 && r.on_brake == 0);
  CHECK(isnan(r.speed_kt) && isnan(r.mean_tension_lbf) && r.tug == NULL);
  rc = towdb_query_open(good_path, TOWDB_QUERY_SPACE_AUTO, &db);
  CHECK(rc == TOWDB_QUERY_OK && towdb_query_errcode(db) == TOWDB_QUERY_OK);
  CHECK(towdb_query_case_count(db) > 0);
  CHECK(towdb_query_space(db) == TOWDB_QUERY_SPACE_LINEAR || towdb_query_space(db) == TOWDB_QUERY_SPACE_LOG);
  r = valid_request();
  rc = towdb_query_run(db, &r, &res);
  CHECK(rc == TOWDB_QUERY_OK);
  CHECK(fabs(res.dynamic_999_kips - expected_999_kips) <= 1e-12 * expected_999_kips);
  CHECK(res.nearest_count >= 1);
  CHECK(towdb_query_nearest(db, 0, &near_case) == TOWDB_QUERY_OK && near_case.case_id > 0);
  /* The database's names of the vessels matched, whatever the spelling asked. */
  {
    const char* tug_name = NULL;
    const char* tow_name = NULL;
    r.tug = "tatf";
    r.tow = "lha-1";
    CHECK(towdb_query_run(db, &r, &res) == TOWDB_QUERY_OK);
    CHECK(towdb_query_names(db, &tug_name, &tow_name) == TOWDB_QUERY_OK);
    CHECK(tug_name != NULL && strcmp(tug_name, "T-ATF 166") == 0);
    CHECK(tow_name != NULL && strcmp(tow_name, "LHA 1") == 0);
    CHECK(towdb_query_names(db, NULL, &tow_name) == TOWDB_QUERY_MISUSE);
    CHECK(towdb_query_names(NULL, &tug_name, &tow_name) == TOWDB_QUERY_MISUSE);
    r = valid_request();
  }
  CHECK(towdb_query_run(NULL, &r, &res) == TOWDB_QUERY_MISUSE);
  CHECK(towdb_query_run(db, NULL, &res) == TOWDB_QUERY_MISUSE);
  CHECK(towdb_query_run(db, &r, NULL) == TOWDB_QUERY_MISUSE);

  /* capi-4 */
  r = valid_request();
  r.tug = "Titanic";
  expect_query_error(db, r, TOWDB_QUERY_INPUT, "tug 'Titanic' is not in the database");
  r = valid_request();
  r.tug = NULL;
  expect_query_error(db, r, TOWDB_QUERY_INPUT, "tug: a tug name is required");
  r = valid_request();
  r.speed_kt = NAN;
  expect_query_error(db, r, TOWDB_QUERY_INPUT, "speed_kt = nan");
  r = valid_request();
  r.heading_deg = 400.0;
  expect_query_error(db, r, TOWDB_QUERY_INPUT, "heading_deg = 400");
  r = valid_request();
  r.probability = 0.0;
  expect_query_error(db, r, TOWDB_QUERY_INPUT, "probability = 0");
  r = valid_request();
  r.probability = 1.0;
  expect_query_error(db, r, TOWDB_QUERY_INPUT, "probability = 1");
  r = valid_request();
  r.length_ft = -5.0;
  expect_query_error(db, r, TOWDB_QUERY_INPUT, "length_ft = -5");
  r = valid_request();
  r.speed_kt = 50.0;
  expect_query_error(db, r, TOWDB_QUERY_RANGE, "speed_kt = 50 is outside the stored range");

  /* capi-5 */
  r = valid_request();
  CHECK(towdb_query_run(db, &r, &res) == TOWDB_QUERY_OK);
  CHECK(towdb_query_errcode(db) == TOWDB_QUERY_OK && strcmp(towdb_query_errmsg(db), "") == 0);
  CHECK(towdb_query_warning(db, -1, &kind) == NULL);
  CHECK(towdb_query_warning(db, res.warning_count, &kind) == NULL);
  CHECK(towdb_query_warning(NULL, 0, NULL) == NULL);
  CHECK(towdb_query_nearest(db, -1, &near_case) == TOWDB_QUERY_MISUSE);
  CHECK(towdb_query_nearest(db, res.nearest_count, &near_case) == TOWDB_QUERY_MISUSE);
  CHECK(towdb_query_nearest(db, 0, NULL) == TOWDB_QUERY_MISUSE);
  r.speed_kt = 50.0;
  r.extrapolate = 1;
  CHECK(towdb_query_run(db, &r, &res) == TOWDB_QUERY_OK);
  CHECK(res.extrapolated == 1 && res.warning_count >= 1);
  CHECK(towdb_query_warning(db, 0, &kind) != NULL && kind == TOWDB_QUERY_WARN_EXTRAPOLATED);
  CHECK(towdb_query_warning(db, 0, NULL) != NULL);

  /* capi-6 */
  r = valid_request();
  CHECK(towdb_query_max_speed(db, &r, NULL, NULL) == TOWDB_QUERY_MISUSE);
  CHECK(towdb_query_max_speed(db, &r, &search, NULL) == TOWDB_QUERY_OK);
  CHECK(search.found == 1 && search.evaluations > 0 && search.value >= search.range_low &&
        search.value <= search.range_high);
  CHECK(towdb_query_min_length(db, &r, &search, &res) == TOWDB_QUERY_OK);
  CHECK(search.found == 1 ? res.extreme_check_passed == 1 : isnan(search.value));
  CHECK(towdb_query_leave_one_out(db, TOWDB_QUERY_SPACE_AUTO, TOWDB_QUERY_AXIS_ALL, &loo) == TOWDB_QUERY_INPUT);
  CHECK(towdb_query_leave_one_out(db, TOWDB_QUERY_SPACE_LINEAR, 17, &loo) == TOWDB_QUERY_INPUT);
  CHECK(contains(towdb_query_errmsg(db), "axis = 17"));
  CHECK(towdb_query_leave_one_out(db, TOWDB_QUERY_SPACE_LINEAR, TOWDB_QUERY_AXIS_ALL, &loo) == TOWDB_QUERY_OK);
  CHECK(loo.space == TOWDB_QUERY_SPACE_LINEAR && loo.samples >= 0);
  CHECK(towdb_query_leave_one_out(db, TOWDB_QUERY_SPACE_LINEAR, TOWDB_QUERY_AXIS_ALL, NULL) == TOWDB_QUERY_MISUSE);
  towdb_query_close(db);
  return failures;
}
