#include "kinestat/io/structure_yaml.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <set>
#include <tuple>
#include <unordered_map>

#include "io/roll_orientation.hpp"
#include "io/yaml_fields.hpp"
#include "kinestat/core/frame.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/section.hpp"

namespace kinestat::io {
namespace {

using units::kDeg;

// One parse of one file. Every check fails through fail(), which names the file, the line of the
// offending YAML node, the item and the fix.
class Parser : public YamlFields {
 public:
  explicit Parser(std::string file) : YamlFields(std::move(file), "docs/structure-format.md") {}

  msa::Structure parse(const YAML::Node& root) {
    if (!root.IsDefined() || root.IsNull())
      fail(root, "file", "the file is empty; start with a 'nodes:' list (see docs/structure-format.md)");
    if (!root.IsMap())
      fail(root, "file", "the top level is not a map of keys; write 'nodes:', 'beams:', ... at the start of lines");
    check_keys(root, "file",
               {"units", "title", "beam_theory", "nodes", "materials", "sections", "beams", "joints", "rigid_links",
                "supports", "masses", "load_cases", "report"});
    units_ = units(root["units"], true);
    if (const YAML::Node t = root["beam_theory"]; t.IsDefined()) default_theory_ = theory(t, "file", "beam_theory");
    s_.set_source(file());
    if (const YAML::Node t = root["title"]; t.IsDefined()) s_.set_title(text(t, "file", "title"));
    for_each(root, "nodes", true, [&](const YAML::Node& n, int i) { parse_node(n, i); });
    zero_length_ = 1e-9 * s_.length_scale();  // as Structure::validate() judges coincidence
    for_each(root, "materials", false, [&](const YAML::Node& n, int i) { parse_material(n, i); });
    for_each(root, "sections", false, [&](const YAML::Node& n, int i) { parse_section(n, i); });
    for_each(root, "beams", false, [&](const YAML::Node& n, int i) { parse_beam(n, i); });
    for_each(root, "joints", false, [&](const YAML::Node& n, int i) { parse_joint(n, i); });
    for_each(root, "rigid_links", false, [&](const YAML::Node& n, int i) { parse_rigid_link(n, i); });
    for_each(root, "supports", false, [&](const YAML::Node& n, int i) { parse_support(n, i); });
    for_each(root, "masses", false, [&](const YAML::Node& n, int i) { parse_mass(n, i); });
    for_each(root, "load_cases", false, [&](const YAML::Node& n, int i) { parse_load_case(n, i); });
    if (const YAML::Node r = root["report"]; r.IsDefined()) {
      check_map(r, "report", {"node"});
      s_.set_report_node(node_ref(require(r, "report", "node"), "report", "node"));
    }
    return std::move(s_);
  }

 private:
  int dof(const YAML::Node& v, const std::string& item) {
    if (v.IsScalar()) {
      for (int d = 0; d < kDofsPerNode; ++d) {
        if (v.Scalar() == dof_name(d)) return d;
      }
    }
    fail(v, item, fmt::format("unknown dof '{}'; dofs are ux, uy, uz, rx, ry, rz", v.IsScalar() ? v.Scalar() : "?"));
  }

  // A list of dof names, or `all`.
  msa::DofMask dof_mask(const YAML::Node& v, const std::string& item) {
    if (v.IsScalar() && v.Scalar() == "all") return msa::kAllDofs;
    if (!v.IsSequence() || v.size() == 0) fail(v, item, "expected a list of dofs such as [ux, uy, rz] or the word all");
    msa::DofMask mask{};
    for (const auto& d : v) mask[static_cast<std::size_t>(dof(d, item))] = true;
    return mask;
  }

