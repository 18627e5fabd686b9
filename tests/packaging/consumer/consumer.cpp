// Compiled as C++17 against the installed <towdb/query.hpp> wrapper.
#include <cstdio>
#include <string>

#include <towdb/query.hpp>

int main() {
  try {
    towdb::query::Database db("/nonexistent/towdb-packaging.towdb");
  } catch (const towdb::query::QueryError& e) {
    if (e.code() == TOWDB_QUERY_DATABASE && e.is_input()) {
      std::printf("C++ consumer ok: %s\n", e.what());
      return 0;
    }
    std::fprintf(stderr, "code %d: %s\n", e.code(), e.what());
    return 2;
  }
  std::fprintf(stderr, "a missing database opened\n");
  return 1;
}
