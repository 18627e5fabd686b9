// The stored FFTW plan of the one-day record (docs/physics.md 1.3; sea.hpp
// EQ-SEA-8, EQ-SEA-9).
//
// Every day of every case takes eight c2r transforms of N = 86,400 points
// (one day at 1 s, simulation::CaseOptions). FFTW_ESTIMATE's plan for that
// length takes 0.35 ms a transform on the 2-core CI machine kind; the plan
// FFTW_PATIENT finds takes 0.20 ms. But FFTW_PATIENT times candidate plans,
// so two processes could choose different plans, whose outputs differ in the
// last bits, and the database's results must not depend on the process that
// computed them. So the patient plan is made once, offline, and stored here
// as FFTW wisdom; DaySynthesizer asks FFTW for that plan only
// (FFTW_WISDOM_ONLY) and falls back to FFTW_ESTIMATE when FFTW refuses it:
// another FFTW version or build (the text's first line names FFTW 3.3.10 and
// a signature of the set of solvers it was built with), or a processor
// without the AVX codelets it names. Results are then bit-identical between
// all processes on machines that take the stored plan. Where FFTW refuses it,
// FFTW_ESTIMATE's plan is used, which itself depends on the processor's
// SIMD codelets (`towdb simulate --json` reports which plan: record.fft_plan;
// sweep/build/numerics.hpp guards databases against mixing machine kinds).
//
// Regenerate (after an FFTW upgrade, or for another record length; a few
// minutes): build, then
//   build/tools/towdb_make_fftw_wisdom 86400 > wisdom.txt
// and paste the text into fft_wisdom.cpp. Changing it changes the database's
// results in the last bits: bump the version (common/version.hpp) with it.
#ifndef TOWDB_SEA_FFT_WISDOM_HPP
#define TOWDB_SEA_FFT_WISDOM_HPP

namespace towdb::sea {

// FFTW wisdom text (fftw_import_wisdom_from_string).
extern const char* const kStoredRecordWisdom;

}  // namespace towdb::sea

#endif  // TOWDB_SEA_FFT_WISDOM_HPP