  // {x: [...], z: [...]}: the frame's x and z axes in global coordinates, perpendicular.
  Mat3 frame(const YAML::Node& v, const std::string& item) {
    check_map(v, item + " frame", {"x", "z"});
    const Vec3 x = direction(require(v, item + " frame", "x"), item, "frame x");
    const Vec3 z = direction(require(v, item + " frame", "z"), item, "frame z");
    if (std::abs(x.dot(z)) > 1e-6) {
      fail(v, item, "frame axes x and z are not perpendicular; give two perpendicular directions");
    }
    Mat3 R;
    R.col(0) = x;
    R.col(2) = z;
    R.col(1) = R.col(2).cross(R.col(0));
    return R;
  }

  int node_ref(const YAML::Node& v, const std::string& item, const std::string& key) {
    const std::string id = text(v, item, key);
    const auto n = node_index_.find(id);
    if (n == node_index_.end()) fail(v, item, fmt::format("unknown node '{}' in '{}'; define it under nodes", id, key));
    return n->second;
  }

  // An entry's id, checked for uniqueness within its kind.
  std::string entry_id(const YAML::Node& n, const char* kind, int index, std::set<std::string>& ids) {
    const std::string fallback = fmt::format("{} #{}", kind, index + 1);
    if (!n.IsMap()) fail(n, fallback, "expected a map such as {id: ..., ...}");
    const std::string id = text(require(n, fallback, "id"), fallback, "id");
    if (!ids.insert(id).second)
      fail(n["id"], fmt::format("{} '{}'", kind, id), "this id is already used; give each a unique id");
    return id;
  }

  // An entry that belongs to a node (`kind`: support, mass): its keys checked, its node and source
  // set in `entry`; returns its name for messages, "support at node 'A'".
  template <class Entry>
  std::string node_entry(const YAML::Node& n, const char* kind, int index, std::initializer_list<const char*> allowed,
                         Entry& entry) {
    const std::string fallback = fmt::format("{} #{}", kind, index + 1);
    check_map(n, fallback, allowed);
    entry.source = source(n);
    entry.node = node_ref(require(n, fallback, "node"), fallback, "node");
    return fmt::format("{} at node '{}'", kind, s_.nodes()[entry.node].id);
  }

  // --- blocks ----------------------------------------------------------------------------------

  void parse_node(const YAML::Node& n, int i) {
    const std::string id = entry_id(n, "node", i, node_ids_);
    const std::string item = fmt::format("node '{}'", id);
    check_keys(n, item, {"id", "xyz"});
    node_index_[id] = s_.add_node(
        id, vec3(require(n, item, "xyz"), item, "xyz", Quantity::kLength, units_.of(Quantity::kLength)), source(n));
  }

  void parse_material(const YAML::Node& n, int i) {
    const std::string id = entry_id(n, "material", i, material_ids_);
    const std::string item = fmt::format("material '{}'", id);
    check_keys(n, item, {"id", "E", "G", "nu", "density"});
    auto modulus = [&](const YAML::Node& v, const char* key) {
      return value(v, item, key, Quantity::kModulus, units_.of(Quantity::kModulus), Sign::kPositive);
    };
    const double E = modulus(require(n, item, "E"), "E");
    const YAML::Node G = n["G"], nu = n["nu"];
    if (G.IsDefined() == nu.IsDefined())
      fail(n, item, "give exactly one of G (shear modulus) and nu (Poisson's ratio)");
    Material m;
    if (G.IsDefined()) {
      m = Material{id, E, modulus(G, "G")};
    } else {
      const double v = number(nu, item, "nu");
      if (!(v > -1.0 && v <= 0.5)) fail(nu, item, fmt::format("nu = {} is outside (-1, 0.5]; steel is 0.3", v));
      m = Material::from_E_nu(id, E, v);
    }
    if (const YAML::Node d = n["density"]; d.IsDefined())
      m.density = value(d, item, "density", Quantity::kDensity, units_.of(Quantity::kDensity), Sign::kNonNegative);
    s_.add_material(m);
  }

