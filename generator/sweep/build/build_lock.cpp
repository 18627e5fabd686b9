#include "sweep/build/build_lock.hpp"

#include <cstdio>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/error.hpp"

namespace towdb::sweep {

BuildLock::BuildLock(const std::filesystem::path& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path.string() + ": cannot open the database file for writing");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw InputError(path.string() + ": another towdb build is writing to this database (it holds the build lock)");
  }
}

BuildLock::~BuildLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the flock
}

// A database file without any write permission bit is treated as read-only
// even for root (who could write it anyway): its owner marked it so.
void require_writable(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(dir)) {
      throw InputError(path.string() + ": the directory " + dir.string() + " does not exist");
    }
    return;  // a new database
  }
  if (S_ISDIR(st.st_mode)) throw InputError(path.string() + ": is a directory, not a database file");
  if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
    throw InputError(path.string() + ": the database file is read-only (mode " + mode +
                     "); make it writable (chmod u+w) to build into it");
  }
}

}  // namespace towdb::sweep
