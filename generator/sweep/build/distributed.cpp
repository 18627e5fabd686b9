#include "sweep/build/distributed.hpp"

#include <cstdlib>
#include <string>

#include "common/error.hpp"

#ifdef TOWDB_WITH_MPI
#include <mpi.h>
#endif

namespace towdb::sweep::distributed {

#ifdef TOWDB_WITH_MPI

namespace {
void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) {
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(rc, text, &length);
    throw StorageError(std::string("MPI: ") + what + " failed: " + std::string(text, static_cast<std::size_t>(length)));
  }
}
}  // namespace

bool compiled_with_mpi() { return true; }

Session::Session() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    finalize_ = true;
  }
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
}

Session::~Session() {
  if (finalize_) {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  }
}

void send(int destination, Tag tag, const std::vector<std::uint8_t>& bytes) {
  check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, destination, static_cast<int>(tag),
                 MPI_COMM_WORLD),
        "MPI_Send");
}

Message receive(int source) {
  MPI_Status status;
  check(MPI_Probe(source < 0 ? MPI_ANY_SOURCE : source, MPI_ANY_TAG, MPI_COMM_WORLD, &status), "MPI_Probe");
  int count = 0;
  check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
  Message m;
  m.source = status.MPI_SOURCE;
  m.tag = static_cast<Tag>(status.MPI_TAG);
  m.bytes.resize(static_cast<std::size_t>(count));
  check(MPI_Recv(m.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE),
        "MPI_Recv");
  return m;
}

void abort_all(int exit_code) {
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::exit(exit_code);
}

#else  // without MPI: one process

bool compiled_with_mpi() { return false; }

Session::Session() = default;
Session::~Session() = default;

void send(int, Tag, const std::vector<std::uint8_t>&) {
  throw StorageError("MPI: towdb was built without MPI (configure with -DTOWDB_MPI=ON)");
}

Message receive(int) { throw StorageError("MPI: towdb was built without MPI (configure with -DTOWDB_MPI=ON)"); }

void abort_all(int exit_code) { std::exit(exit_code); }

#endif

}  // namespace towdb::sweep::distributed
