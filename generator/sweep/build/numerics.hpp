// The numerics fingerprint of a process: what, besides a case's inputs and the
// code, decides the last bits of its results (the determinism of EQ-SWEEP-7
// holds between processes with the same fingerprint).
//
// Two things vary by machine without the code changing:
//   - the FFT plan of the day's record: the stored wisdom's where FFTW takes
//     it, else FFTW_ESTIMATE's (sea/fft_wisdom.hpp), and FFTW_ESTIMATE itself
//     picks codelets by processor;
//   - the C math library: glibc chooses variants of sin, cos, exp, log, pow
//     ... by processor at load time (for example with fused multiply-add).
// The fingerprint is the first 16 hex digits of SHA-256 over the output bits
// of both at fixed arguments: a one-day record of 86,400 samples (the
// simulation's), and sin, cos, exp, log, pow, atan2, tanh,
// hypot and cbrt at 64 points each. Equal fingerprints do not prove equal
// results for every input, but a differing one proves that results differ.
//
// Used by the build so that a database never mixes two machine kinds' last
// bits: an MPI rank whose fingerprint differs from rank 0's refuses its cases,
// and a database records its first build's fingerprint (meta) and refuses a
// later build that would compute cases with another one (build.cpp). Printed
// by `towdb --version`. Computed once per process (a few ms).
#ifndef TOWDB_SWEEP_NUMERICS_HPP
#define TOWDB_SWEEP_NUMERICS_HPP

#include <string>

namespace towdb::sweep {

std::string numerics_fingerprint();

// The refusal of an MPI rank whose fingerprint differs from rank 0's; empty
// when they are equal.
std::string numerics_mismatch(int rank, const std::string& rank_fingerprint, const std::string& rank0_fingerprint);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_NUMERICS_HPP
