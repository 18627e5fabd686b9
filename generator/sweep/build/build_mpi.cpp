#include "sweep/build/build_mpi.hpp"

#include <cstdint>
#include <exception>
#include <string>

#include "sweep/build/distributed.hpp"
#include "sweep/build/numerics.hpp"
#include "sweep/build/serialize.hpp"

namespace towdb::sweep {

namespace {

Bytes encode_work(std::size_t work, const CaseSpec& spec, const CaseKeys& keys, const std::string& code_version) {
  ByteWriter w;
  w.i64(static_cast<std::int64_t>(work));
  w.str(keys.inputs_sha256);
  w.str(code_version);
  w.str(numerics_fingerprint());
  write_spec(w, spec);
  return w.take();
}

Bytes encode_result(const CaseEvent& e) {
  ByteWriter w;
  w.i64(static_cast<std::int64_t>(e.work));
  w.u8(e.ok ? 1 : 0);
  w.f64(e.runtime_s);
  if (e.ok) {
    write_outcome(w, e.outcome);
  } else {
    w.str(e.error);
  }
  return w.take();
}

CaseEvent decode_result(const Bytes& bytes) {
  ByteReader r(bytes);
  CaseEvent e;
  e.work = static_cast<std::size_t>(r.i64());
  e.ok = r.u8() != 0;
  e.runtime_s = r.f64();
  if (e.ok) {
    e.outcome = read_outcome(r);
  } else {
    e.error = r.str();
  }
  return e;
}

}  // namespace

void run_coordinator(const std::vector<CaseSpec>& cases, const std::vector<CaseKeys>& keys,
                     const std::vector<std::size_t>& work, const BuildOptions& options, int ranks,
                     const std::function<void(const CaseEvent&)>& record, BuildSummary& summary) {
  std::size_t next = 0;
  int active = ranks - 1;
  std::exception_ptr writer_error;
  while (active > 0) {
    distributed::Message m = distributed::receive(-1);
    if (m.tag == distributed::Tag::kResult && !writer_error) {
      try {
        record(decode_result(m.bytes));
      } catch (...) {
        writer_error = std::current_exception();
      }
    }
    if (next < work.size() && !stop_requested(options) && !writer_error) {
      const std::size_t i = work[next];
      distributed::send(m.source, distributed::Tag::kWork, encode_work(next, cases[i], keys[i], options.code_version));
      CaseEvent started;
      started.kind = CaseEvent::Kind::kStarted;
      started.work = next;
      if (!writer_error) {
        try {
          record(started);
        } catch (...) {
          writer_error = std::current_exception();
        }
      }
      ++next;
    } else {
      distributed::send(m.source, distributed::Tag::kStop, {});
      --active;
    }
  }
  if (writer_error) std::rethrow_exception(writer_error);
  summary.interrupted = next < work.size();
}

void run_worker(const io::ShipCatalog& catalog, const CaseRunner& runner, int rank) {
  distributed::send(0, distributed::Tag::kReady, {});
  for (;;) {
    distributed::Message m = distributed::receive(0);
    if (m.tag == distributed::Tag::kStop) return;
    ByteReader r(m.bytes);
    const auto work = static_cast<std::size_t>(r.i64());
    const std::string inputs_sha256 = r.str();
    const std::string code_version = r.str();
    const std::string rank0_numerics = r.str();
    const CaseSpec spec = read_spec(r);
    CaseEvent e;
    // This rank must compute the bits rank 0 would (numerics.hpp), from the
    // ship files rank 0 hashed.
    std::string mismatch = numerics_mismatch(rank, numerics_fingerprint(), rank0_numerics);
    if (mismatch.empty()) {
      try {
        if (case_keys(spec, catalog, code_version).inputs_sha256 != inputs_sha256) {
          mismatch = "MPI rank " + std::to_string(rank) +
                     ": its ship or towline files differ from rank 0's (inputs_sha256 mismatch)";
        }
      } catch (const std::exception& x) {
        mismatch = "MPI rank " + std::to_string(rank) + ": " + x.what();
      }
    }
    if (mismatch.empty()) {
      e = run_one(work, spec, catalog, runner);
    } else {
      e.work = work;
      e.error = "input error: " + mismatch;
    }
    distributed::send(0, distributed::Tag::kResult, encode_result(e));
  }
}

void stop_mpi_workers(int ranks) {
  for (int r = 1; r < ranks; ++r) distributed::send(r, distributed::Tag::kStop, {});
}

}  // namespace towdb::sweep
