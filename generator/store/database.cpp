#include "store/database.hpp"

#include <sqlite3.h>

#include <utility>

#include "common/error.hpp"
#include "store/key_bytes.hpp"
#include "store/packed_days.hpp"

namespace towdb::store {

namespace {

struct Migration {
  const char* name;
  const char* sql;
};

const Migration kMigrations[] = {
#include "schema_migrations.inc"
};

// A migration's second step where SQL alone cannot convert the data, run in
// the same transaction after its SQL (by file name).
void after_migration(Database& db, const std::string& name) {
  if (name == "004_case_days.sql") pack_daily_maxima(db);
  if (name == "009_key_bytes.sql") store_keys_as_bytes(db);
}

// Application id stamped in the file header so a towdb database can be told
// apart from any other SQLite file ("TWDB" in ASCII).
constexpr int kApplicationId = 0x54574442;

// How long a writer waits for another connection's lock before giving up.
constexpr int kBusyTimeout_ms = 5000;

[[noreturn]] void raise(sqlite3* db, const std::filesystem::path& path, const std::string& what, int rc) {
  const std::string msg = path.string() + ": " + what + ": " + (db ? sqlite3_errmsg(db) : sqlite3_errstr(rc));
  const int primary = rc & 0xFF;
  if (primary == SQLITE_CORRUPT || primary == SQLITE_NOTADB || primary == SQLITE_BUSY ||
      primary == SQLITE_LOCKED || primary == SQLITE_READONLY || primary == SQLITE_CANTOPEN) {
    std::string hint;
    if (primary == SQLITE_CORRUPT || primary == SQLITE_NOTADB) hint = " (the file is not a valid towdb database)";
    if (primary == SQLITE_BUSY || primary == SQLITE_LOCKED) hint = " (another process holds a lock on it)";
    if (primary == SQLITE_READONLY) hint = " (the file or its directory is read-only)";
    throw InputError(msg + hint);
  }
  throw StorageError(msg);
}

}  // namespace

int latest_schema_version() { return static_cast<int>(std::size(kMigrations)); }

Database Database::open(const std::filesystem::path& path, Mode mode) {
  if (mode != Mode::kCreate && !std::filesystem::exists(path)) {
    throw InputError(path.string() + ": database does not exist");
  }
  if (std::filesystem::is_directory(path)) {
    throw InputError(path.string() + ": is a directory, expected a towdb database file");
  }
  int flags = SQLITE_OPEN_FULLMUTEX;
  if (mode == Mode::kReadOnly) flags |= SQLITE_OPEN_READONLY;
  if (mode == Mode::kReadWrite) flags |= SQLITE_OPEN_READWRITE;
  if (mode == Mode::kCreate) flags |= SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  sqlite3* raw = nullptr;
  const int rc = sqlite3_open_v2(path.c_str(), &raw, flags, nullptr);
  if (rc != SQLITE_OK) {
    std::string msg = raw ? sqlite3_errmsg(raw) : sqlite3_errstr(rc);
    sqlite3_close(raw);
    throw InputError(path.string() + ": cannot open database: " + msg);
  }
  Database db(raw, path);
  sqlite3_busy_timeout(raw, kBusyTimeout_ms);
  sqlite3_extended_result_codes(raw, 1);
  db.exec("PRAGMA foreign_keys = ON");

  // Is it a towdb database? An empty file (page count 0) is a new one.
  std::int64_t app_id = 0, page_count = 0;
  {
    Statement check = db.prepare("PRAGMA application_id");
    check.step();
    app_id = check.column_int(0);
    Statement pages = db.prepare("PRAGMA page_count");
    pages.step();
    page_count = pages.column_int(0);
  }  // statements finalised: no implicit read transaction stays open
  if (page_count > 0 && app_id != kApplicationId) {
    throw InputError(path.string() + ": not a towdb database (SQLite application_id " + std::to_string(app_id) +
                     ", expected " + std::to_string(kApplicationId) + ")");
  }
  const int version = db.schema_version();
  if (version > latest_schema_version()) {
    throw InputError(path.string() + ": database schema version " + std::to_string(version) +
                     " is newer than this towdb understands (" + std::to_string(latest_schema_version()) +
                     "); use a newer towdb");
  }
  if (mode == Mode::kReadOnly) {
    if (page_count == 0) {
      throw InputError(path.string() + ": the file is empty, not a towdb database (build one with towdb build)");
    }
    if (version < latest_schema_version()) {
      throw InputError(path.string() + ": database schema version " + std::to_string(version) +
                       " is older than " + std::to_string(latest_schema_version()) +
                       "; open it once for writing (towdb build --resume) to migrate it");
    }
    db.exec("PRAGMA query_only = ON");
  } else {
    db.exec("PRAGMA journal_mode = WAL");
    db.exec("PRAGMA synchronous = NORMAL");
    db.migrate();
  }
  return db;
}

void Database::migrate() {
  int version = schema_version();
  while (version < latest_schema_version()) {
    const Migration& m = kMigrations[version];
    transaction([&] {
      exec(m.sql);
      after_migration(*this, m.name);
      exec("PRAGMA application_id = " + std::to_string(kApplicationId));
      exec("PRAGMA user_version = " + std::to_string(version + 1));
    });
    ++version;
  }
}

Database::Database(Database&& other) noexcept
    : db_(std::exchange(other.db_, nullptr)), path_(std::move(other.path_)) {}

Database& Database::operator=(Database&& other) noexcept {
  if (this != &other) {
    sqlite3_close_v2(db_);
    db_ = std::exchange(other.db_, nullptr);
    path_ = std::move(other.path_);
  }
  return *this;
}

Database::~Database() { sqlite3_close_v2(db_); }

int Database::schema_version() const {
  sqlite3_stmt* stmt = nullptr;
  int rc = sqlite3_prepare_v2(db_, "PRAGMA user_version", -1, &stmt, nullptr);
  if (rc != SQLITE_OK) raise(db_, path_, "reading the schema version", rc);
  rc = sqlite3_step(stmt);
  const int v = rc == SQLITE_ROW ? sqlite3_column_int(stmt, 0) : -1;
  sqlite3_finalize(stmt);
  if (v < 0) raise(db_, path_, "reading the schema version", rc);
  return v;
}

void Database::exec(std::string_view sql) {
  const std::string s(sql);
  char* err = nullptr;
  const int rc = sqlite3_exec(db_, s.c_str(), nullptr, nullptr, &err);
  if (rc != SQLITE_OK) {
    sqlite3_free(err);
    raise(db_, path_, "executing '" + s.substr(0, 60) + "'", rc);
  }
}

void Database::exec_noexcept(const char* sql) noexcept { sqlite3_exec(db_, sql, nullptr, nullptr, nullptr); }

Statement Database::prepare(std::string_view sql) {
  sqlite3_stmt* stmt = nullptr;
  const int rc = sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &stmt, nullptr);
  if (rc != SQLITE_OK) raise(db_, path_, "preparing '" + std::string(sql.substr(0, 60)) + "'", rc);
  return Statement(stmt, this);
}

