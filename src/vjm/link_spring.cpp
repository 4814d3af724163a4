#include "kinestat/vjm/link_spring.hpp"

#include <fmt/format.h>

#include "kinestat/core/frame.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::vjm {

Mat6 cantilever_spring(const Material& m, const Section& s, double length, BeamTheory theory) {
  // Node 1 clamped: condensing the clamped dofs away leaves the node-2 block.
  return beam_local_stiffness(m, s, length, theory).bottomRightCorner<6, 6>();
}

StatusOr<Mat6> serial_link_spring(const Chain& link) {
  if (link.num_passive() > 0)
    return Status::Invalid(
        fmt::format("link '{}' has passive joints; a link spring needs springs and rigid "
                    "transforms only",
                    link.name()));
  StatusOr<CartesianStiffness> k = unloaded_stiffness(link);
  if (!k.ok()) return k.status();
  if (!k->status.ok() || !k->free_directions.empty())
    return Status::Invalid(
        fmt::format("link '{}': {}", link.name(), k->status.ok() ? "it has a free motion" : k->status.message()));
  // unloaded_stiffness works in global axes; the spring is expressed in the link's end frame.
  const Mat6 R = rotation6(link.nominal_pose().linear());
  return Mat6(R.transpose() * k->stiffness * R);
}

}  // namespace kinestat::vjm
