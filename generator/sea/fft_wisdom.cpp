// The stored FFTW plan of the one-day record: see fft_wisdom.hpp.
// Made by towdb_make_fftw_wisdom 86400 (FFTW 3.3.10, Debian 12, on the 2-core
// CI machine kind, Intel Xeon 2.6 GHz).
#include "sea/fft_wisdom.hpp"

namespace towdb::sea {

const char* const kStoredRecordWisdom = R"wisdom((fftw-3.3.10 fftw_wisdom #x458a31c8 #x92381c4c #x4f974889 #xcd46f97e
  (fftw_codelet_r2cbIII_2 2 #x10048 #x10048 #x0 #x069d1538 #xb5a26809 #x7daf2e4b #x17ed3d36)
  (fftw_codelet_t1bv_15_avx 0 #x10048 #x10048 #x0 #xbbe24e64 #x3ec43dd9 #xd9e33735 #xf3458a35)
  (fftw_codelet_n2bv_12_avx 0 #x10048 #x10048 #x0 #xdbae691e #x81a64552 #xe3f81120 #xd81b9234)
  (fftw_codelet_r2cb_2 2 #x10048 #x10048 #x0 #x84e67cf7 #x1046ee34 #x9d9101b5 #xdb189e4a)
  (fftw_codelet_hc2cbdftv_2_avx 0 #x10048 #x10048 #x0 #x8d7b1a83 #xf80c90cc #x8ba33978 #xd8c0ac45)
  (fftw_dft_vrank_geq1_register 0 #x10048 #x10048 #x0 #xd090a104 #x2a914b88 #x88a51bbc #x38791a37)
  (fftw_codelet_t3bv_20_avx 0 #x10048 #x10048 #x0 #xe52f0d12 #x8e11f84b #x2cb8e4da #xd9f63e32)
  (fftw_dft_vrank_geq1_register 0 #x10048 #x10048 #x0 #xd7f5e0a2 #xc1afe07e #xc240fd2d #x04fa66b3)
  (fftw_codelet_t1bv_12_avx 0 #x10048 #x10048 #x0 #xf54e0827 #xa9c6dd12 #xa5a06b8a #x2d9357ab)
)
)wisdom";

}  // namespace towdb::sea
