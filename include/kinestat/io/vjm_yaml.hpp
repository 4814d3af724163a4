// Reading a VJM model (the chains of one platform, Pashkevich et al. 2009 eq. (1)) from a YAML file.
// Format and units: docs/vjm.md, "Model files and the vjm command". Two forms:
// - `mechanism: orthoglide` with the Orthoglide's design inputs: the chains are built by
//   mechanisms::orthoglide_chains at any Cartesian point (inverse kinematics);
// - `chains:` written element by element at one posture (the file gives every joint value).
// A spring may be `fea:` (a link mesh): reading the file then meshes the link and runs its FEA,
// unless the result is in the spring's `cache` folder.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/mechanisms/orthoglide_stiffness.hpp"
#include "kinestat/vjm/chain.hpp"

namespace kinestat::io {

struct VjmModel {
  std::string title;
  // `mechanism: orthoglide`: the design inputs (SI); chains come from the inverse kinematics.
  std::optional<mechanisms::OrthoglideStiffnessModel> orthoglide;
  mechanisms::OrthoglideArchitecture architecture = mechanisms::OrthoglideArchitecture::kPUU;
  // `chains:`: the platform at the file's posture (SI).
  std::vector<vjm::Chain> chains;
};

// Parses and checks a model file. Problems give kInvalidInput "FILE:LINE: ITEM: what is wrong; what to do".
StatusOr<VjmModel> read_vjm_model_yaml(const std::string& path);
StatusOr<VjmModel> read_vjm_model_yaml_string(const std::string& text, const std::string& display_name);

// The chains at the tool point `point` (m, Orthoglide kinematics frame). A point is accepted only by
// an Orthoglide model (kInvalidInput otherwise: a `chains:` file fixes its posture); no point means
// the Orthoglide's isotropic posture Q0 = (0, 0, 0) or the file's posture.
StatusOr<std::vector<vjm::Chain>> vjm_model_chains(const VjmModel& model, const std::optional<Vec3>& point);

}  // namespace kinestat::io
