// The 6x6 Cartesian stiffness of one point, as every method gives it: MSA (a node, by static
// condensation), VJM (a robot's tool point, Pashkevich et al. 2009 eq. 10 and 21) and FEA (a
// link's reference point), with the one report every command prints.
//
// Dofs (rows and columns): ux uy uz rx ry rz, the translation of `point` and the small rotation,
// along and about the axes named by `frame`. A wrench is (Fx Fy Fz, Mx My Mz), the moment about
// `point`. SI units (kStiffnessUnits, kComplianceUnits).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/stiffness_indices.hpp"
#include "kinestat/core/types.hpp"

namespace kinestat {

// The two 6x6 matrices of a point, fixed size (no heap): the part of a CartesianStiffness that a
// posture sweep keeps per point (mechanisms::PostureResult derives from it too).
struct CartesianMatrices {
  static constexpr const char* kStiffnessUnits = "N/m, N/rad (rows ux uy uz); N, N m/rad (rows rx ry rz)";
  static constexpr const char* kComplianceUnits = "m/N, m/(N m) (rows ux uy uz); rad/N, rad/(N m) (rows rx ry rz)";

  Mat6 stiffness = Mat6::Zero();
  Mat6 compliance = Mat6::Zero();
};

struct CartesianStiffness : CartesianMatrices {
  Vec3 point = Vec3::Zero();          // m, in `frame`: the tool, node or reference point
  std::string frame = "global axes";  // the axes of the dofs, in words

  // `stiffness` is the finite part: zero along rigid directions. `compliance` is zero along rigid
  // directions and is valid only when compliance_defined.
  bool stiffness_defined = false;  // no rigid direction: `stiffness` is the whole stiffness
  bool compliance_defined =
      false;  // no free direction: `compliance` is the whole compliance, K C = I off rigid directions
  std::vector<Vec6> free_directions;   // unit twists with zero stiffness (the point moves freely)
  std::vector<Vec6> rigid_directions;  // unit twists with infinite stiffness (left out of `stiffness`)

  std::optional<StiffnessIndices> indices;  // of `stiffness` (Gonçalves et al. 2010, eq. 7-13)
  std::string note;  // what else the method found, in words (why a matrix is undefined, self-motions)
  // kOk, or kSingular with the lost directions in words. A free direction of a single VJM chain is
  // its mobility and does not make the status singular.
  Status status;
};

// From a symmetric positive semi-definite compliance (symmetrized here): the stiffness is its
// inverse when it is regular; a compliance eigenvalue below 1e-13 of the largest is a rigid
// direction (a supported or rigidly tied dof), which leaves the stiffness undefined.
CartesianStiffness cartesian_from_compliance(const Mat6& compliance, const Vec3& point, std::string frame);

// A twist in words for diagnoses: "translation along (0.707, 0.707, 0)", "rotation about +z through
// the point" or a screw motion.
std::string describe_twist(const Vec6& twist);

// The one human-readable report of a Cartesian stiffness (MSA, VJM and FEA reports and commands
// print it): point and frame, the stiffness and the compliance with units, the indices of the
// stiffness, the lost directions in words, the note and the status. `title` heads it.
std::string cartesian_stiffness_report(const CartesianStiffness& c, const std::string& title);

}  // namespace kinestat
