// The planner page of `towdb serve` (cli/web/planner.html), compiled in by
// cli/CMakeLists.txt so that the server needs no files but Chart.js.
#ifndef TOWDB_CLI_SERVE_PAGE_HPP
#define TOWDB_CLI_SERVE_PAGE_HPP

namespace towdb::cli {

extern const char* const kServePageHtml;

}  // namespace towdb::cli

#endif  // TOWDB_CLI_SERVE_PAGE_HPP
