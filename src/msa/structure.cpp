#include "kinestat/msa/structure.hpp"

#include <cmath>
#include <set>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "kinestat/core/frame.hpp"
#include "kinestat/core/input_checks.hpp"

namespace kinestat::msa {
namespace {

template <class T>
std::optional<int> find_by_id(const std::vector<T>& items, const std::string& id) {
  for (size_t i = 0; i < items.size(); ++i)
    if (items[i].id == id) return static_cast<int>(i);
  return std::nullopt;
}

// The item's source when it has one (materials and sections, elements-layer types, have none).
template <class T>
std::string source_of(const T& item) {
  if constexpr (requires { item.source; })
    return item.source;
  else
    return {};
}

// A joint's coupled spring: finite, symmetric, zero on the diagonal and in rigid components' rows,
// and, with the components' stiffnesses on its diagonal, positive semidefinite (a spring that gives
// energy back is no spring).
Status check_coupling(const Joint& j) {
  if (j.coupling.isZero(0.0)) return Status::Ok();
  if (!j.coupling.allFinite())
    return Status::Invalid(fmt::format("joint '{}': its coupling terms must be finite", j.id));
  Mat6 K = j.coupling;
  for (int i = 0; i < 6; ++i) {
    if (K(i, i) != 0.0)
      return Status::Invalid(
          fmt::format("joint '{}': the diagonal of its coupling must be zero (the components' "
                      "stiffnesses are `stiffness`)",
                      j.id));
    if (std::isinf(j.stiffness(i)) && !K.row(i).isZero(0.0))
      return Status::Invalid(
          fmt::format("joint '{}': its rigid component {} is coupled to others; a coupled spring has finite components",
                      j.id, dof_name(i)));
    K(i, i) = std::isinf(j.stiffness(i)) ? 0.0 : j.stiffness(i);
  }
  const double scale = K.cwiseAbs().maxCoeff();
  if ((K - K.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
    return Status::Invalid(fmt::format("joint '{}': its stiffness with its coupling is not symmetric", j.id));
  const double lowest = Eigen::SelfAdjointEigenSolver<Mat6>(K, Eigen::EigenvaluesOnly).eigenvalues()(0);
  if (lowest < -1e-9 * scale)
    return Status::Invalid(fmt::format(
        "joint '{}': its stiffness with its coupling is not positive semidefinite (eigenvalue {:.3g} in units of "
        "its largest term): a spring cannot give energy back",
        j.id, lowest / scale));
  return Status::Ok();
}

bool is_rotation(const Mat3& R) { return (R.transpose() * R - Mat3::Identity()).norm() < 1e-9 && R.determinant() > 0; }

}  // namespace

int Structure::add_node(std::string id, const Vec3& position, std::string source) {
  nodes_.push_back({std::move(id), position, std::move(source)});
  return static_cast<int>(nodes_.size()) - 1;
}
int Structure::add_material(Material m) {
  materials_.push_back(std::move(m));
  return static_cast<int>(materials_.size()) - 1;
}
int Structure::add_section(Section s) {
  sections_.push_back(std::move(s));
  return static_cast<int>(sections_.size()) - 1;
}
int Structure::add_beam(Beam b) {
  beams_.push_back(std::move(b));
  return static_cast<int>(beams_.size()) - 1;
}
int Structure::add_joint(Joint j) {
  joints_.push_back(std::move(j));
  return static_cast<int>(joints_.size()) - 1;
}
int Structure::add_rigid_link(RigidLink r) {
  rigid_links_.push_back(std::move(r));
  return static_cast<int>(rigid_links_.size()) - 1;
}
void Structure::add_support(Support s) { supports_.push_back(s); }
int Structure::add_load_case(LoadCase lc) {
  load_cases_.push_back(std::move(lc));
  return static_cast<int>(load_cases_.size()) - 1;
}

std::optional<int> Structure::find_node(const std::string& id) const { return find_by_id(nodes_, id); }
std::optional<int> Structure::find_material(const std::string& id) const { return find_by_id(materials_, id); }
std::optional<int> Structure::find_section(const std::string& id) const { return find_by_id(sections_, id); }
std::optional<int> Structure::find_beam(const std::string& id) const { return find_by_id(beams_, id); }

double Structure::beam_length(const Beam& b) const {
  return (nodes_[b.node2].position - nodes_[b.node1].position).norm();
}

double Structure::length_scale() const {
  if (nodes_.size() < 2) return 1.0;
  Eigen::AlignedBox3d box;
  for (const auto& n : nodes_) box.extend(n.position);
  const double d = box.diagonal().norm();
  return d > 0 ? d : 1.0;
}

Mat3 Structure::beam_axes(const Beam& b) const {
  const Vec3& p1 = nodes_[b.node1].position;
  const Vec3& p2 = nodes_[b.node2].position;
  const Vec3 o = b.orientation.squaredNorm() > 0 ? b.orientation : default_orientation(p2 - p1);
  Mat3 axes = Mat3::Identity();
  element_axes(p1, p2, o, axes);
  return axes;
}

Status Structure::validate() const {
  const int nn = static_cast<int>(nodes_.size());
  auto node_ok = [nn](int i) { return i >= 0 && i < nn; };
  auto invalid = [](const std::string& source, const std::string& message) {
    return Status::Invalid(at_source(source, message));
  };
  auto dup = [&](const auto& items, const char* kind) -> Status {
    std::set<std::string> seen;
    for (const auto& it : items)
      if (!seen.insert(it.id).second)
        return invalid(source_of(it),
                       fmt::format("{} '{}' is defined twice; give each {} a unique id", kind, it.id, kind));
    return Status::Ok();
  };
  if (nn == 0) return invalid(source_, "the structure has no nodes");
  for (const auto& s : {dup(nodes_, "node"), dup(materials_, "material"), dup(sections_, "section"),
                        dup(beams_, "beam"), dup(joints_, "joint"), dup(rigid_links_, "rigid link")})
    if (!s.ok()) return s;
  for (const auto& n : nodes_)
    for (int k = 0; k < 3; ++k)
      if (Status st =
              check_quantity(n.position[k], Quantity::kLength, fmt::format("node '{}': coordinate {}", n.id, "xyz"[k]));
          !st.ok())
        return invalid(n.source, st.message());
  const double tol = 1e-9 * length_scale();

  for (const auto& m : materials_) {
    for (const auto& [name, value] : {std::pair{"E", m.E}, std::pair{"G", m.G}})
      if (Status st = check_quantity(value, Quantity::kModulus, fmt::format("material '{}': {}", m.id, name), {},
                                     Sign::kPositive);
          !st.ok())
        return st;
    if (Status st = check_quantity(m.density, Quantity::kDensity, fmt::format("material '{}': density", m.id), {},
                                   Sign::kNonNegative);
        !st.ok())
      return st;
  }
  for (const auto& s : sections_) {
    const std::pair<const char*, double> values[] = {{"A", s.A},     {"Iy", s.Iy},   {"Iz", s.Iz}, {"J", s.J},
                                                     {"Asy", s.Asy}, {"Asz", s.Asz}, {"Ip", s.Ip}};
    for (const auto& [name, value] : values) {
      const bool area = name[0] == 'A';
      // Shear areas: 0 = no shear deformation; Ip: 0 = Iy + Iz.
      const bool zero_allowed = (area && name[1] == 's') || name[1] == 'p';
      if (Status st = check_quantity(value, area ? Quantity::kArea : Quantity::kInertia,
                                     fmt::format("section '{}': {}", s.id, name), {},
                                     zero_allowed ? Sign::kNonNegative : Sign::kPositive);
          !st.ok())
        return st;
    }
  }

  for (const auto& b : beams_) {
    if (!node_ok(b.node1) || !node_ok(b.node2))
      return invalid(b.source, fmt::format("beam '{}' refers to a node that does not exist", b.id));
    if (b.material < 0 || b.material >= static_cast<int>(materials_.size()))
      return invalid(b.source, fmt::format("beam '{}' has no valid material", b.id));
    if (b.section < 0 || b.section >= static_cast<int>(sections_.size()))
      return invalid(b.source, fmt::format("beam '{}' has no valid section", b.id));
    const Vec3 d = nodes_[b.node2].position - nodes_[b.node1].position;
    if (d.norm() <= tol)
      return invalid(b.source, fmt::format("beam '{}' has zero length (nodes '{}' and '{}' coincide); use a joint or "
                                           "rigid link between coincident nodes",
                                           b.id, nodes_[b.node1].id, nodes_[b.node2].id));
    if (!b.orientation.allFinite())
      return invalid(b.source, fmt::format("beam '{}': its orientation vector is not finite", b.id));
    Mat3 axes;
    if (b.orientation.squaredNorm() > 0 &&
        !element_axes(nodes_[b.node1].position, nodes_[b.node2].position, b.orientation, axes))
      return invalid(b.source, fmt::format("beam '{}': its orientation vector is parallel to the beam; give a vector "
                                           "in the beam's local x-y plane that is not along the beam",
                                           b.id));
  }
  for (const auto& j : joints_) {
    if (!node_ok(j.node1) || !node_ok(j.node2) || j.node1 == j.node2)
      return invalid(j.source, fmt::format("joint '{}' must connect two different existing nodes", j.id));
    const double gap = (nodes_[j.node2].position - nodes_[j.node1].position).norm();
    if (gap > tol)
      return invalid(j.source, fmt::format("joint '{}' connects nodes '{}' and '{}' that are {:g} m apart: a joint's "
                                           "nodes must coincide (model the offset with a beam or a rigid link)",
                                           j.id, nodes_[j.node1].id, nodes_[j.node2].id, gap));
    if (!is_rotation(j.frame)) return invalid(j.source, fmt::format("joint '{}': its frame is not a rotation", j.id));
    for (int k = 0; k < 6; ++k) {
      if (j.stiffness(k) == kRigid) continue;
      if (Status st = check_quantity(
              j.stiffness(k), k < 3 ? Quantity::kTranslationalStiffness : Quantity::kRotationalStiffness,
              fmt::format("joint '{}': stiffness {} (0 = released, rigid = constrained)", j.id, dof_name(k)), {},
              Sign::kNonNegative);
          !st.ok())
        return invalid(j.source, st.message());
    }
    if (Status st = check_coupling(j); !st.ok()) return invalid(j.source, st.message());
  }
  std::set<int> constrained;  // nodes whose dofs depend on another node (slaves)
  for (const auto& r : rigid_links_) {
    if (!node_ok(r.master) || !node_ok(r.slave) || r.master == r.slave)
      return invalid(r.source, fmt::format("rigid link '{}' must connect two different existing nodes", r.id));
    if (!is_rotation(r.frame))
      return invalid(r.source, fmt::format("rigid link '{}': its frame is not a rotation", r.id));
    constrained.insert(r.slave);
  }
  for (const auto& m : masses_) {
    if (!node_ok(m.node)) return invalid(m.source, "a nodal mass refers to a node that does not exist");
    const std::string item = fmt::format("mass at node '{}'", nodes_[m.node].id);
    if (Status st = check_quantity(m.mass, Quantity::kMass, item + ": mass", {}, Sign::kNonNegative); !st.ok())
      return invalid(m.source, st.message());
    for (int d = 0; d < 3; ++d)
      if (Status st = check_quantity(m.inertia(d), Quantity::kMassInertia, item + ": inertia", {}, Sign::kNonNegative);
          !st.ok())
        return invalid(m.source, st.message());
  }
  for (const auto& s : supports_) {
    if (!node_ok(s.node)) return invalid(s.source, "a support refers to a node that does not exist");
    if (!is_rotation(s.frame))
      return invalid(s.source, fmt::format("support of node '{}': its frame is not a rotation", nodes_[s.node].id));
    if (constrained.count(s.node))
      return invalid(s.source, fmt::format("node '{}' is both supported and the slave of a rigid link: support its "
                                           "master node instead",
                                           nodes_[s.node].id));
  }
  for (const auto& lc : load_cases_) {
    for (const auto& l : lc.loads) {
      if (!node_ok(l.node))
        return invalid(l.source,
                       fmt::format("load case '{}': a load is applied to a node that does not exist", lc.name));
      for (int k = 0; k < 6; ++k)
        if (Status st = check_quantity(l.wrench(k), k < 3 ? Quantity::kForce : Quantity::kMoment,
                                       fmt::format("load case '{}': the load on node '{}', {}", lc.name,
                                                   nodes_[l.node].id, k < 3 ? "force" : "moment"));
            !st.ok())
          return invalid(l.source, st.message());
    }
    for (int k = 0; k < 3; ++k)
      if (Status st = check_quantity(lc.gravity(k), Quantity::kAcceleration,
                                     fmt::format("load case '{}': gravity {}", lc.name, "xyz"[k]));
          !st.ok())
        return invalid(lc.source, st.message());
    if (lc.gravity.squaredNorm() > 0.0) {
      bool weight = false;
      for (const auto& b : beams_) weight = weight || materials_[b.material].density > 0.0;
      if (!weight)
        return invalid(lc.source, fmt::format("load case '{}': gravity is given but no beam's material has a density, "
                                              "so it would load nothing; add density to the materials",
                                              lc.name));
    }
    for (const auto& ml : lc.member_loads)
      if (Status st = validate_member_load(lc, ml); !st.ok()) return st;
    // The loads are summed per node and over the structure: the sums must be finite too.
    Vec6 total = Vec6::Zero();
    for (const auto& l : lc.loads) total += l.wrench.cwiseAbs();
    if (!total.allFinite())
      return invalid(lc.source,
                     fmt::format("load case '{}': the sum of the loads is not finite; check the values", lc.name));
    std::set<std::pair<int, int>> prescribed;
    for (const auto& p : lc.prescribed) {
      if (!node_ok(p.node) || p.dof < 0 || p.dof >= 6)
        return invalid(p.source,
                       fmt::format("load case '{}': a prescribed displacement names a missing node or dof", lc.name));
      if (Status st = check_quantity(p.value, p.dof < 3 ? Quantity::kLength : Quantity::kAngle,
                                     fmt::format("load case '{}': the prescribed {} of node '{}'", lc.name,
                                                 dof_name(p.dof), nodes_[p.node].id));
          !st.ok())
        return invalid(p.source, st.message());
      if (!prescribed.insert({p.node, p.dof}).second)
        return invalid(p.source, fmt::format("load case '{}': the {} of node '{}' is prescribed twice; give one value",
                                             lc.name, dof_name(p.dof), nodes_[p.node].id));
      bool supported = false;
      for (const auto& s : supports_) supported |= (s.node == p.node && s.fixed[p.dof]);
      if (!supported)
        return invalid(p.source, fmt::format("load case '{}': node '{}' {} has a prescribed displacement but is not a "
                                             "supported dof; add it to the node's support",
                                             lc.name, nodes_[p.node].id, dof_name(p.dof)));
    }
  }
  if (report_node_ && !node_ok(*report_node_)) return invalid(source_, "the report node does not exist");
  return Status::Ok();
}

// Called by validate() after the beams are checked, so the beam's length is known.
Status Structure::validate_member_load(const LoadCase& lc, const MemberLoad& ml) const {
  auto invalid = [&](const std::string& message) { return Status::Invalid(at_source(ml.source, message)); };
  if (ml.beam < 0 || ml.beam >= static_cast<int>(beams_.size()))
    return invalid(fmt::format("load case '{}': a member load is applied to a beam that does not exist", lc.name));
  const Beam& b = beams_[ml.beam];
  const std::string item = fmt::format("load case '{}': the member load on beam '{}'", lc.name, b.id);
  auto check = [&](double v, Quantity q, const char* what, Sign sign = Sign::kAny) {
    Status st = check_quantity(v, q, fmt::format("{}, {}", item, what), {}, sign);
    return st.ok() ? st : invalid(st.message());
  };
  auto check3 = [&](const Vec3& v, Quantity q, const char* what) {
    for (int k = 0; k < 3; ++k)
      if (Status st = check(v(k), q, what); !st.ok()) return st;
    return Status::Ok();
  };
  const double L = beam_length(b);
  auto inside = [&](double x, const char* name) {
    if (Status st = check(x, Quantity::kLength, name); !st.ok()) return st;
    if (x < 0.0 || x > L)
      return invalid(
          fmt::format("{}: {} = {:g} m lies outside the beam (length {:g} m); give a distance from its first "
                      "node between 0 and the length",
                      item, name, x, L));
    return Status::Ok();
  };
  switch (ml.type) {
    case MemberLoadType::kUniform:
      return check3(ml.w1, Quantity::kForcePerLength, "w");
    case MemberLoadType::kTrapezoidal:
      for (const Status& st : {check3(ml.w1, Quantity::kForcePerLength, "w1"),
                               check3(ml.w2, Quantity::kForcePerLength, "w2"), inside(ml.a, "a"), inside(ml.b, "b")})
        if (!st.ok()) return st;
      if (!(ml.a < ml.b))
        return invalid(
            fmt::format("{}: the loaded stretch [a, b] = [{:g}, {:g}] m is empty; give a < b", item, ml.a, ml.b));
      return Status::Ok();
    case MemberLoadType::kPoint:
      for (const Status& st : {check3(ml.force, Quantity::kForce, "force"),
                               check3(ml.moment, Quantity::kMoment, "moment"), inside(ml.a, "a")})
        if (!st.ok()) return st;
      return Status::Ok();
    case MemberLoadType::kTemperature: {
      const ThermalLoad& t = ml.thermal;
      for (const Status& st :
           {check(t.alpha, Quantity::kThermalExpansion, "alpha", Sign::kPositive),
            check(t.dT, Quantity::kTemperature, "dT"), check(t.dTy, Quantity::kTemperature, "dTy"),
            check(t.dTz, Quantity::kTemperature, "dTz"),
            check(t.hy, Quantity::kLength, "hy", t.dTy != 0.0 ? Sign::kPositive : Sign::kNonNegative),
            check(t.hz, Quantity::kLength, "hz", t.dTz != 0.0 ? Sign::kPositive : Sign::kNonNegative)})
        if (!st.ok()) return st;
      return Status::Ok();
    }
  }
  return invalid(item + ": unknown member load type");
}

}  // namespace kinestat::msa