  void parse_section(const YAML::Node& n, int i) {
    const std::string id = entry_id(n, "section", i, section_ids_);
    const std::string item = fmt::format("section '{}'", id);
    // A required positive property in file units, returned in SI.
    auto property = [&](const char* key, Quantity q) {
      return value(require(n, item, key), item, key, q, units_.of(q), Sign::kPositive);
    };
    auto shear_area = [&](const char* key) {  // 0 = no shear deformation
      const YAML::Node a = n[key];
      if (!a.IsDefined()) return 0.0;
      return value(a, item, key, Quantity::kArea, units_.of(Quantity::kArea), Sign::kNonNegative);
    };
    Section s;
    const YAML::Node type = n["type"];
    const std::string t = type.IsDefined() ? text(type, item, "type") : "";
    if (!type.IsDefined()) {
      check_keys(n, item, {"id", "A", "Iy", "Iz", "J", "Asy", "Asz"});
      s.A = property("A", Quantity::kArea);
      s.Iy = property("Iy", Quantity::kInertia);
      s.Iz = property("Iz", Quantity::kInertia);
      s.J = property("J", Quantity::kInertia);
      s.Asy = shear_area("Asy");
      s.Asz = shear_area("Asz");
      if (s.Asy > 0 || s.Asz > 0) sections_with_shear_areas_.insert(s_.sections().size());
    } else {
      if (t == "circle") check_keys(n, item, {"id", "type", "d"});
      if (t == "tube") check_keys(n, item, {"id", "type", "d", "t"});
      if (t == "rectangle") check_keys(n, item, {"id", "type", "b", "h"});
      if (t == "hollow_rectangle") check_keys(n, item, {"id", "type", "b", "h", "t"});
      s = shape_section(n, item, type, units_, ", or omit type and give A, Iy, Iz, J");
    }
    s.id = id;
    s_.add_section(s);
  }

  void parse_beam(const YAML::Node& n, int i) {
    const std::string id = entry_id(n, "beam", i, beam_ids_);
    const std::string item = fmt::format("beam '{}'", id);
    check_keys(n, item, {"id", "nodes", "material", "section", "orientation", "roll", "theory", "releases"});
    msa::Beam b;
    b.id = id;
    b.source = source(n);
    std::tie(b.node1, b.node2) = node_pair(require(n, item, "nodes"), item);
    const YAML::Node m = require(n, item, "material"), sec = require(n, item, "section");
    const auto mat = s_.find_material(text(m, item, "material"));
    if (!mat) fail(m, item, fmt::format("unknown material '{}'; define it under materials", m.Scalar()));
    const auto sid = s_.find_section(text(sec, item, "section"));
    if (!sid) fail(sec, item, fmt::format("unknown section '{}'; define it under sections", sec.Scalar()));
    b.material = *mat;
    b.section = *sid;

    const Vec3 p1 = s_.nodes()[b.node1].position, p2 = s_.nodes()[b.node2].position;
    const double length = (p2 - p1).norm();
    if (!(length > zero_length_)) {
      fail(n["nodes"], item,
           "the beam has zero length (its nodes are at the same place); connect two distinct points or use a joint");
    }
    if (const YAML::Node o = n["orientation"]; o.IsDefined()) {
      b.orientation = direction(o, item, "orientation");
      Mat3 axes;
      if (!element_axes(p1, p2, b.orientation, axes)) {
        fail(o, item,
             "the orientation vector is zero or along the beam; give a vector in the beam's local x-y plane, not "
             "parallel to it");
      }
    }
    if (const YAML::Node r = n["roll"]; r.IsDefined()) {
      if (n["orientation"].IsDefined())
        fail(r, item, "give either 'orientation' or 'roll', not both; they set the same local axes");
      const double roll = value(r, item, "roll", Quantity::kAngle, {kDeg, "deg"});
      b.orientation = roll_orientation(p2 - p1, roll);
    }
    const YAML::Node th = n["theory"];
    b.theory = th.IsDefined() ? theory(th, item, "theory") : default_theory_;
    // Shear areas written by hand are meant to be used: an Euler-Bernoulli beam would drop them
    // without a word. (The standard shapes always carry theirs, used only by Timoshenko beams.)
    if (b.theory == BeamTheory::kEulerBernoulli && sections_with_shear_areas_.count(b.section))
      fail(th.IsDefined() ? th : sec, item,
           fmt::format("section '{}' gives shear areas Asy/Asz, which Euler-Bernoulli beams ignore; write theory: "
                       "timoshenko on this beam (or beam_theory: timoshenko at the top of the file), or remove "
                       "Asy/Asz from the section",
                       s_.sections()[b.section].id));
    if (const YAML::Node r = n["releases"]; r.IsDefined()) {
      check_map(r, item + " releases", {"end1", "end2"});
      for (int end = 0; end < 2; ++end) {
        const YAML::Node list = r[end == 0 ? "end1" : "end2"];
        if (!list.IsDefined()) continue;
        const msa::DofMask mask = dof_mask(list, item + " releases");
        for (int d = 0; d < kDofsPerNode; ++d)
          b.releases[static_cast<std::size_t>(6 * end + d)] = mask[static_cast<std::size_t>(d)];
      }
      // Released dofs that leave the element itself free (torsion at both ends, ...) cannot be
      // condensed out: report it here, where the line is known.
      const Mat12 k = beam_local_stiffness(s_.materials()[b.material], s_.sections()[b.section], length, b.theory);
      if (const auto c = condense_releases(k, b.releases); !c.ok()) {
        fail(r, item, fmt::format("{}; keep each dof fixed at one end at least", c.status().message()));
      }
    }
    s_.add_beam(b);
  }

