// towdb_make_fftw_wisdom: prints the FFTW wisdom of the record plan for
// generator/sea/fft_wisdom.cpp (see generator/sea/fft_wisdom.hpp).
//   towdb_make_fftw_wisdom [SAMPLES]     (default 86400: one day at 1 s)
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "common/error.hpp"
#include "sea/record.hpp"

int main(int argc, char** argv) {
  std::int64_t samples = 86400;
  if (argc > 2) {
    std::cerr << "usage: towdb_make_fftw_wisdom [SAMPLES]\n";
    return 2;
  }
  if (argc == 2) {
    const std::string text = argv[1];
    std::size_t used = 0;
    try {
      samples = std::stoll(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || used == 0) {
      std::cerr << "towdb_make_fftw_wisdom: SAMPLES '" << text << "' is not an integer\n";
      return 2;
    }
  }
  try {
    std::cout << towdb::sea::plan_record_wisdom(samples);
  } catch (const towdb::InputError& e) {
    std::cerr << "towdb_make_fftw_wisdom: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "towdb_make_fftw_wisdom: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
