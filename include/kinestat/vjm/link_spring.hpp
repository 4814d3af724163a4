// 6x6 stiffness of a link for the 6-dof virtual springs of eq. (1) (Pashkevich et al. 2009, section 4.2):
// from one beam (a cantilever: the 12x12 beam matrix condensed onto the free end, i.e. its free-end
// block, node 1 clamped), or from a serial chain of beams via the VJM itself,
// K_link^-1 = J_b K_b^-1 J_b^T (a chain of rigid transforms and springs, no passive joints).
#pragma once

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/vjm/chain.hpp"

namespace kinestat::vjm {

// Free-end stiffness of a cantilever of length L (m) in the beam's local axes (x along the beam from
// the clamp to the free end, y and z the section axes of `s`), dofs ux uy uz rx ry rz of the free end.
Mat6 cantilever_spring(const Material& m, const Section& s, double length, BeamTheory theory);

// Stiffness of the end of `link` (a chain with springs and rigid transforms only) relative to its
// base, expressed in the link's end frame: the spring to put after the link's rigid transform.
// kInvalidInput when the link has passive joints or a direction no spring deforms.
StatusOr<Mat6> serial_link_spring(const Chain& link);

}  // namespace kinestat::vjm
