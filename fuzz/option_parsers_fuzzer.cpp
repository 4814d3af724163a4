// Fuzz harness: the command-line value parsers shared by the commands and the model files: regions
// (--clamp, --reference), materials (--material), points (--reference-point), and the map's ranges
// (--region, through the command itself: a grid of at most 100 points at a 1 m step). The first byte
// chooses the parser, the rest is the option's text.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "kinestat/cli/app.hpp"
#include "kinestat/fea/link_stiffness_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  namespace fea = kinestat::fea;
  switch (data[0] % 5) {
    case 0: {
      const auto r = fea::parse_region(text, 1e-3, "--clamp");
      if (r.ok() && !(r->point.allFinite() && r->normal.allFinite() && r->lo.allFinite() && r->hi.allFinite()))
        std::abort();
      break;
    }
    case 1: {
      const auto m = fea::parse_material(text, "--material");
      if (m.ok() && !(m->E > 0 && m->G > 0)) std::abort();
      break;
    }
    case 2: {
      const auto p = fea::parse_point(text, 1e-3, "--reference-point");
      if (p.ok() && !p->allFinite()) std::abort();
      break;
    }
    case 3: {
      const auto r = fea::parse_region(text, 1.0, "--reference");
      if (!r.ok() && r.status().message().empty()) std::abort();
      break;
    }
    default: {
      std::ostringstream out, err;
      const int code = kinestat::cli::run(
          {"map", "fivebar", "--region", text, "--step", "1000", "--max-points", "100", "--quiet"}, out, err);
      // Solved, bad input or singular; never an internal failure, never a refusal without a message.
      if (code == kinestat::cli::kExitInternal || (code != 0 && err.str().empty())) std::abort();
    }
  }
  return 0;
}
