#include "store/packed_days.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include <Eigen/Core>

#include "common/error.hpp"

namespace towdb::store {

namespace {

void put_u32(std::string& out, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xFFu));
}

std::uint32_t get_u32(std::string_view blob, std::size_t i) {
  std::uint32_t v = 0;
  for (int b = 0; b < 4; ++b) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(blob[4 * i + b])) << (8 * b);
  return v;
}

void check_length(std::string_view blob, std::size_t count, const std::string& field, std::size_t bytes = 4) {
  if (blob.size() != bytes * count) {
    throw InputError(field + ": " + std::to_string(blob.size()) + " bytes, expected " + std::to_string(bytes) +
                     " x " + std::to_string(count) + " days (the database is damaged)");
  }
}

// The largest finite binary16 value.
constexpr double kFloat16Max = 65504.0;

template <typename T>
bool all_zero(const std::vector<T>& v) {
  return std::all_of(v.begin(), v.end(), [](T x) { return x == T{0}; });
}

}  // namespace

std::string pack_float32(const std::vector<double>& values) {
  std::string out;
  out.reserve(4 * values.size());
  for (double x : values) put_u32(out, std::bit_cast<std::uint32_t>(static_cast<float>(x)));
  return out;
}

std::string pack_uint32(const std::vector<std::int64_t>& values) {
  std::string out;
  out.reserve(4 * values.size());
  for (std::int64_t x : values) {
    if (x < 0 || x > std::numeric_limits<std::uint32_t>::max()) {
      throw InputError("snatch_events = " + std::to_string(x) + ": must be in [0, 4294967295]");
    }
    put_u32(out, static_cast<std::uint32_t>(x));
  }
  return out;
}

std::vector<double> unpack_float32(std::string_view blob, std::size_t count, const std::string& field) {
  check_length(blob, count, field);
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = std::bit_cast<float>(get_u32(blob, i));
  return out;
}

std::vector<std::int64_t> unpack_uint32(std::string_view blob, std::size_t count, const std::string& field) {
  check_length(blob, count, field);
  std::vector<std::int64_t> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = get_u32(blob, i);
  return out;
}

bool pack_float16(const std::vector<double>& values, std::string* out) {
  std::string packed;
  packed.reserve(2 * values.size());
  for (double x : values) {
    const auto f = static_cast<float>(x);
    if (!std::isfinite(f) || std::fabs(f) > kFloat16Max) return false;
    const auto bits = Eigen::numext::bit_cast<std::uint16_t>(Eigen::half(f));
    packed.push_back(static_cast<char>(bits & 0xFFu));
    packed.push_back(static_cast<char>(bits >> 8));
  }
  *out = std::move(packed);
  return true;
}

std::vector<double> unpack_float16(std::string_view blob, std::size_t count, const std::string& field) {
  check_length(blob, count, field, 2);
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto bits = static_cast<std::uint16_t>(static_cast<unsigned char>(blob[2 * i]) |
                                                 (static_cast<unsigned char>(blob[2 * i + 1]) << 8));
    out[i] = static_cast<float>(Eigen::numext::bit_cast<Eigen::half>(bits));
  }
  return out;
}

namespace {

// The row in the current layout, or (`with_stored_flag` false) in the layout of
// schema versions 4 to 6, which have no slack_snatch_stored column (migration 4).
void insert_case_days(Database& db, std::int64_t case_id, const CaseDays& days, bool with_stored_flag) {
  const std::size_t n = days.max_dynamic_kips.size();
  const std::size_t per_day = days.slack_snatch_stored ? n : 0;
  if (n == 0 || days.slack_time_s.size() != per_day || days.snatch_events.size() != per_day) {
    throw InputError("case " + std::to_string(case_id) + ": day arrays of " + std::to_string(n) + ", " +
                     std::to_string(days.slack_time_s.size()) + " and " + std::to_string(days.snatch_events.size()) +
                     " values: must be the same, at least 1" +
                     (days.slack_snatch_stored ? "" : " (slack and snatch: none, as they are not stored)"));
  }
  if (!with_stored_flag && !days.slack_snatch_stored) {
    throw InputError("case " + std::to_string(case_id) +
                     ": schema versions 4 to 6 store every day's slack and snatch (version 7 may leave them out)");
  }
  if (days.maxima_bytes != 4 && days.maxima_bytes != 2) {
    throw InputError("case " + std::to_string(case_id) + ": maxima_bytes = " + std::to_string(days.maxima_bytes) +
                     ": must be 4 (binary32) or 2 (binary16)");
  }
  if (!with_stored_flag && days.maxima_bytes != 4) {
    throw InputError("case " + std::to_string(case_id) + ": schema versions 4 to 6 store binary32 maxima only");
  }
  std::string maxima;
  const bool half = days.maxima_bytes == 2 && pack_float16(days.max_dynamic_kips, &maxima);
  if (!half) maxima = pack_float32(days.max_dynamic_kips);
  Statement st = db.prepare(
      with_stored_flag
          ? "INSERT OR REPLACE INTO case_days (case_id, days, max_dynamic_kips, slack_time_s, snatch_events, "
            "slack_snatch_stored, maxima_bytes) VALUES (?, ?, ?, ?, ?, ?, ?)"
          : "INSERT OR REPLACE INTO case_days (case_id, days, max_dynamic_kips, slack_time_s, snatch_events) "
            "VALUES (?, ?, ?, ?, ?)");
  st.bind(1, case_id).bind(2, static_cast<std::int64_t>(n)).bind_blob(3, maxima);
  if (with_stored_flag) {
    st.bind(6, static_cast<std::int64_t>(days.slack_snatch_stored ? 1 : 0));
    st.bind(7, static_cast<std::int64_t>(half ? 2 : 4));
  }
  if (all_zero(days.slack_time_s)) {
    st.bind_null(4);
  } else {
    st.bind_blob(4, pack_float32(days.slack_time_s));
  }
  if (all_zero(days.snatch_events)) {
    st.bind_null(5);
  } else {
    st.bind_blob(5, pack_uint32(days.snatch_events));
  }
  st.run();
}

}  // namespace

