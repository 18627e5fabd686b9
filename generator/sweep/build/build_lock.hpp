// The database file's side of a build: the exclusive build lock and the
// check that the file may be written.
#ifndef TOWDB_SWEEP_BUILD_LOCK_HPP
#define TOWDB_SWEEP_BUILD_LOCK_HPP

#include <filesystem>

namespace towdb::sweep {

// An exclusive advisory lock (flock) on the database file for the whole
// build: a second `towdb build` on the same file is refused at once. flock
// locks are independent of SQLite's POSIX record locks on Linux; the
// descriptor is closed only after the database connection (declared after
// this object, destroyed before it), so SQLite's locks are never dropped by
// our close().
class BuildLock {
 public:
  // Creates the file if missing. Throws InputError if it cannot be opened or
  // another process holds the lock.
  explicit BuildLock(const std::filesystem::path& path);
  ~BuildLock();
  BuildLock(const BuildLock&) = delete;
  BuildLock& operator=(const BuildLock&) = delete;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// Throws InputError unless a build may write the database file at `path`:
// its directory exists, it is not a directory, and (if it exists) it has a
// write permission bit.
void require_writable(const std::filesystem::path& path);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_BUILD_LOCK_HPP
