// The MSA model: an immutable description of a frame (nodes, beams, joints, rigid links, supports,
// load cases), built once and solved many times (Pinocchio's Model/Data split: this is the Model,
// msa::Solution is the Data). Units are SI (m, N, rad, Pa); io/ converts files declared in mm.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/elements/member_loads.hpp"
#include "kinestat/elements/section.hpp"

namespace kinestat::msa {

using DofMask = std::array<bool, 6>;  // per node dof: ux uy uz rx ry rz
inline constexpr DofMask kAllDofs = {true, true, true, true, true, true};
inline constexpr double kRigid = std::numeric_limits<double>::infinity();

// Every item may carry `source`, where it was defined ("FILE:LINE", set by io::read_structure_yaml;
// empty when built in code): the checks that run after reading (validate(), the solve's dof
// reduction) start their messages with it, so every message names the file and the line.

struct Node {
  std::string id;
  Vec3 position = Vec3::Zero();
  std::string source{};
};

struct Beam {
  std::string id;
  int node1 = -1, node2 = -1;  // indices into Structure::nodes()
  int material = -1, section = -1;
  Vec3 orientation = Vec3::Zero();  // a vector in the local x-y plane; zero = default_orientation()
  BeamTheory theory = BeamTheory::kEulerBernoulli;
  BeamReleases releases{};  // local dofs freed at the ends (pins, torsion releases)
  std::string source{};
};

// 6-dof spring between two coincident nodes; stiffness in `frame` (columns: local axes in global).
// A component may be 0 (released) or kRigid (exact constraint). `coupling`: the off-diagonal terms
// of a spring that couples its components in `frame` (a link's 6x6 from FEA; N/m, N and N m/rad as
// the components they join), symmetric with a zero diagonal, zero in the rows of rigid components,
// diag(stiffness) + coupling positive semidefinite (validate() checks).
struct Joint {
  std::string id;
  int node1 = -1, node2 = -1;
  Mat3 frame = Mat3::Identity();
  Vec6 stiffness = Vec6::Zero();
  Mat6 coupling = Mat6::Zero();
  std::string source{};
};

// The `slave` node follows `master` as a rigid body in the dofs of `mask` (expressed in `frame`);
// the other dofs stay independent. Full mask = rigid offset / rigid link.
struct RigidLink {
  std::string id;
  int master = -1, slave = -1;
  DofMask mask = kAllDofs;
  Mat3 frame = Mat3::Identity();
  std::string source{};
};

// Fixed dofs of a node, in `frame` (identity = global axes).
struct Support {
  int node = -1;
  DofMask fixed = kAllDofs;
  Mat3 frame = Mat3::Identity();
  std::string source{};
};

struct NodalLoad {
  int node = -1;
  Vec6 wrench = Vec6::Zero();  // Fx Fy Fz (N), Mx My Mz (N m), global axes
  std::string source{};
};

// A prescribed displacement of a supported dof (in the support's frame): m or rad.
struct PrescribedDisplacement {
  int node = -1;
  int dof = 0;
  double value = 0.0;
  std::string source{};
};

// A point mass at a node (kinestat modes): `mass` on its translations, `inertia` its rotary inertias
// about axes through the node parallel to global x, y, z.
struct NodalMass {
  int node = -1;
  double mass = 0.0;            // kg
  Vec3 inertia = Vec3::Zero();  // Ixx Iyy Izz, kg m^2
  std::string source{};
};

enum class MemberLoadType { kUniform, kTrapezoidal, kPoint, kTemperature };

// A load on the span of a beam (elements/member_loads.hpp gives its fixed-end forces). Vectors are
// in the beam's local axes, or in global axes when `global_axes`; distances a, b are measured along
// the beam from its first node (m). A distributed load is per unit length of the beam (N/m).
struct MemberLoad {
  int beam = -1;
  MemberLoadType type = MemberLoadType::kUniform;
  bool global_axes = false;
  Vec3 w1 = Vec3::Zero();      // uniform: the load; trapezoidal: the load at a (N/m)
  Vec3 w2 = Vec3::Zero();      // trapezoidal: the load at b (N/m)
  double a = 0.0;              // trapezoidal: start; point: where the force acts (m)
  double b = 0.0;              // trapezoidal: end, a < b <= L (m)
  Vec3 force = Vec3::Zero();   // point (N)
  Vec3 moment = Vec3::Zero();  // point (N m)
  ThermalLoad thermal{};       // temperature (local axes always)
  std::string source{};
};

// (Every member has an initializer, so that designated initializers may leave any out warning-free.)
struct LoadCase {
  std::string name{};
  std::vector<NodalLoad> loads{};
  std::vector<PrescribedDisplacement> prescribed{};
  std::string source{};
  // Self-weight: every beam carries the uniform global load density * A * gravity (m/s^2).
  Vec3 gravity = Vec3::Zero();
  std::vector<MemberLoad> member_loads{};
};

// How the beams' geometric stiffness K_G is formed (buckling, the second-order solve and the prestress
// of modal analysis; docs/stability-and-modes.md). kKinestat, the default: each beam's axial force is
// the mean of its end forces, N = (N2 - N1) / 2, and K_G has the axial term (N/L) [1 -1; -1 1].
// kFrame3dd, what Frame3DD does and what io::read_frame3dd sets: N is the force at the beam's first
// end (-N1), and K_G has no axial term. Either way a Timoshenko beam's K_G has the shear-deformation
// terms (elements/beam_element.hpp, GeometricStiffnessTerms).
enum class GeometricStiffnessConvention { kKinestat, kFrame3dd };

class Structure {
 public:
  // Building. Each add_* returns the new item's index. Names must be unique per kind.
  int add_node(std::string id, const Vec3& position, std::string source = {});
  int add_material(Material m);
  int add_section(Section s);
  int add_beam(Beam b);
  int add_joint(Joint j);
  int add_rigid_link(RigidLink r);
  void add_support(Support s);
  void add_mass(NodalMass m) { masses_.push_back(std::move(m)); }
  int add_load_case(LoadCase lc);
  void set_report_node(int node) { report_node_ = node; }
  void set_title(std::string t) { title_ = std::move(t); }
  // Where the structure was read from (a file name): starts the messages about the whole structure.
  void set_source(std::string s) { source_ = std::move(s); }
  void set_geometric_stiffness_convention(GeometricStiffnessConvention c) { kg_convention_ = c; }

