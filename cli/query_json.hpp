// The answer of one question as `towdb query --json` prints it (cmd_query.cpp),
// for the other commands that show answers: `towdb plan --json`, `towdb serve`.
#ifndef TOWDB_CLI_QUERY_JSON_HPP
#define TOWDB_CLI_QUERY_JSON_HPP

#include <nlohmann/json.hpp>

#include "towdb/query.hpp"

namespace towdb::cli {

// Keys and units as documented for `towdb query --json` (README, "Commands").
nlohmann::ordered_json query_answer_json(const query::QueryRequest& request, const query::QueryResult& result,
                                         bool on_brake);

}  // namespace towdb::cli

#endif  // TOWDB_CLI_QUERY_JSON_HPP
