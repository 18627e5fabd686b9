// Case keys in the file (schema/009_key_bytes.sql): cases.case_key,
// cases.inputs_sha256 and cases.condition_key hold the 32 bytes of their
// SHA-256 as a BLOB, not its 64 hexadecimal digits as TEXT, so that each case
// row and the two unique indexes on them cost half as much (4.8 MB of the
// bundled 28,800-case file). The keys are computed and compared as hex text
// everywhere else (sweep/spec/keys.hpp); they are converted here, at the
// database's edge.
#ifndef TOWDB_STORE_KEY_BYTES_HPP
#define TOWDB_STORE_KEY_BYTES_HPP

#include <string>
#include <string_view>

#include "store/database.hpp"

namespace towdb::store {

// The 32 bytes of a SHA-256 given as 64 hexadecimal digits (either case);
// InputError naming `field` for anything else.
std::string key_bytes(std::string_view hex, const std::string& field);

// Migration 9's second step: every key column that holds 64 hexadecimal
// digits as TEXT becomes its 32 bytes (rows of another form, never written by
// a build, are left as they are); returns how many values changed.
int store_keys_as_bytes(Database& db);

}  // namespace towdb::store

#endif  // TOWDB_STORE_KEY_BYTES_HPP
