// What the diagnosis of a singular structure finds: which nodes and dofs move freely, and how, in
// words. The diagnosis itself runs inside msa::solve (src/msa/singularity_diagnosis.hpp).
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/types.hpp"

namespace kinestat::msa {

// One free motion (null-space mode) of a singular structure.
struct FreeMotion {
  std::vector<Vec6> node_motion;  // per node (ux uy uz rx ry rz); the largest translation is 1 (or the largest rotation if none)
  double rayleigh_ratio = 0.0;    // u'Ku / u'Du: ~1e-16 for a true mechanism
  std::string description;        // in words: which nodes move and how
};

struct SingularityDiagnosis {
  bool singular = false;
  struct WeakDof { int node; int dof; };  // dof in the node's support frame / global
  std::vector<WeakDof> weak_dofs;          // where the pivot check failed
  std::vector<FreeMotion> modes;
  std::string message;                     // the whole diagnosis in words
};

// "node '5' translates along +y" / "rotates about (0.71, 0.71, 0)": one node's motion in words.
std::string describe_node_motion(const Vec6& motion, double length_scale);

}  // namespace kinestat::msa