  // Checks what the assembly relies on: valid indices, unique ids, every value finite and in its
  // physical range (core/input_checks.hpp), positive lengths and section properties, coincident joint
  // nodes, loads on existing nodes whose sum is finite, one prescribed value per dof, no node both
  // supported and constrained, member loads on existing beams and inside their span. Messages start with the item's
  // source, name the item and say what to fix.
  Status validate() const;

  const std::string& title() const { return title_; }
  const std::string& source() const { return source_; }
  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Material>& materials() const { return materials_; }
  const std::vector<Section>& sections() const { return sections_; }
  const std::vector<Beam>& beams() const { return beams_; }
  const std::vector<Joint>& joints() const { return joints_; }
  const std::vector<RigidLink>& rigid_links() const { return rigid_links_; }
  const std::vector<Support>& supports() const { return supports_; }
  const std::vector<NodalMass>& masses() const { return masses_; }
  const std::vector<LoadCase>& load_cases() const { return load_cases_; }
  std::optional<int> report_node() const { return report_node_; }
  GeometricStiffnessConvention geometric_stiffness_convention() const { return kg_convention_; }

  std::optional<int> find_node(const std::string& id) const;
  std::optional<int> find_material(const std::string& id) const;
  std::optional<int> find_section(const std::string& id) const;
  std::optional<int> find_beam(const std::string& id) const;
  int num_dofs() const { return kDofsPerNode * static_cast<int>(nodes_.size()); }
  // Largest distance between nodes (a length scale for tolerances); 1 if fewer than two nodes.
  double length_scale() const;
  // Local axes of a beam (x along it), from its orientation vector or the default.
  Mat3 beam_axes(const Beam& b) const;
  double beam_length(const Beam& b) const;

 private:
  Status validate_member_load(const LoadCase& lc, const MemberLoad& ml) const;

  std::string title_;
  std::string source_;
  std::vector<Node> nodes_;
  std::vector<Material> materials_;
  std::vector<Section> sections_;
  std::vector<Beam> beams_;
  std::vector<Joint> joints_;
  std::vector<RigidLink> rigid_links_;
  std::vector<Support> supports_;
  std::vector<NodalMass> masses_;
  std::vector<LoadCase> load_cases_;
  std::optional<int> report_node_;
  GeometricStiffnessConvention kg_convention_ = GeometricStiffnessConvention::kKinestat;
};

}  // namespace kinestat::msa