  BeamTheory theory(const YAML::Node& t, const std::string& item, const char* key) {
    const std::string th = text(t, item, key);
    if (th == "euler-bernoulli") return BeamTheory::kEulerBernoulli;
    if (th == "timoshenko") return BeamTheory::kTimoshenko;
    fail(t, item, fmt::format("unknown {} '{}'; use euler-bernoulli or timoshenko", key, th));
  }

  std::pair<int, int> node_pair(const YAML::Node& v, const std::string& item) {
    if (!v.IsSequence() || v.size() != 2) fail(v, item, "'nodes' must be a list of two node ids [a, b]");
    return {node_ref(v[0], item, "nodes"), node_ref(v[1], item, "nodes")};
  }

  void parse_joint(const YAML::Node& n, int i) {
    const std::string id = entry_id(n, "joint", i, joint_ids_);
    const std::string item = fmt::format("joint '{}'", id);
    check_keys(n, item, {"id", "nodes", "stiffness", "frame"});
    msa::Joint j;
    j.id = id;
    j.source = source(n);
    std::tie(j.node1, j.node2) = node_pair(require(n, item, "nodes"), item);
    const YAML::Node k = require(n, item, "stiffness");
    // Six values in the joint frame: N/m along x, y, z, then N m/rad about them (file units).
    auto component = [&](const YAML::Node& v, int d) {
      if (v.IsScalar() && v.Scalar() == "rigid") return msa::kRigid;
      // 0 = a free dof; rigid = constrained.
      const Quantity q = d < 3 ? Quantity::kTranslationalStiffness : Quantity::kRotationalStiffness;
      return value(v, item, fmt::format("stiffness {}", dof_name(d)), q, units_.of(q), Sign::kNonNegative);
    };
    if (k.IsSequence() && k.size() == 6) {
      for (int d = 0; d < kDofsPerNode; ++d) j.stiffness[d] = component(k[d], d);
    } else if (k.IsMap()) {
      check_keys(k, item + " stiffness", {"ux", "uy", "uz", "rx", "ry", "rz"});
      for (int d = 0; d < kDofsPerNode; ++d)
        j.stiffness[d] = component(require(k, item + " stiffness", dof_name(d)), d);
    } else {
      fail(k, item,
           "'stiffness' must be a list of six values [ux, uy, uz, rx, ry, rz] or a map with all six; a value is a "
           "number, 0 or rigid");
    }
    if (const YAML::Node f = n["frame"]; f.IsDefined()) j.frame = frame(f, item);
    s_.add_joint(j);
  }

