// Geometric synthesis of the Orthoglide: Pashkevich, Wenger, Chablat, MMT 40(8) 2005, sections 3.2-6.
//
// The specification is a cube of edge c and symmetric bounds [mu, 1/mu], 0 < mu < 1, on the velocity
// transmission factors. The Q-axis (the bisector p_x = p_y = p_z) gives the joint limits; the
// critical points Q, R, S (section 5.1) give the global transmission factors over the joint-bounded
// workspace W_rho = {p : rho(p) in [rho_min, rho_max]^3}; the three strategies of Table 3 place the
// cube; the unit design (L = 1) is then scaled by c / (p_max - p_min).
//
// Functions named "unit" work on the unit manipulator (L = 1, all lengths in units of L). The
// numerical searches and OrthoglideDesign use SI (m). Transmission factors are dimensionless.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/mechanisms/orthoglide_kinematics.hpp"

namespace kinestat::mechanisms {

// ---- Q-axis, section 3.2 (L = 1). chi = -p / sqrt(1 - 2 p^2) parameterises the bisector; the
// singularity-free part is chi in (-1/2, 1), where p and rho decrease monotonically with chi.
double unit_q_axis_position(double chi);  // p = -chi / sqrt(1 + 2 chi^2)
double unit_q_axis_joint(double chi);     // rho = (1 - chi) / sqrt(1 + 2 chi^2)
double unit_q_axis_chi_from_position(double p);
// Inverse of rho(chi) on (-1/2, 1): chi = (1 - rho^2) / (1 + rho sqrt(3 - 2 rho^2)), an algebraically
// equal form of the root (rho sqrt(3 - 2 rho^2) - 1) / (2 rho^2 - 1) without the 0/0 at rho^2 = 1/2.
// (The paper prints this root with the opposite sign, section 5.2; the sign above gives chi(1) = 0.)
double unit_q_axis_chi_from_joint(double rho);

// Closed interval of real numbers; max = +inf when a parallel singularity is included, min = 0 a
// serial one.
struct TransmissionRange {
  double min = 0.0;
  double max = 0.0;
  bool singular() const { return !(max < std::numeric_limits<double>::infinity()) || !(min > 0.0); }
};

// Eq. (16) for the symmetric bounds [mu, 1/mu]: the Q-axis segment chi in [chi_plus, chi_minus] on
// which both Q-axis singular values 1 + 2 chi and 1 - chi of J^-1 give factors within bounds.
// Q+ (chi_plus <= 0) is the upper joint limit, Q- (chi_minus >= 0) the lower one.
struct UnitQAxisLimits {
  double chi_plus = 0.0, chi_minus = 0.0;
  double rho_plus = 0.0, rho_minus = 0.0;  // rho(Q+) > 1 > rho(Q-)
  double p_plus = 0.0, p_minus = 0.0;      // p(Q+) > 0 > p(Q-)
};
UnitQAxisLimits unit_q_axis_limits(double mu);

// ---- Critical points, section 5.1 (L = 1), for the joint limit value rho (rho_min or rho_max):
// Q: p = (p, p, p), rho = (rho, rho, rho), eq. (7), (17);
// R (R_z, in the xy-plane): p = (p, p, 0), rho = (rho, rho, rho_1), eq. (18)-(22);
// S (S_x, on the x axis): p = (p, 0, 0), rho = (rho, rho_1, rho_1), eq. (23)-(26).
enum class CriticalPoint { kQ, kR, kS };
const char* to_string(CriticalPoint c);
Vec3 unit_critical_point_position(CriticalPoint c, double rho);
// Singular values of J^-1 at that point from the paper's closed forms, descending.
Vec3 unit_critical_point_singular_values(CriticalPoint c, double rho);

// Section 5.2: the global transmission factors over W_rho for unit joint limits
// 0 < rho_min <= 1 <= rho_max < sqrt(2), as the extremes over the six critical points Q+-, R+-, S+-.
// rho_max >= sqrt(3/2) puts the parallel singularity inside W_rho: max = +inf. As the paper claims,
// exact for rho_min >= ~0.24; below, the true mu_min is up to 0.8 % lower (it lies on an edge but
// not at R-, see docs/orthoglide.md): search_joint_space gives the true value.
TransmissionRange unit_joint_space_range(double rho_min, double rho_max);
// Proposition 1: the factors over the cube [p_min, p_max]^3 (unit) are those at its two Q-axis
// vertices.
TransmissionRange unit_cube_range(double p_min, double p_max);
// Eq. (36b): the smallest unit rho_min with every factor of W_rho >= mu and <= 1/mu given
// rho_max = rho(Q+): the larger of the Q- bound (Q-axis, eq. 16) and the R- bound mu / sqrt(mu^2 - 2 mu + 2).
double unit_joint_space_rho_min(double mu);

// ---- Numerical search (SI) over a workspace, to verify the critical-point formulas: the factors
// are evaluated by SVD on the six faces of the box (n x n points each), an interior grid, and then
// refined by a shrinking pattern search around the extremes. Inside the joint box the direct
// kinematics of the working branch gives p; joint points with no assembly, or a det J^-1 <= 0,
// mark the workspace as singular (max = +inf, or min = 0 when a serial singularity is crossed).
struct WorkspaceSearch {
  TransmissionRange range;
  Vec3 p_at_min = Vec3::Zero(), rho_at_min = Vec3::Zero();  // m
  Vec3 p_at_max = Vec3::Zero(), rho_at_max = Vec3::Zero();  // m
  long evaluations = 0;
  bool singular = false;  // a sample had no assembly or was beyond a singularity
};
// W_rho = {rho in [rho_min, rho_max]^3, rho_x + rho_y + rho_z <= joint_sum_limit} (m).
WorkspaceSearch search_joint_space(const OrthoglideGeometry& g, double rho_min, double rho_max,
                                   double joint_sum_limit = std::numeric_limits<double>::infinity(), int n = 101);
// The cube [p_min, p_max]^3 (m) in the working mode.
WorkspaceSearch search_cube(const OrthoglideGeometry& g, double p_min, double p_max, int n = 101);

// Size checks of the numerical searches, estimated before anything is searched or allocated (the
// searches above trust n). The default limit is `kinestat design orthoglide --max-points`'s.
inline constexpr double kDefaultMaxSearchPoints = 2e6;
// kInvalidInput unless n >= 2 and one search of grid n (search_joint_space, search_cube: faces,
// cutting plane and interior, ~7 n^2 + n^3/64 points) visits at most max_points; `item` names n
// ("--search-points", "n"), `limit` the option that raises the limit ("--max-points", "max_points").
Status check_search_points(int n, double max_points, const std::string& item, const std::string& limit);
// The same for an n x n x n grid (sample_joint_workspace, unit_dexterous_volumes): n^3 points.
Status check_grid_points(int n, double max_points, const std::string& item, const std::string& limit);

// Fig. 3 and Table 2 (L = 1): the singularity-free workspace W0 (the working mode inside the sphere
// |p| < 1, on the near side of the flat singularity) relative to the sphere, and the parts of W0
// with mu_min >= mu_low (lower bounding), both bounds (two-sided), mu_max <= mu_high (upper),
// relative to W0. Counted over the centres of an n^3 grid on [-1, 1]^3.
struct DexterousVolumes {
  double singularity_free_of_sphere = 0.0;
  double lower_of_w0 = 0.0;
  double two_sided_of_w0 = 0.0;
  double upper_of_w0 = 0.0;
};
DexterousVolumes unit_dexterous_volumes(double mu_low, double mu_high, int n);

// Section 5.2, Fig. 9a: where the global minimum factor mu_min(rho_min) over W_rho changes its
// critical point, for W_rho = [rho_min, 1]^3 (L = 1; mu_min there is set by the low side and does not
// depend on rho_max as long as Q+ does not compete, i.e. for rho_min below ~0.5). The paper's
// rho_SR = 0.1093 and rho_RQ = 0.2240 (factors 0.3232, 0.4210) are where its critical-point formulas
// switch. The true minimum is lower there (docs/orthoglide.md): near S- on a face, then on the edge
// (rho_min, rho_min, t) at t ~ 0.45, short of R-. Along that edge it competes with the vertex
// Q- = (rho_min, rho_min, rho_min) and stays the lower one up to rho_min = 0.2398: the true switch.
struct MinimumSwitchPoints {
  double rho_sr = 0.0, mu_sr = 0.0;  // S- | R- by the formulas
  double rho_rq = 0.0, mu_rq = 0.0;  // R- | Q- by the formulas
  double search_mu_at_rho_sr = 0.0;  // numerical search (search_joint_space) at rho_sr: the true mu_min
  double search_mu_at_rho_rq = 0.0;  // ... at rho_rq
  double rho_q = 0.0, mu_q = 0.0;    // the true switch to Q- and the factor there (Q-'s)
};
// `n`: grid of the numerical searches (search_joint_space).
MinimumSwitchPoints unit_minimum_switch_points(int n = 41);

// ---- The three design strategies, Table 3 (unit values scaled by L = c / (p_max - p_min)).
//  1: cube vertices at Q+, Q-; rho_max raised to 1 + p(Q+) so the cube is reachable.
//  2: joint limits at Q+, Q-; the largest cube inside W_rho, p_max = rho(Q+) - 1 (Proposition 2).
//  3: rho_min raised so all of W_rho meets [mu, 1/mu] (eq. 36); cube as in 2 (Corollary).
struct OrthoglideDesign {
  int strategy = 0;
  double mu = 0.0;                      // specification: factors in [mu, 1/mu]
  double cube_size = 0.0;               // c (m)
  double link_length = 0.0;             // L (m)
  double rho_min = 0.0, rho_max = 0.0;  // actuated joint limits (m)
  double p_min = 0.0, p_max = 0.0;      // the cube [p_min, p_max]^3 (m)
  double rho_q_plus = 0.0;              // rho at Q+ of the Q-axis analysis (m)
  // Software limit rho_x + rho_y + rho_z <= 3 rho(Q+) (m, section 6), set (finite) when the box
  // [rho_min, rho_max]^3 reaches the parallel singularity (rho_max >= sqrt(3/2) L, strategy 1).
  double joint_sum_limit = std::numeric_limits<double>::infinity();
  TransmissionRange joint_space;  // over the box W_rho, critical points (unit_joint_space_range, no software limit)
  TransmissionRange cube;         // over the cube, Proposition 1
  // Share of the joint box [rho_min, rho_max]^3 (joint-space volume) that the software limit keeps: the
  // cut corner is the simplex sum(rho_max - rho) < 3 rho_max - joint_sum_limit. 1 without a limit.
  double joint_box_kept = 1.0;
};
// kInvalidInput when strategy is not 1, 2 or 3, mu is not in (0, 1), or c is not positive and finite.
StatusOr<OrthoglideDesign> design_orthoglide(int strategy, double mu, double cube_size);

// Section 6's encoder offsets: the controller commands the cube [p_min, p_max]^3 (m) through the
// nominal inverse kinematics, but every slider sits `offset` (m) further out than commanded (rho + offset
// on all three joints); the factors are those of the postures actually reached (direct kinematics).
// With +5 and +10 mm the prototype's cube goes from [0.50, 2.00] to [0.507, 2.419] and [0.515, 3.420]:
// the paper's upper bounds 2.42 and 3.42 (docs/orthoglide.md).
WorkspaceSearch search_cube_with_encoder_offset(const OrthoglideGeometry& g, double p_min, double p_max, double offset,
                                                int n = 101);

// Numerical check of a design: search_joint_space (with its software limit), search_cube, and the cube
// under each of `encoder_offsets` (m).
struct EncoderOffsetEffect {
  double offset = 0.0;  // m, on every joint
  WorkspaceSearch cube;
};
struct OrthoglideDesignCheck {
  WorkspaceSearch joint_space;
  WorkspaceSearch cube;
  std::vector<EncoderOffsetEffect> encoder_offsets;
};
OrthoglideDesignCheck check_design(const OrthoglideDesign& d, int n = 101,
                                   const std::vector<double>& encoder_offsets = {});

// The joint-bounded workspace sampled on a regular n x n x n joint grid (index i + n (j + n k) for
// rho_x, rho_y, rho_z), mapped by the working-branch direct kinematics: for VTK output.
struct JointWorkspaceSamples {
  int n = 0;
  std::vector<Vec3> rho;  // m
  std::vector<Vec3> p;    // m (zero where !valid)
  std::vector<VelocityTransmission> factors;
  std::vector<char> valid;  // assembly exists, regular, and within the software limit
};
JointWorkspaceSamples sample_joint_workspace(const OrthoglideDesign& d, int n);

}  // namespace kinestat::mechanisms
