// Fuzz harness: the Frame3DD reader (io::read_frame3dd_string, read as N-mm) and, for small models
// that read, the solve. Every input must end as a model or one kInvalidInput message, never a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_checks.hpp"
#include "kinestat/io/frame3dd.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const kinestat::io::FileUnits units{1e-3, 1.0, "mm", "N"};
  kinestat::fuzz::check_structure(kinestat::io::read_frame3dd_string(text, "fuzz.3dd", units));
  return 0;
}