  void parse_rigid_link(const YAML::Node& n, int i) {
    const std::string id = entry_id(n, "rigid link", i, link_ids_);
    const std::string item = fmt::format("rigid link '{}'", id);
    check_keys(n, item, {"id", "master", "slave", "dofs", "frame"});
    msa::RigidLink r;
    r.id = id;
    r.source = source(n);
    r.master = node_ref(require(n, item, "master"), item, "master");
    r.slave = node_ref(require(n, item, "slave"), item, "slave");
    if (r.master == r.slave) fail(n["slave"], item, "master and slave are the same node; link two different nodes");
    if (const YAML::Node d = n["dofs"]; d.IsDefined()) r.mask = dof_mask(d, item);
    if (const YAML::Node f = n["frame"]; f.IsDefined()) r.frame = frame(f, item);
    s_.add_rigid_link(r);
  }

  void parse_support(const YAML::Node& n, int i) {
    msa::Support sup;
    const std::string item = node_entry(n, "support", i, {"node", "fixed", "frame"}, sup);
    sup.fixed = dof_mask(require(n, item, "fixed"), item);
    if (const YAML::Node f = n["frame"]; f.IsDefined()) sup.frame = frame(f, item);
    s_.add_support(sup);
  }

  void parse_mass(const YAML::Node& n, int i) {
    msa::NodalMass m;
    const std::string item = node_entry(n, "mass", i, {"node", "mass", "inertia"}, m);
    const YAML::Node mass = n["mass"], inertia = n["inertia"];
    if (!mass.IsDefined() && !inertia.IsDefined())
      fail(n, item, "a nodal mass needs 'mass: M' and/or 'inertia: [Ixx, Iyy, Izz]'");
    if (mass.IsDefined())
      m.mass = value(mass, item, "mass", Quantity::kMass, units_.of(Quantity::kMass), Sign::kNonNegative);
    if (inertia.IsDefined()) {
      m.inertia = vec3(inertia, item, "inertia", Quantity::kMassInertia, units_.of(Quantity::kMassInertia));
      if (m.inertia.minCoeff() < 0.0) fail(inertia, item, "a rotary inertia must not be negative");
    }
    s_.add_mass(m);
  }

  void parse_load_case(const YAML::Node& n, int i) {
    const std::string fallback = fmt::format("load case #{}", i + 1);
    check_map(n, fallback, {"name", "loads", "prescribed", "gravity", "member_loads"});
    msa::LoadCase lc;
    lc.source = source(n);
    lc.name = text(require(n, fallback, "name"), fallback, "name");
    const std::string item = fmt::format("load case '{}'", lc.name);
    if (!case_names_.insert(lc.name).second)
      fail(n["name"], item, "this name is already used; give each load case a unique name");
    for_each(n, "loads", false, [&](const YAML::Node& l, int) {
      check_map(l, item + " load", {"node", "force", "moment"});
      msa::NodalLoad load;
      load.source = source(l);
      load.node = node_ref(require(l, item, "node"), item, "node");
      const YAML::Node f = l["force"], m = l["moment"];
      if (!f.IsDefined() && !m.IsDefined())
        fail(l, item, "a load needs 'force: [Fx, Fy, Fz]' and/or 'moment: [Mx, My, Mz]'");
      if (f.IsDefined()) load.wrench.head<3>() = vec3(f, item, "force", Quantity::kForce, units_.of(Quantity::kForce));
      if (m.IsDefined())
        load.wrench.tail<3>() = vec3(m, item, "moment", Quantity::kMoment, units_.of(Quantity::kMoment));
      lc.loads.push_back(load);
    });
    for_each(n, "prescribed", false, [&](const YAML::Node& p, int) {
      check_map(p, item + " prescribed", {"node", "dof", "value"});
      msa::PrescribedDisplacement pd;
      pd.source = source(p);
      pd.node = node_ref(require(p, item, "node"), item, "node");
      pd.dof = dof(require(p, item, "dof"), item);
      // Translations in the file's length unit, rotations in rad.
      const Quantity q = pd.dof < 3 ? Quantity::kLength : Quantity::kAngle;
      pd.value = value(require(p, item, "value"), item, "value", q, units_.of(q));
      for (const msa::PrescribedDisplacement& other : lc.prescribed)
        if (other.node == pd.node && other.dof == pd.dof)
          fail(p, item,
               fmt::format("dof {} of node '{}' is already prescribed (at {}); give one value per dof",
                           dof_name(pd.dof), s_.nodes()[pd.node].id, other.source));
      bool supported = false;
      for (const auto& sup : s_.supports())
        supported = supported || (sup.node == pd.node && sup.fixed[static_cast<std::size_t>(pd.dof)]);
      if (!supported) {
        fail(p, item,
             fmt::format("dof {} of node '{}' is not fixed by a support; a prescribed displacement needs a support "
                         "that fixes it",
                         dof_name(pd.dof), s_.nodes()[pd.node].id));
      }
      lc.prescribed.push_back(pd);
    });
    if (const YAML::Node g = n["gravity"]; g.IsDefined())
      lc.gravity = vec3(g, item, "gravity", Quantity::kAcceleration, units_.of(Quantity::kAcceleration));
    for_each(n, "member_loads", false,
             [&](const YAML::Node& l, int) { lc.member_loads.push_back(member_load(l, item)); });
    s_.add_load_case(lc);
  }

