#include "io/file_bytes.hpp"

#include <fstream>
#include <sstream>

#include "common/error.hpp"

namespace towdb::io {

std::string read_file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open the file (missing or unreadable)");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

}  // namespace towdb::io
