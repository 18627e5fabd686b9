#include "store/key_bytes.hpp"

#include <cstdint>
#include <vector>

#include "common/error.hpp"

namespace towdb::store {

namespace {

constexpr std::size_t kSha256Bytes = 32;

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool is_sha256_hex(std::string_view s) {
  if (s.size() != 2 * kSha256Bytes) return false;
  for (char c : s) {
    if (hex_digit(c) < 0) return false;
  }
  return true;
}

}  // namespace

std::string key_bytes(std::string_view hex, const std::string& field) {
  if (!is_sha256_hex(hex)) {
    throw InputError(field + " = '" + std::string(hex.substr(0, 80)) +
                     "': must be a SHA-256 as 64 hexadecimal digits");
  }
  std::string out(kSha256Bytes, '\0');
  for (std::size_t i = 0; i < kSha256Bytes; ++i) {
    out[i] = static_cast<char>(hex_digit(hex[2 * i]) * 16 + hex_digit(hex[2 * i + 1]));
  }
  return out;
}

int store_keys_as_bytes(Database& db) {
  int changed = 0;
  for (const char* column : {"case_key", "inputs_sha256", "condition_key"}) {
    // The ids first: a table is not updated while a statement scans it.
    std::vector<std::pair<std::int64_t, std::string>> rows;
    Statement list = db.prepare(std::string("SELECT case_id, ") + column + " FROM cases WHERE typeof(" + column +
                                ") = 'text' AND length(" + column + ") = 64");
    while (list.step()) rows.emplace_back(list.column_int(0), list.column_text(1));
    Statement update = db.prepare(std::string("UPDATE cases SET ") + column + " = ? WHERE case_id = ?");
    for (const auto& [id, hex] : rows) {
      if (!is_sha256_hex(hex)) continue;
      update.bind_blob(1, key_bytes(hex, column)).bind(2, id);
      update.run();
      ++changed;
    }
  }
  return changed;
}

}  // namespace towdb::store
