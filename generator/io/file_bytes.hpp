// Reading a whole input file as bytes (ship, towline and sweep files, and the
// texts a build stores beside its cases).
#ifndef TOWDB_IO_FILE_BYTES_HPP
#define TOWDB_IO_FILE_BYTES_HPP

#include <filesystem>
#include <string>

namespace towdb::io {

// The file's bytes; InputError "<path>: cannot open the file (missing or
// unreadable)" when it cannot be opened.
std::string read_file_bytes(const std::filesystem::path& path);

}  // namespace towdb::io

#endif  // TOWDB_IO_FILE_BYTES_HPP
