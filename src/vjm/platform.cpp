#include "kinestat/vjm/platform.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace kinestat::vjm {

Status validate_platform(const std::vector<Chain>& chains, int max_chain_coordinates) {
  if (chains.empty()) return Status::Invalid("the platform has no chains; add at least one");
  for (const Chain& c : chains)
    if (Status s = c.validate(max_chain_coordinates); !s.ok()) return s;
  const Vec3 p0 = chains[0].nominal_pose().translation();
  for (const Chain& c : chains) {
    const double gap = (c.nominal_pose().translation() - p0).norm();
    if (gap > 1e-9 * std::max(c.length_scale(), chains[0].length_scale()))
      return Status::Invalid(
          fmt::format("chain '{}': its nominal tool point is {:.6g} m from chain '{}''s; the "
                      "platform is not assembled (check the nominal passive coordinates)",
                      c.name(), gap, chains[0].name()));
  }
  return Status::Ok();
}

double platform_length_scale(const std::vector<Chain>& chains) {
  double L = 0.0;
  for (const Chain& c : chains) L = std::max(L, c.length_scale());
  return L;
}

}  // namespace kinestat::vjm
