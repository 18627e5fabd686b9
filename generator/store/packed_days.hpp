// Every simulated day of a case in one row (schema/004_case_days.sql): the
// day arrays packed little-endian, 4 bytes a value, whatever the host's byte
// order, so that a database file reads the same on any machine.
//   max_dynamic_kips, slack_time_s: IEEE-754 binary32 (7 significant digits:
//     the Type-I fits are computed from the doubles before storing, so the
//     stored parameters do not depend on this rounding);
//   snatch_events: unsigned 32-bit.
// Schema 8: max_dynamic_kips may instead hold IEEE-754 binary16 values, 2 bytes
// a day (case_days.maxima_bytes = 2): each the binary16 nearest to the binary32
// value (round to nearest, ties to even; Eigen::half), 11 significant bits,
// a relative rounding of at most 2^-11 = 0.05 %, far below the sampling scatter
// of a daily maximum. A case with a maximum that binary16 cannot hold (above
// 65,504 kips, or not finite) keeps binary32.
#ifndef TOWDB_STORE_PACKED_DAYS_HPP
#define TOWDB_STORE_PACKED_DAYS_HPP

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "store/database.hpp"

namespace towdb::store {

std::string pack_float32(const std::vector<double>& values);
std::string pack_uint32(const std::vector<std::int64_t>& values);
// Refuse a blob whose length is not 4 x `count` (InputError naming `field`).
std::vector<double> unpack_float32(std::string_view blob, std::size_t count, const std::string& field);
std::vector<std::int64_t> unpack_uint32(std::string_view blob, std::size_t count, const std::string& field);
// binary16 (through binary32, as above); false when some value does not fit
// (|x| > 65,504 or not finite), `out` then unchanged.
bool pack_float16(const std::vector<double>& values, std::string* out);
std::vector<double> unpack_float16(std::string_view blob, std::size_t count, const std::string& field);

// One case's days, as the writer stores them and readers get them back.
// slack_snatch_stored = false (schema 7): the daily maxima only; the two
// per-day vectors are then empty (the case's slack fraction and snatch rate
// stay in results).
struct CaseDays {
  std::vector<double> max_dynamic_kips;
  std::vector<double> slack_time_s;        // all zero when never slack
  std::vector<std::int64_t> snatch_events;  // all zero when none
  bool slack_snatch_stored = true;
  // Bytes a daily maximum takes in the file: 4 (binary32) or 2 (binary16,
  // schema 8). Asking for 2 where a value does not fit stores 4.
  int maxima_bytes = 4;
};

// Replaces case `case_id`'s row of case_days (inside the caller's transaction).
void write_case_days(Database& db, std::int64_t case_id, const CaseDays& days);
// Reads it back (InputError naming the column when a blob does not match `days`).
CaseDays read_case_days(Database& db, std::int64_t case_id);
// Drops the per-day slack time and snatch count of every case that still
// holds them (slack_snatch_stored 1 -> 0); returns how many cases changed.
int drop_slack_snatch_days(Database& db);
// Repacks the daily maxima of every case stored as binary32 into binary16
// (maxima_bytes 4 -> 2; the cases whose values do not fit stay binary32);
// returns how many cases changed.
int pack_maxima_binary16(Database& db);

// Migration 4's second step: packs every row of daily_maxima into case_days
// and drops daily_maxima (inside the migration's transaction).
void pack_daily_maxima(Database& db);

}  // namespace towdb::store

#endif  // TOWDB_STORE_PACKED_DAYS_HPP
