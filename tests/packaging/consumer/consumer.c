/* Compiled as C against the installed <towdb/query.h>: the library loads, its
 * version is the one installed, and a missing database gives the documented
 * code and message (towdb/query.h). Exit 0 on success. */
#include <stdio.h>
#include <string.h>

#include <towdb/query.h>

int main(int argc, char** argv) {
  towdb_query_db* db = NULL;
  int rc = towdb_query_open("/nonexistent/towdb-packaging.towdb", TOWDB_QUERY_SPACE_AUTO, &db);
  if (argc > 1 && strcmp(towdb_query_version(), argv[1]) != 0) {
    fprintf(stderr, "version %s, expected %s\n", towdb_query_version(), argv[1]);
    return 1;
  }
  if (rc != TOWDB_QUERY_DATABASE || strstr(towdb_query_errmsg(db), "does not exist") == NULL) {
    fprintf(stderr, "open: code %d, message '%s'\n", rc, towdb_query_errmsg(db));
    return 2;
  }
  towdb_query_close(db);
  towdb_query_close(NULL);
  printf("towdb %s: C consumer ok\n", towdb_query_version());
  return 0;
}
