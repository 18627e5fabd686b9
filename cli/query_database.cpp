#include "query_database.hpp"

#include <string>

#include "common/error.hpp"

namespace towdb::cli {

std::unique_ptr<query::Database> open_query_database(const std::string& flag, const std::string& path, int space) {
  try {
    return std::make_unique<query::Database>(path, space);
  } catch (const query::QueryError& e) {
    if (!e.is_input()) throw;
    const std::string what = e.what();  // the library's messages about the file start with its path
    throw InputError(flag + " = " + (what.rfind(path, 0) == 0 ? what : path + ": " + what));
  }
}

}  // namespace towdb::cli
