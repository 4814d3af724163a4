// Reading a VJM model (the chains of one platform, Pashkevich et al. 2009 eq. (1)) from a YAML file.
// Format and units: docs/vjm.md, "Model files and the vjm command". Two forms:
// - `mechanism: orthoglide` with the Orthoglide's design inputs: the chains are built by
//   mechanisms::orthoglide_chains at any Cartesian point (inverse kinematics);
// - `chains:` written element by element at one posture (the file gives every joint value).
// A spring may be `fea:` (a link mesh): reading the file only records what to compute (a
// FeaSpring); resolve_fea_springs meshes the link and runs its FEA (or reads the spring's `cache`).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/mechanisms/orthoglide_stiffness.hpp"
#include "kinestat/vjm/chain.hpp"

namespace kinestat::io {

// A `fea:` spring of a `chains:` file: the link stiffness to compute and the spring it becomes.
struct FeaSpring {
  int chain = 0;                      // index into VjmModel::chains
  int spring = 0;                     // index into that chain's springs()
  std::string where;                  // "FILE:LINE: chain 'c' element N (spring) fea", for messages
  fea::LinkStiffnessRequest request;  // paths resolved against the model file's folder, SI
  bool resolved = false;              // the chain's spring holds the result
};

struct VjmModel {
  std::string title;
  // `mechanism: orthoglide`: the design inputs (SI); chains come from the inverse kinematics.
  std::optional<mechanisms::OrthoglideStiffnessModel> orthoglide;
  mechanisms::OrthoglideArchitecture architecture = mechanisms::OrthoglideArchitecture::kPUU;
  // `chains:`: the platform at the file's posture (SI). The springs of `fea_springs` are not finite
  // until resolve_fea_springs has computed them.
  std::vector<vjm::Chain> chains;
  std::vector<FeaSpring> fea_springs;
};

// Parses and checks a model file. Problems give kInvalidInput "FILE:LINE: ITEM: what is wrong; what to do".
StatusOr<VjmModel> read_vjm_model_yaml(const std::string& path);
StatusOr<VjmModel> read_vjm_model_yaml_string(const std::string& text, const std::string& display_name);

// Computes every unresolved `fea:` spring (fea::compute_link_stiffness: meshing and FEA, or the
// spring's cache) and puts it into its chain. `progress` (optional) hears the long stages and
// `warning` (optional) what the user must hear, "FILE:LINE: ...: why" (a rejected cache entry,
// recomputed). A bad mesh or region gives kInvalidInput "FILE:LINE: chain 'c' element N (spring)
// fea: MESH: ...".
Status resolve_fea_springs(VjmModel& model, const std::function<void(const std::string&)>& progress = {},
                           const std::function<void(const std::string&)>& warning = {});

// The chains at the tool point `point` (m, Orthoglide kinematics frame). A point is accepted only by
// an Orthoglide model (kInvalidInput otherwise: a `chains:` file fixes its posture); no point means
// the Orthoglide's isotropic posture Q0 = (0, 0, 0) or the file's posture. kInvalidInput while
// `fea:` springs are unresolved.
StatusOr<std::vector<vjm::Chain>> vjm_model_chains(const VjmModel& model, const std::optional<Vec3>& point);

}  // namespace kinestat::io
