// What the diagnosis of a singular structure finds: which nodes and dofs move freely, and how, in
// words. The diagnosis itself runs inside msa::solve (src/msa/singularity_diagnosis.hpp).
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/types.hpp"

namespace kinestat::msa {

// One free motion (null-space mode) of a singular structure. A part that no support holds (the whole
// model when it has none) contributes six rigid-body motions in the canonical basis: unit translations
// along global x, y, z, then 1 rad rotations about x, y, z through the part's centroid; they come
// first, the other free motions (mechanisms) after them.
struct FreeMotion {
  std::vector<Vec6> node_motion;  // per node (ux uy uz rx ry rz); the largest translation is 1 (or the largest
                                  // rotation if none); rigid-body motions as above
  double rayleigh_ratio = 0.0;    // u'Ku / u'Du: ~1e-16 for a true mechanism
  std::string description;        // in words: which nodes move and how
};

struct SingularityDiagnosis {
  bool singular = false;
  struct WeakDof {
    int node;
    int dof;
  };                               // dof in the node's support frame / global
  std::vector<WeakDof> weak_dofs;  // where the pivot check failed
  std::vector<FreeMotion> modes;
  std::string message;  // the whole diagnosis in words
};

// "node '5' translates along +y" / "rotates about (0.71, 0.71, 0)": one node's motion in words.
std::string describe_node_motion(const Vec6& motion, double length_scale);

}  // namespace kinestat::msa
