// towdb's one error policy.
//
// Inside C++ code, failures are typed exceptions derived from towdb::Error:
//   InputError    bad input of any kind (ship file, sweep file, CLI, query,
//                 database contents). The message names the field, the value
//                 and what is allowed. The CLI maps it to exit code 2.
//   NumericalError a solver did not converge or produced a non-finite value;
//                 the message names the solver, the iteration and the residual.
//   StorageError  the database could not be opened, read or written.
// Programmer errors (violated preconditions inside the library) use
// TOWDB_ASSERT, which aborts with file and line. At the C API boundary
// (query/src/capi.cpp) every exception is caught once and turned into an int
// code plus a message owned by the handle.
#ifndef TOWDB_COMMON_ERROR_HPP
#define TOWDB_COMMON_ERROR_HPP

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace towdb {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InputError : public Error {
 public:
  using Error::Error;
};

class NumericalError : public Error {
 public:
  using Error::Error;
};

class StorageError : public Error {
 public:
  using Error::Error;
};

// Formats a value for an error message with full precision ("1.5", "nan").
std::string format_value(double value);

// Throws InputError("<field> = <value>: <allowed>") unless `ok`.
void require_input(bool ok, const std::string& field, double value, const std::string& allowed);

// Checks an options field: finite and inside [lo, hi]; throws InputError naming it.
void require_in_range(const std::string& field, double value, double lo, double hi);
// Checks finite and > 0.
void require_positive(const std::string& field, double value);

[[noreturn]] void assertion_failed(const char* expr, const char* file, int line);

}  // namespace towdb

#define TOWDB_ASSERT(expr) \
  ((expr) ? static_cast<void>(0) : ::towdb::assertion_failed(#expr, __FILE__, __LINE__))

#endif  // TOWDB_COMMON_ERROR_HPP
