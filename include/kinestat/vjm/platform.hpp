// Chains that share one platform (Pashkevich et al. 2009, section 3.3): the checks every platform
// computation (stiffness, equilibrium) starts with.
#pragma once

#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/vjm/chain.hpp"

namespace kinestat::vjm {

// Checks that the chains are valid (Chain::validate, at most `max_chain_coordinates` coordinates each)
// and that their nominal tool points coincide (the platform is assembled); the message names the chain
// at fault.
Status validate_platform(const std::vector<Chain>& chains, int max_chain_coordinates = kDefaultMaxChainCoordinates);

// The largest chain length scale (m): makes metres and radians comparable in rank decisions.
double platform_length_scale(const std::vector<Chain>& chains);

}  // namespace kinestat::vjm