void write_case_days(Database& db, std::int64_t case_id, const CaseDays& days) {
  insert_case_days(db, case_id, days, true);  // writers open the file migrated to the latest version
}

CaseDays read_case_days(Database& db, std::int64_t case_id) {
  Statement st = db.prepare(
      "SELECT days, max_dynamic_kips, slack_time_s, snatch_events, slack_snatch_stored, maxima_bytes FROM case_days "
      "WHERE case_id = ?");
  st.bind(1, case_id);
  if (!st.step()) throw InputError("case " + std::to_string(case_id) + ": no row in case_days");
  const std::int64_t days = st.column_int(0);
  if (days < 1) throw InputError("case_days.days = " + std::to_string(days) + ": must be >= 1");
  const auto n = static_cast<std::size_t>(days);
  CaseDays out;
  out.maxima_bytes = static_cast<int>(st.column_int(5));
  out.max_dynamic_kips = out.maxima_bytes == 2 ? unpack_float16(st.column_blob(1), n, "case_days.max_dynamic_kips")
                                               : unpack_float32(st.column_blob(1), n, "case_days.max_dynamic_kips");
  out.slack_snatch_stored = st.column_int(4) != 0;
  if (!out.slack_snatch_stored) return out;
  out.slack_time_s = st.is_null(2) ? std::vector<double>(n, 0.0)
                                   : unpack_float32(st.column_blob(2), n, "case_days.slack_time_s");
  out.snatch_events = st.is_null(3) ? std::vector<std::int64_t>(n, 0)
                                    : unpack_uint32(st.column_blob(3), n, "case_days.snatch_events");
  return out;
}

int drop_slack_snatch_days(Database& db) {
  Statement count = db.prepare("SELECT count(*) FROM case_days WHERE slack_snatch_stored = 1");
  count.step();
  const auto n = static_cast<int>(count.column_int(0));
  if (n > 0) {
    db.prepare(
          "UPDATE case_days SET slack_time_s = NULL, snatch_events = NULL, slack_snatch_stored = 0 "
          "WHERE slack_snatch_stored = 1")
        .run();
  }
  return n;
}

int pack_maxima_binary16(Database& db) {
  // The ids first: a table is not updated while a statement scans it.
  std::vector<std::int64_t> ids;
  Statement list = db.prepare("SELECT case_id FROM case_days WHERE maxima_bytes = 4 ORDER BY case_id");
  while (list.step()) ids.push_back(list.column_int(0));
  Statement read = db.prepare("SELECT days, max_dynamic_kips FROM case_days WHERE case_id = ?");
  Statement update = db.prepare("UPDATE case_days SET max_dynamic_kips = ?, maxima_bytes = 2 WHERE case_id = ?");
  int changed = 0;
  for (const std::int64_t case_id : ids) {
    read.reset();
    read.bind(1, case_id);
    read.step();
    const auto n = static_cast<std::size_t>(read.column_int(0));
    const std::vector<double> maxima = unpack_float32(read.column_blob(1), n, "case_days.max_dynamic_kips");
    std::string half;
    if (!pack_float16(maxima, &half)) continue;  // a value binary16 cannot hold: the case keeps binary32
    update.reset();
    update.bind_blob(1, half).bind(2, case_id);
    update.run();
    ++changed;
  }
  return changed;
}

void pack_daily_maxima(Database& db) {
  Statement rows = db.prepare(
      "SELECT case_id, day, max_dynamic_kips, slack_time_s, snatch_events FROM daily_maxima ORDER BY case_id, day");
  std::int64_t current = -1;
  CaseDays days;
  const auto flush = [&] {
    if (current >= 0) insert_case_days(db, current, days, false);  // migration 4's own row layout
    days = CaseDays{};
  };
  while (rows.step()) {
    const std::int64_t case_id = rows.column_int(0);
    if (case_id != current) {
      flush();
      current = case_id;
    }
    const std::int64_t day = rows.column_int(1);
    if (day != static_cast<std::int64_t>(days.max_dynamic_kips.size())) {
      throw InputError("daily_maxima: case " + std::to_string(case_id) + " has day " + std::to_string(day) +
                       " where day " + std::to_string(days.max_dynamic_kips.size()) +
                       " was expected (days must run 0, 1, 2, ...)");
    }
    days.max_dynamic_kips.push_back(rows.column_double(2));
    days.slack_time_s.push_back(rows.column_double(3));
    days.snatch_events.push_back(rows.column_int(4));
  }
  flush();
  db.exec("DROP TABLE daily_maxima");
}

}  // namespace towdb::store
