// The 5R five-bar of Gonçalves et al. 2010 as a VJM model: two serial chains meeting at P, each a
// locked motor, beam springs (the cantilever condensation of each link) and passive revolute joints
// with the MSA joints' springs in their other five dofs. Same inputs as make_five_bar_structure, so
// the two methods must give the same 6x6 stiffness at P.
#pragma once

#include <vector>

#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/vjm/chain.hpp"

namespace kinestat::mechanisms {

// Chain 1 (A1 B1 P) crosses the P joint and chain 2 (A2 B2 P) ends at P, because the MSA report
// node "5" is P on the PB2 link. The tool frame has global axes.
std::vector<vjm::Chain> five_bar_vjm_chains(const FiveBarParams& p, const FiveBarPosture& q);

}  // namespace kinestat::mechanisms
