// Fuzz harness: the YAML structure reader (io::read_structure_yaml_string) and, for small models that
// read, the checks of the solve (dof reduction: rigid-tie loops, two masters, support frames) and the
// solve itself. Every input must end as a model or one kInvalidInput message, never a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/msa/static_analysis.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto s = kinestat::io::read_structure_yaml_string(text, "fuzz.yaml");
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
