// Opening a database through the query library for a CLI command: the one
// place where the library's errors on open become the CLI's. A library error
// that is the user's (missing file, not a towdb database, a stored value that
// fails validation: query.h TOWDB_QUERY_INPUT, TOWDB_QUERY_DATABASE) is an
// InputError naming the flag (exit 2); anything else stays an internal error.
#ifndef TOWDB_CLI_QUERY_DATABASE_HPP
#define TOWDB_CLI_QUERY_DATABASE_HPP

#include <memory>
#include <string>

#include "towdb/query.hpp"

namespace towdb::cli {

std::unique_ptr<query::Database> open_query_database(const std::string& flag, const std::string& path,
                                                     int space = TOWDB_QUERY_SPACE_AUTO);

}  // namespace towdb::cli

#endif  // TOWDB_CLI_QUERY_DATABASE_HPP
