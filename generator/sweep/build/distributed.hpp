// The one interface between towdb and MPI. Every MPI call of the project is
// in distributed.cpp, compiled with MPI only when towdb is configured with
// -DTOWDB_MPI=ON; without it the same interface reports one process (rank 0
// of 1) and the message functions are never called.
//
// The builder's protocol on top of it (sweep/build/build_mpi.hpp): rank 0 coordinates
// and is the only writer; ranks 1..N-1 ask for work (dynamic scheduling),
// compute one case at a time and send the outcome back.
#ifndef TOWDB_SWEEP_DISTRIBUTED_HPP
#define TOWDB_SWEEP_DISTRIBUTED_HPP

#include <cstdint>
#include <vector>

namespace towdb::sweep::distributed {

// True when this towdb was built with MPI.
bool compiled_with_mpi();

// RAII: initialises MPI on construction (once per process) and finalises it
// on destruction. Without MPI: rank 0, size 1.
class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
  bool finalize_ = false;
};

// Message tags of the build protocol.
enum class Tag : int {
  kReady = 1,   // worker -> 0: give me work (empty)
  kWork = 2,    // 0 -> worker: one case (work index + spec)
  kStop = 3,    // 0 -> worker: no more work
  kResult = 4,  // worker -> 0: outcome or failure of one case
};

struct Message {
  int source = 0;
  Tag tag = Tag::kReady;
  std::vector<std::uint8_t> bytes;
};

// Blocking point-to-point byte messages (MPI_BYTE). Throw StorageError when
// MPI reports an error or when called without MPI.
void send(int destination, Tag tag, const std::vector<std::uint8_t>& bytes);
// Receives the next message from any rank (source < 0) or from `source`.
Message receive(int source);

// Ends every rank at once after an unrecoverable error on one of them.
[[noreturn]] void abort_all(int exit_code);

}  // namespace towdb::sweep::distributed

#endif  // TOWDB_SWEEP_DISTRIBUTED_HPP
