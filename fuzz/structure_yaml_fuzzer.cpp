// Fuzz harness: the YAML structure reader (io::read_structure_yaml_string) and, for small models that
// read, the checks of the solve (dof reduction: rigid-tie loops, two masters, support frames) and the
// solve itself. Every input must end as a model or one kInvalidInput message, never a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_checks.hpp"
#include "kinestat/io/structure_yaml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinestat::fuzz::check_structure(kinestat::io::read_structure_yaml_string(text, "fuzz.yaml"));
  return 0;
}
