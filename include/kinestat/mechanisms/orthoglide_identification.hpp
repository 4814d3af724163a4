// Identification of an Orthoglide stiffness model's unknown inputs from measured (or published)
// compliance values: the declared calibration behind models/orthoglide_*.yaml.
//
// Pashkevich et al. 2009 publish the compliance (Tables 1-2) but not the inputs it came from (link
// stiffness from FEA, actuator stiffness, platform geometry). With as many target compliance terms as
// free inputs, the model is solved for the inputs; every other term of the tables is then a
// prediction that can be compared (tests/mechanisms/orthoglide_identification_test.cpp, docs/vjm.md).
// The same function calibrates a model to a robot's measured compliance.
//
// Method: Levenberg-Marquardt (Eigen's unsupported NonLinearOptimization module) on the logarithms of
// the inputs (they stay positive, and the steps do not depend on their units), residuals
// log(model / target) for diagonal terms and model / target - 1 otherwise, forward-difference
// Jacobian.
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/mechanisms/orthoglide_stiffness.hpp"

namespace kinestat::mechanisms {

// The model inputs the identification may adjust.
enum class OrthoglideInput {
  kActuatorStiffness,   // actuator_stiffness (N/m)
  kBarScale,            // every dimension of bar_section scaled by one factor (scaled_section)
  kParallelogramWidth,  // parallelogram_width (m)
  kPlatformOffset,      // platform_offset (m)
  kFootLength,          // foot_length (m): the foot's bending compliance grows as its cube
};
const char* input_name(OrthoglideInput input);

// One unloaded compliance term C(row, col) of C = K^-1 (SI: m/N, 1/N, rad/(N m)); dofs
// (dx dy dz rx ry rz) at the tool point, global axes.
struct ComplianceTarget {
  std::string label;  // for reports, e.g. "Table 1, Q0, k_tran"
  OrthoglideArchitecture architecture = OrthoglideArchitecture::kPUU;
  Vec3 point = Vec3::Zero();  // kinematics frame (m)
  int row = 0, col = 0;
  double value = 0.0;
  std::string source{};  // where it was read ("file:line"; empty when built in code): starts its messages
};

struct OrthoglideIdentification {
  OrthoglideStiffnessModel model;  // the start model with the identified inputs
  // Per input, in the order asked: the start and identified values, SI (the bar scale is relative to
  // the start model's section, so it starts at 1).
  std::vector<double> start_values, values;
  std::vector<double> relative_residual;  // per target, (model - target) / |target|
  int iterations = 0, evaluations = 0;
  std::string report;  // inputs before and after, target and model values, convergence
};

// Solves for `inputs` (start values from `start`; each must be > 0, so give platform_offset a
// positive guess) so that the model's compliance matches `targets`; at least as many targets as
// inputs. kInvalidInput for a bad start model, a tolerance outside (0, 1), too few targets, an index
// out of range, a negative diagonal term, a repeated target, an input that changes no target or
// targets that cannot tell the inputs apart (rank-deficient Jacobian at the start); kSingular if a
// target cannot be evaluated at the start (unreachable point, singular posture); kNotConverged when a
// residual stays above `tolerance` (the report says which). Messages about a target start with its
// source and label.
StatusOr<OrthoglideIdentification> identify_orthoglide_inputs(const OrthoglideStiffnessModel& start,
                                                              const std::vector<OrthoglideInput>& inputs,
                                                              const std::vector<ComplianceTarget>& targets,
                                                              double tolerance = 1e-8);

// The declared calibration of models/orthoglide_*.yaml: five unloaded diagonal entries of
// Pashkevich et al. 2009 (Q0 k_tran 2.78e-4 mm/N of both tables, Q0 k_rot 20.9e-7 and 1.94e-7
// rad/(N mm) of Tables 1 and 2, Q2 k_tran 71.3e-4 and 21.2e-4 mm/N), in SI at the kinematics-frame
// points of paper_table_point, and the five inputs they identify (every input of OrthoglideInput).
std::vector<ComplianceTarget> paper_calibration_targets();
std::vector<OrthoglideInput> paper_calibration_inputs();
// Its start: the nominal inputs (OrthoglideStiffnessModel{}) with a 50 mm platform offset guess.
OrthoglideStiffnessModel paper_calibration_start();

}  // namespace kinestat::mechanisms
