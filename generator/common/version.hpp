// towdb version: the single source of the project version (read by CMake).
#ifndef TOWDB_COMMON_VERSION_HPP
#define TOWDB_COMMON_VERSION_HPP

#define TOWDB_VERSION_STRING "0.4.0"

namespace towdb {
inline constexpr const char* kVersion = TOWDB_VERSION_STRING;
}  // namespace towdb

#endif  // TOWDB_COMMON_VERSION_HPP
