// SQLite access for towdb: one RAII connection, prepared statements, and the
// versioned schema (schema/NNN_*.sql applied in order, PRAGMA user_version =
// number of applied migrations).
//
// Errors: a file that is not a towdb database, is corrupt, is newer than this
// program, or is locked raises InputError naming the file and the problem (the
// CLI exits 2); other SQLite failures raise StorageError. Doubles are bound as
// REAL (bit-exact round trip), never formatted as text.
#ifndef TOWDB_STORE_DATABASE_HPP
#define TOWDB_STORE_DATABASE_HPP

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace towdb::store {

// Number of migrations this build knows (the schema version it writes).
int latest_schema_version();

class Statement;

class Database {
 public:
  enum class Mode {
    kReadOnly,   // open an existing towdb database for reading
    kReadWrite,  // open an existing database, migrate it to the latest schema
    kCreate,     // open or create, migrate to the latest schema
  };

  static Database open(const std::filesystem::path& path, Mode mode);
  Database(Database&& other) noexcept;
  Database& operator=(Database&& other) noexcept;
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  ~Database();

  int schema_version() const;
  const std::filesystem::path& path() const { return path_; }

  void exec(std::string_view sql);
  Statement prepare(std::string_view sql);
  std::int64_t last_insert_rowid() const;

  // BEGIN IMMEDIATE ... COMMIT, rolled back if `fn` throws.
  template <typename Fn>
  void transaction(Fn&& fn) {
    exec("BEGIN IMMEDIATE");
    try {
      fn();
    } catch (...) {
      exec_noexcept("ROLLBACK");
      throw;
    }
    exec("COMMIT");
  }

  sqlite3* handle() { return db_; }

 private:
  Database(sqlite3* db, std::filesystem::path path) : db_(db), path_(std::move(path)) {}
  void migrate();
  void exec_noexcept(const char* sql) noexcept;
  sqlite3* db_ = nullptr;
  std::filesystem::path path_;
};

class Statement {
 public:
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&&) = delete;
  Statement(const Statement&) = delete;
  ~Statement();

  // Binders take 1-based parameter indices, as SQLite does.
  Statement& bind(int index, double value);
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, std::string_view value);
  Statement& bind(int index, const char* value) { return bind(index, std::string_view(value)); }
  Statement& bind(int index, const std::string& value) { return bind(index, std::string_view(value)); }
  Statement& bind_null(int index);
  Statement& bind(int index, std::optional<double> value);
  Statement& bind_blob(int index, std::string_view bytes);

  // Steps once: true while a row is available.
  bool step();
  // Runs a statement that returns no rows.
  void run();
  void reset();

  bool is_null(int column) const;
  // SQL typeof() of a column of the current row: "integer", "real", "text",
  // "blob" or "null" (a REAL column may hold text when CHECKs were bypassed).
  const char* column_type_name(int column) const;
  double column_double(int column) const;
  std::int64_t column_int(int column) const;
  std::string column_text(int column) const;
  std::optional<double> column_optional_double(int column) const;
  std::string column_blob(int column) const;  // the bytes of a BLOB (empty for NULL)

 private:
  friend class Database;
  Statement(sqlite3_stmt* stmt, Database* db) : stmt_(stmt), db_(db) {}
  sqlite3_stmt* stmt_ = nullptr;
  Database* db_ = nullptr;
};

}  // namespace towdb::store

#endif  // TOWDB_STORE_DATABASE_HPP
