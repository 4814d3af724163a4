#include "kinestat/core/status.hpp"

#include <cstdio>
#include <cstdlib>

namespace kinestat {

const char* status_code_name(StatusCode code) {
  switch (code) {
    case StatusCode::kOk:
      return "kOk";
    case StatusCode::kInvalidInput:
      return "kInvalidInput";
    case StatusCode::kSingular:
      return "kSingular";
    case StatusCode::kNotConverged:
      return "kNotConverged";
    case StatusCode::kInternal:
      return "kInternal";
  }
  return "unknown status code";
}

namespace detail {

void status_or_value_of_error(const Status& status) {
  // A programming error (the caller did not test ok()), so it ends the process: the value asked for
  // was never computed, and handing out a default-made one would turn the error into wrong numbers.
  std::fprintf(stderr,
               "kinestat: StatusOr::value() called on an error (%s: %s); test ok() before reading the "
               "value\n",
               status_code_name(status.code()), status.message().c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace detail
}  // namespace kinestat
