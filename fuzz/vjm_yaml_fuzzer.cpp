// Fuzz harness: the VJM model reader (io::read_vjm_model_yaml_string) and, for a model that reads, its
// chains' unloaded stiffness (small chains only). The display name's folder does not exist, so `fea:`
// springs with relative mesh paths are refused rather than meshed.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_checks.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/vjm/stiffness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto model = kinestat::io::read_vjm_model_yaml_string(text, "/nonexistent-fuzz-folder/model.yaml");
  if (kinestat::fuzz::refused(model)) return 0;
  const auto chains = kinestat::io::vjm_model_chains(*model, std::nullopt);
  if (!chains.ok()) return 0;
  kinestat::vjm::StiffnessOptions options;
  options.max_chain_coordinates = 200;  // keeps each input fast; larger chains are refused by the same check
  const auto K = kinestat::vjm::platform_unloaded_stiffness(*chains, options);
  if (K.ok() && !K->stiffness.allFinite()) std::abort();  // never numbers that are not numbers
  return 0;
}
