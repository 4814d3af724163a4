// Fuzz harness: the Frame3DD reader (io::read_frame3dd_string, read as N-mm) and, for small models
// that read, the solve. Every input must end as a model or one kInvalidInput message, never a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "kinestat/io/frame3dd.hpp"
#include "kinestat/msa/static_analysis.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const kinestat::io::FileUnits units{1e-3, 1.0, "mm", "N"};
  const auto s = kinestat::io::read_frame3dd_string(text, "fuzz.3dd", units);
  if (!s.ok()) {
    if (s.status().message().empty()) std::abort();  // every refusal says why
    return 0;
  }
  if (s->nodes().size() <= 30) {
    const kinestat::msa::Solution sol = kinestat::msa::solve(*s);
    if (!sol.status.ok() && sol.status.message().empty()) std::abort();
  }
  return 0;
}