  msa::MemberLoad member_load(const YAML::Node& l, const std::string& case_item) {
    const std::string fallback = case_item + " member load";
    if (!l.IsMap()) fail(l, fallback, "expected a map such as {beam: ID, type: uniform, w: [0, 0, -1000]}");
    msa::MemberLoad ml;
    ml.source = source(l);
    const YAML::Node bn = require(l, fallback, "beam");
    const std::string bid = text(bn, fallback, "beam");
    const auto beam = s_.find_beam(bid);
    if (!beam) fail(bn, fallback, fmt::format("unknown beam '{}'; define it under beams", bid));
    ml.beam = *beam;
    const std::string item = fmt::format("{}: the member load on beam '{}'", case_item, bid);
    const YAML::Node tn = require(l, item, "type");
    const std::string type = text(tn, item, "type");
    const UnitOfInput lu = units_.of(Quantity::kLength);
    const double length = s_.beam_length(s_.beams()[ml.beam]);
    // A distance along the beam, in the file's length unit, within the span.
    auto distance = [&](const char* key) {
      const YAML::Node v = require(l, item, key);
      const double x = value(v, item, key, Quantity::kLength, lu, Sign::kNonNegative);
      if (x > length * (1.0 + 1e-12))
        fail(
            v, item,
            fmt::format("{} = {:g} {} lies beyond the end of the beam (length {:g} {}); give a distance from its first "
                        "node between 0 and the length",
                        key, x / lu.scale, lu.name.empty() ? "m" : lu.name, length / lu.scale,
                        lu.name.empty() ? "m" : lu.name));
      return std::min(x, length);
    };
    auto per_length = [&](const char* key) {
      return vec3(require(l, item, key), item, key, Quantity::kForcePerLength, units_.of(Quantity::kForcePerLength));
    };
    auto axes = [&]() {
      const YAML::Node a = l["axes"];
      if (!a.IsDefined()) return false;
      const std::string ax = text(a, item, "axes");
      if (ax != "local" && ax != "global") fail(a, item, fmt::format("unknown axes '{}'; use local or global", ax));
      return ax == "global";
    };
    if (type == "uniform") {
      check_keys(l, item, {"beam", "type", "axes", "w"});
      ml.type = msa::MemberLoadType::kUniform;
      ml.global_axes = axes();
      ml.w1 = per_length("w");
    } else if (type == "trapezoidal") {
      check_keys(l, item, {"beam", "type", "axes", "a", "b", "w1", "w2"});
      ml.type = msa::MemberLoadType::kTrapezoidal;
      ml.global_axes = axes();
      ml.a = distance("a");
      ml.b = distance("b");
      if (!(ml.a < ml.b)) fail(l["b"], item, "the loaded stretch is empty or reversed; give a < b");
      ml.w1 = per_length("w1");
      ml.w2 = per_length("w2");
    } else if (type == "point") {
      check_keys(l, item, {"beam", "type", "axes", "a", "force", "moment"});
      ml.type = msa::MemberLoadType::kPoint;
      ml.global_axes = axes();
      ml.a = distance("a");
      const YAML::Node f = l["force"], m = l["moment"];
      if (!f.IsDefined() && !m.IsDefined())
        fail(l, item, "a point load needs 'force: [Fx, Fy, Fz]' and/or 'moment: [Mx, My, Mz]'");
      if (f.IsDefined()) ml.force = vec3(f, item, "force", Quantity::kForce, units_.of(Quantity::kForce));
      if (m.IsDefined()) ml.moment = vec3(m, item, "moment", Quantity::kMoment, units_.of(Quantity::kMoment));
    } else if (type == "temperature") {
      check_keys(l, item, {"beam", "type", "alpha", "hy", "hz", "dT", "dTy", "dTz"});
      ml.type = msa::MemberLoadType::kTemperature;
      ThermalLoad& th = ml.thermal;
      th.alpha = value(require(l, item, "alpha"), item, "alpha", Quantity::kThermalExpansion, {}, Sign::kPositive);
      auto temperature = [&](const char* key) {
        const YAML::Node v = l[key];
        return v.IsDefined() ? value(v, item, key, Quantity::kTemperature, {}) : 0.0;
      };
      th.dT = temperature("dT");
      th.dTy = temperature("dTy");
      th.dTz = temperature("dTz");
      // A depth is required only with its gradient.
      auto depth = [&](const char* key, bool needed) {
        const YAML::Node v = needed ? require(l, item, key) : l[key];
        return v.IsDefined() ? value(v, item, key, Quantity::kLength, lu, Sign::kPositive) : 0.0;
      };
      th.hy = depth("hy", th.dTy != 0.0);
      th.hz = depth("hz", th.dTz != 0.0);
      if (th.dT == 0.0 && th.dTy == 0.0 && th.dTz == 0.0)
        fail(l, item, "a temperature load needs dT (uniform change) and/or dTy, dTz (differences across the depths)");
    } else {
      fail(tn, item,
           fmt::format("unknown member load type '{}'; use uniform, trapezoidal, point or temperature", type));
    }
    return ml;
  }

