// Fuzz harness: the identification-target reader (io::read_identification_targets_yaml_string).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_checks.hpp"
#include "kinestat/io/identification_yaml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto t = kinestat::io::read_identification_targets_yaml_string(text, "fuzz.yaml");
  if (kinestat::fuzz::refused(t)) return 0;
  for (const auto& target : t->targets)
    if (!std::isfinite(target.value) || !target.point.allFinite()) std::abort();  // checked values only
  return 0;
}