std::int64_t Database::last_insert_rowid() const { return sqlite3_last_insert_rowid(db_); }

Statement::Statement(Statement&& other) noexcept
    : stmt_(std::exchange(other.stmt_, nullptr)), db_(other.db_) {}

Statement::~Statement() { sqlite3_finalize(stmt_); }

namespace {
void check_bind(int rc, Database* db, int index) {
  if (rc != SQLITE_OK) raise(db->handle(), db->path(), "binding parameter " + std::to_string(index), rc);
}
}  // namespace

Statement& Statement::bind(int index, double value) {
  check_bind(sqlite3_bind_double(stmt_, index, value), db_, index);
  return *this;
}
Statement& Statement::bind(int index, std::int64_t value) {
  check_bind(sqlite3_bind_int64(stmt_, index, value), db_, index);
  return *this;
}
Statement& Statement::bind(int index, std::string_view value) {
  check_bind(sqlite3_bind_text(stmt_, index, value.data(), static_cast<int>(value.size()), SQLITE_TRANSIENT), db_,
             index);
  return *this;
}
Statement& Statement::bind_null(int index) {
  check_bind(sqlite3_bind_null(stmt_, index), db_, index);
  return *this;
}
Statement& Statement::bind(int index, std::optional<double> value) {
  return value ? bind(index, *value) : bind_null(index);
}
Statement& Statement::bind_blob(int index, std::string_view bytes) {
  check_bind(sqlite3_bind_blob64(stmt_, index, bytes.data(), bytes.size(), SQLITE_TRANSIENT), db_, index);
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  raise(db_->handle(), db_->path(), "running a statement", rc);
}

void Statement::run() {
  while (step()) {
  }
  reset();
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

bool Statement::is_null(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }
const char* Statement::column_type_name(int column) const {
  switch (sqlite3_column_type(stmt_, column)) {
    case SQLITE_INTEGER: return "integer";
    case SQLITE_FLOAT: return "real";
    case SQLITE_TEXT: return "text";
    case SQLITE_BLOB: return "blob";
    default: return "null";
  }
}
double Statement::column_double(int column) const { return sqlite3_column_double(stmt_, column); }
std::int64_t Statement::column_int(int column) const { return sqlite3_column_int64(stmt_, column); }
std::string Statement::column_text(int column) const {
  const unsigned char* t = sqlite3_column_text(stmt_, column);
  return t ? std::string(reinterpret_cast<const char*>(t)) : std::string();
}
std::optional<double> Statement::column_optional_double(int column) const {
  if (is_null(column)) return std::nullopt;
  return column_double(column);
}
std::string Statement::column_blob(int column) const {
  const void* p = sqlite3_column_blob(stmt_, column);
  const int n = sqlite3_column_bytes(stmt_, column);
  return p ? std::string(static_cast<const char*>(p), static_cast<std::size_t>(n)) : std::string();
}

}  // namespace towdb::store