  FileUnits units_;
  double zero_length_ = 0.0;
  BeamTheory default_theory_ = BeamTheory::kEulerBernoulli;  // `beam_theory:`
  std::set<std::size_t> sections_with_shear_areas_;          // sections that give Asy/Asz by hand
  msa::Structure s_;
  std::unordered_map<std::string, int> node_index_;  // a hash map: large frames reference nodes often
  std::set<std::string> node_ids_, material_ids_, section_ids_, beam_ids_, joint_ids_, link_ids_, case_names_;
};

}  // namespace

StatusOr<msa::Structure> read_structure_yaml_string(const std::string& text, const std::string& display_name) {
  StatusOr<msa::Structure> s =
      parse_yaml_text<msa::Structure>(text, display_name, "docs/structure-format.md",
                                      [&](const YAML::Node& root) { return Parser(display_name).parse(root); });
  if (!s.ok()) return s;
  // Its messages start with the item's "FILE:LINE" (or the file name for the whole structure).
  if (const Status st = s->validate(); !st.ok()) return st;
  return s;
}

StatusOr<msa::Structure> read_structure_yaml(const std::string& path) {
  StatusOr<std::string> text = read_text_file(path, "structure file");
  if (!text.ok()) return text.status();
  return read_structure_yaml_string(*text, path);
}

}  // namespace kinestat::io
