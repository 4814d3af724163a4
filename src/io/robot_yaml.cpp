// Robot description files (docs/robots.md): YAML through YamlFields, numbers through muParser.
#include "kinestat/io/robot_yaml.hpp"

#include <fmt/format.h>
#include <muParser.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>

#include "io/roll_orientation.hpp"
#include "io/yaml_fields.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/vjm/link_spring.hpp"

namespace kinestat::io {
namespace {

using namespace kinestat::mechanisms;
constexpr const char* kDoc = "docs/robots.md";
using units::kDeg;

class RobotReader : public YamlFields {
 public:
  RobotReader(const std::string& path, const ParamOverrides& overrides)
      : YamlFields(path, kDoc), overrides_(overrides) {
    parser_.DefineConst("deg", kDeg);
    parser_.DefineConst("pi", M_PI);
  }

  RobotDescription parse(const YAML::Node& root) {
    check_map(root, "file",
              {"robot", "units", "params", "task", "planar", "tool", "workspace", "materials", "sections", "legs"});
    RobotDescription d;
    d.source = file();
    d.name = text(require(root, "file", "robot"), "robot", "robot");
    u_ = units(root["units"]);
    parse_params(root["params"], d);
    if (const YAML::Node p = root["planar"]; p.IsDefined()) {
      if (!p.IsScalar() || (p.Scalar() != "true" && p.Scalar() != "false")) fail(p, "planar", "write true or false");
      d.planar = p.Scalar() == "true";
    }
    const YAML::Node task = require(root, "file", "task");
    if (!task.IsSequence() || task.size() == 0) fail(task, "task", "give a list such as [x, y, z]");
    for (const YAML::Node& t : task) {
      static const std::map<std::string, TaskCoordinate> kNames = {
          {"x", TaskCoordinate::kX},   {"y", TaskCoordinate::kY},   {"z", TaskCoordinate::kZ},
          {"rx", TaskCoordinate::kRx}, {"ry", TaskCoordinate::kRy}, {"rz", TaskCoordinate::kRz}};
      const auto it = kNames.find(t.IsScalar() ? t.Scalar() : "");
      if (it == kNames.end()) fail(t, "task", "a task coordinate is one of x, y, z, rx, ry, rz");
      if (std::find(d.task.begin(), d.task.end(), it->second) != d.task.end())
        fail(t, "task", fmt::format("'{}' is named twice; keep one", t.Scalar()));
      d.task.push_back(it->second);
    }
    d.tool = point(require(root, "file", "tool"), "tool", "tool");
    if (const YAML::Node w = root["workspace"]; w.IsDefined()) {
      // {x, y, z} (lengths) or {rx, ry, rz} (deg: an orientation map at the home position).
      d.workspace_angular = w.IsMap() && w["rx"].IsDefined();
      // A map over the task's angles needs one among them, over positions a position.
      if (std::none_of(d.task.begin(), d.task.end(),
                       [&](TaskCoordinate c) { return (c >= TaskCoordinate::kRx) == d.workspace_angular; }))
        fail(w, "workspace",
             d.workspace_angular ? "the task commands no angle: give the workspace as {x, y, z} (lengths)"
                                 : "the task commands no position: give the workspace as {rx, ry, rz} (deg)");
      if (d.workspace_angular)
        check_map(w, "workspace", {"rx", "ry", "rz"});
      else
        check_map(w, "workspace", {"x", "y", "z"});
      std::array<std::pair<double, double>, 3> box;
      for (int a = 0; a < 3; ++a) {
        static constexpr const char* kKeys[2][3] = {{"x", "y", "z"}, {"rx", "ry", "rz"}};
        const char* key = kKeys[d.workspace_angular ? 1 : 0][a];
        const YAML::Node r = require(w, "workspace", key);
        if (!r.IsSequence() || r.size() != 2) fail(r, "workspace", fmt::format("'{}' must be [low, high]", key));
        box[a] = d.workspace_angular ? std::pair{degrees(r[0], "workspace", key), degrees(r[1], "workspace", key)}
                                     : std::pair{length(r[0], "workspace", key), length(r[1], "workspace", key)};
        if (!(box[a].first <= box[a].second)) fail(r, "workspace", fmt::format("'{}': low above high", key));
      }
      d.workspace = box;
    }
    if (const YAML::Node m = root["materials"]; m.IsDefined()) {
      if (!m.IsMap()) fail(m, "materials", "expected a map of named materials {E, nu}");
      check_unique_keys(m, "materials");
      for (const auto& kv : m) materials_[kv.first.Scalar()] = material(kv.second, "material " + kv.first.Scalar());
    }
    if (const YAML::Node s = root["sections"]; s.IsDefined()) {
      if (!s.IsMap()) fail(s, "sections", "expected a map of named sections {type, ...}");
      check_unique_keys(s, "sections");
      for (const auto& kv : s) sections_[kv.first.Scalar()] = section(kv.second, "section " + kv.first.Scalar());
    }
    for_each(root, "legs", true, [&](const YAML::Node& leg, int i) { parse_leg(leg, i, d); });
    return d;
  }

 private:
  // ---- numbers: a YAML number, or an expression of the parameters (muParser) ----
  double expr(const YAML::Node& v, const std::string& item, const std::string& key) {
    if (!v.IsDefined() || !v.IsScalar() || v.Scalar().empty())
      fail(v, item, fmt::format("'{}' must be a number or an expression of the parameters", key));
    try {
      parser_.SetExpr(v.Scalar());
      const double x = parser_.Eval();
      if (!std::isfinite(x)) fail(v, item, fmt::format("'{}' = {} is not finite", key, v.Scalar()));
      return x;
    } catch (const mu::Parser::exception_type& e) {
      fail(v, item,
           fmt::format("'{}': cannot evaluate '{}': {}; use numbers, the parameters ({}), deg, pi and "
                       "functions such as sqrt, sin (radians), cos, atan2",
                       key, v.Scalar(), e.GetMsg(), param_names()));
    }
  }
  double quantity(const YAML::Node& v, const std::string& item, const std::string& key, Quantity q,
                  Sign sign = Sign::kAny) {
    const double x = expr(v, item, key);
    const UnitOfInput unit = u_.of(q);
    if (Status s = check_quantity(x, q, "'" + key + "'", unit, sign); !s.ok()) fail(v, item, s.message());
    return x * unit.scale;
  }
  // An angle the file gives in degrees (turns, rolls), in rad.
  double degrees(const YAML::Node& v, const std::string& item, const std::string& key) {
    const double x = expr(v, item, key);
    if (Status s = check_quantity(x, Quantity::kAngle, "'" + key + "'", {kDeg, "deg"}); !s.ok())
      fail(v, item, s.message());
    return x * kDeg;
  }
  double length(const YAML::Node& v, const std::string& item, const std::string& key) {
    return quantity(v, item, key, Quantity::kLength);
  }
  Vec3 point(const YAML::Node& v, const std::string& item, const std::string& key) {
    if (!v.IsSequence() || v.size() != 3) fail(v, item, fmt::format("'{}' must be [x, y, z]", key));
    return {length(v[0], item, key), length(v[1], item, key), length(v[2], item, key)};
  }
  Vec3 axis(const YAML::Node& v, const std::string& item, const std::string& key) {
    if (!v.IsSequence() || v.size() != 3) fail(v, item, fmt::format("'{}' must be a direction [x, y, z]", key));
    const Vec3 a(expr(v[0], item, key), expr(v[1], item, key), expr(v[2], item, key));
    if (!(a.norm() > 0.0)) fail(v, item, fmt::format("'{}' is the zero vector; give a direction", key));
    return a.normalized();
  }
  std::string param_names() const {
    std::string s;
    for (const auto& [name, value] : params_) s += (s.empty() ? "" : ", ") + name;
    return s.empty() ? "none" : s;
  }

  void parse_params(const YAML::Node& p, RobotDescription& d) {
    for (const auto& [name, value] : overrides_) {
      bool found = false;
      if (p.IsDefined() && p.IsMap())
        for (const auto& kv : p) found |= kv.first.Scalar() == name;
      if (!found) {
        std::string names;
        if (p.IsDefined() && p.IsMap())
          for (const auto& kv : p) names += (names.empty() ? "" : ", ") + kv.first.Scalar();
        fail(p.IsDefined() ? p : YAML::Node(), "params",
             fmt::format("no parameter '{}' to set; the file's parameters are: {}", name,
                         names.empty() ? "none" : names));
      }
    }
    if (!p.IsDefined()) return;
    if (!p.IsMap()) fail(p, "params", "expected a map name: value (or expression of the parameters above it)");
    check_unique_keys(p, "params");
    for (const auto& kv : p) {
      const std::string name = kv.first.Scalar();
      if (name == "deg" || name == "pi") fail(kv.first, "params", fmt::format("'{}' is a constant; rename it", name));
      double value = 0.0;
      bool given = false;
      for (const auto& [n, v] : overrides_)
        if (n == name) value = v, given = true;
      if (!given) value = expr(kv.second, "params", name);
      auto stored = std::make_unique<double>(value);
      try {
        parser_.DefineVar(name, stored.get());
      } catch (const mu::Parser::exception_type&) {
        fail(kv.first, "params",
             fmt::format("'{}' is not a usable name: a name starts with a letter, then letters, digits or _",
                         printable(name)));
      }
      params_.emplace_back(name, std::move(stored));
      d.params.emplace_back(name, value);
    }
  }

  Material material(const YAML::Node& n, const std::string& item) {
    check_map(n, item, {"E", "nu"});
    const double nu = expr(require(n, item, "nu"), item, "nu");
    if (!(nu > -1.0 && nu < 0.5)) fail(n["nu"], item, fmt::format("'nu' = {} is not in (-1, 0.5)", nu));
    return Material::from_E_nu(item, quantity(require(n, item, "E"), item, "E", Quantity::kModulus, Sign::kPositive),
                               nu);
  }
  Section section(const YAML::Node& n, const std::string& item) {
    check_map(n, item, {"type", "d", "t", "b", "h"});
    return shape_section(n, item, require(n, item, "type"), u_, "");
  }
  template <class T>
  const T& named(const std::map<std::string, T>& all, const YAML::Node& v, const std::string& item, const char* what) {
    const std::string name = text(v, item, what);
    const auto it = all.find(name);
    if (it == all.end()) fail(v, item, fmt::format("no {} named '{}'; define it under `{}s:`", what, name, what));
    return it->second;
  }

  // A 6x6 spring: `matrix` (6 rows, file units: N/mm, N/rad, N mm/rad for mm-N-s) or `diagonal`
  // (6 numbers), with optional `axes: {x: [..], y: [..]}` (default: `default_axes`).
  // Or `fea:` (the keys of fea_request, io/yaml_fields.hpp): only what to compute
  // (mechanisms::resolve_robot_fea_springs); its stiffness is NaN until then. `fea_item` names it in
  // messages.
  RobotSpring spring(const YAML::Node& n, const std::string& item, const Mat3& default_axes,
                     const std::string& fea_item) {
    check_map(n, item, {"matrix", "diagonal", "fea", "axes"});
    RobotSpring s;
    s.label = item;
    s.axes = default_axes;
    if (const YAML::Node f = n["fea"]; f.IsDefined()) {
      if (n["matrix"].IsDefined() || n["diagonal"].IsDefined())
        fail(n, item, "give one of 'matrix', 'diagonal' or 'fea'");
      s.fea = fea_request(*this, f, fea_item, u_);
      s.fea_where = where(f, fea_item);
      // The copies of a leg pattern read the same entry: one computation for all.
      const auto key = std::pair{f.Mark().line, f.Mark().column};
      s.fea_entry = fea_entries_.emplace(key, static_cast<int>(fea_entries_.size())).first->second;
      s.stiffness = Mat6::Constant(std::numeric_limits<double>::quiet_NaN());
      if (const YAML::Node a = n["axes"]; a.IsDefined()) s.axes = frame_axes(a, item);
      return s;
    }
    Vec6 dscale;
    dscale << Vec3::Constant(1.0 / std::sqrt(u_.length)), Vec3::Constant(std::sqrt(u_.length));
    auto entry = [&](const YAML::Node& v, int i, int j, const std::string& key) {
      const Quantity q = i < 3 && j < 3     ? Quantity::kTranslationalStiffness
                         : i >= 3 && j >= 3 ? Quantity::kRotationalStiffness
                                            : Quantity::kForce;
      const double x = expr(v, item, key);
      UnitOfInput unit = u_.of(q);
      if (Status st = check_quantity(x, q, "'" + key + "'", unit); !st.ok()) fail(v, item, st.message());
      return x * u_.force * dscale(i) * dscale(j);
    };
    if (n["matrix"].IsDefined() == n["diagonal"].IsDefined())
      fail(n, item, "give one of 'matrix', 'diagonal' or 'fea'");
    s.stiffness.setZero();
    if (const YAML::Node k = n["matrix"]; k.IsDefined()) {
      if (!k.IsSequence() || k.size() != 6) fail(k, item, "'matrix' must be 6 rows of 6 numbers");
      for (int i = 0; i < 6; ++i) {
        const YAML::Node row = k[static_cast<std::size_t>(i)];
        if (!row.IsSequence() || row.size() != 6)
          fail(row, item, fmt::format("'matrix' row {} needs 6 numbers", i + 1));
        for (int j = 0; j < 6; ++j)
          s.stiffness(i, j) =
              entry(row[static_cast<std::size_t>(j)], i, j, fmt::format("matrix ({}, {})", i + 1, j + 1));
      }
    } else {
      const YAML::Node g = n["diagonal"];
      if (!g.IsSequence() || g.size() != 6) fail(g, item, "'diagonal' must be 6 numbers");
      for (int i = 0; i < 6; ++i) s.stiffness(i, i) = entry(g[static_cast<std::size_t>(i)], i, i, "diagonal");
    }
    if (const YAML::Node a = n["axes"]; a.IsDefined()) s.axes = frame_axes(a, item);
    return s;
  }
  Mat3 frame_axes(const YAML::Node& a, const std::string& item) {
    check_map(a, item + " axes", {"x", "y"});
    const Vec3 x = axis(require(a, item + " axes", "x"), item, "axes x");
    Vec3 y = axis(require(a, item + " axes", "y"), item, "axes y");
    y -= y.dot(x) * x;
    if (y.norm() < 1e-6) fail(a, item, "axes x and y are parallel");
    Mat3 R;
    R << x, y.normalized(), x.cross(y.normalized());
    return R;
  }

  // Local axes of a beam from `from` to `to` (x along it, y by Frame3DD's convention rolled by `roll`).
  static Mat3 beam_axes(const Vec3& dir, double roll) {
    const Vec3 x = dir.normalized();
    Vec3 y = roll_orientation(dir, roll);
    y = (y - y.dot(x) * x).normalized();
    Mat3 R;
    R << x, y, x.cross(y);
    return R;
  }

  // A leg pattern's copy is the first leg turned: its link axes too, not the convention's axes of the
  // turned direction `dir`, which differ about x unless the turn is about z (the Orthoglide's about
  // (1, 1, 1)). The VJM's loaded mode sees that roll even for a symmetric section (its springs'
  // rotation coordinates are elementary rotations about their axes: second order).
  static Mat3 copy_axes(const Mat3& turn, const Vec3& dir, double roll) {
    return turn * beam_axes(turn.transpose() * dir, roll);
  }

  BeamTheory beam_theory(const YAML::Node& b, const std::string& label) {
    const YAML::Node t = b["theory"];
    if (!t.IsDefined()) return BeamTheory::kEulerBernoulli;
    const std::string name = text(t, label, "theory");
    if (name == "timoshenko") return BeamTheory::kTimoshenko;
    if (name != "euler-bernoulli") fail(t, label, "theory is euler-bernoulli (default) or timoshenko");
    return BeamTheory::kEulerBernoulli;
  }

  RobotLink link(const YAML::Node& n, const std::string& label, const Vec3& from, const Mat3& turn) {
    check_map(n, label, {"to", "length", "beam", "spring"});
    RobotLink l;
    l.label = fmt::format("{} ({})", label, source(n));
    l.to = turn * point(require(n, label, "to"), label, "to");
    const Vec3 dir = l.to - from;
    if (const YAML::Node len = n["length"]; len.IsDefined()) {
      const double L = quantity(len, label, "length", Quantity::kLength, Sign::kPositive);
      if (std::abs(dir.norm() - L) > 1e-9 * std::max(L, 1e-3))
        fail(len, label,
             fmt::format("{:.6g} {} between its ends in the drawing, `length` says {:.6g} {}: the leg does not close "
                         "at home; move `to` or the joints' points",
                         dir.norm() / u_.length, u_.length_name, L / u_.length, u_.length_name));
    }
    if (n["beam"].IsDefined() && n["spring"].IsDefined()) fail(n, label, "give 'beam' or 'spring', not both");
    if (const YAML::Node b = n["beam"]; b.IsDefined()) {
      check_map(b, label + " beam", {"material", "section", "theory", "roll", "length", "x", "count"});
      const Material m = named(materials_, require(b, label, "material"), label, "material");
      const Section s = named(sections_, require(b, label, "section"), label, "section");
      const BeamTheory theory = beam_theory(b, label);
      // `x` and `length`: an equivalent cantilever off the drawing (e.g. a foot whose compliance
      // stands for a carriage and its guide), at the link's end.
      const Vec3 x = b["x"].IsDefined() ? Vec3(turn * axis(b["x"], label, "x")) : dir;
      const double L = b["length"].IsDefined()
                           ? quantity(b["length"], label, "beam length", Quantity::kLength, Sign::kPositive)
                           : dir.norm();
      if (!(x.norm() > 0.0) || !(L > 0.0))
        fail(b, label, "the link has no length in the drawing; give the beam's `x` direction and `length`");
      const double roll = b["roll"].IsDefined() ? degrees(b["roll"], label, "roll") : 0.0;
      // `count`: identical beams side by side (a parallelogram's bars as one leg): every section
      // property times it, which multiplies the cantilever's stiffness (linear in A, I, J, As).
      Section bars = s;
      if (b["count"].IsDefined()) {
        const double count = expr(b["count"], label, "count");
        if (!(count >= 1 && count == std::floor(count))) fail(b["count"], label, "'count' is a whole number >= 1");
        for (double* p : {&bars.A, &bars.Asy, &bars.Asz, &bars.Iy, &bars.Iz, &bars.J, &bars.Ip}) *p *= count;
      }
      RobotSpring cantilever;
      cantilever.label = l.label;
      cantilever.stiffness = vjm::cantilever_spring(m, bars, L, theory);
      cantilever.axes = copy_axes(turn, x, roll);
      l.spring = cantilever;
      l.beam = RobotBeam{m, bars, L, theory};
    } else if (const YAML::Node sp = n["spring"]; sp.IsDefined()) {
      const Vec3 x = dir.norm() > 0.0 ? dir : Vec3::UnitX();
      RobotSpring s = spring(sp, l.label, copy_axes(turn, x, 0.0), label + " spring fea");
      if (sp["axes"].IsDefined()) s.axes = turn * s.axes;
      l.spring = s;
    }
    return l;
  }

  RobotJoint joint(const YAML::Node& n, const std::string& kind, const std::string& label, const Mat3& turn) {
    static const std::map<std::string, RobotJointType> kTypes = {
        {"revolute", RobotJointType::kRevolute},       {"prismatic", RobotJointType::kPrismatic},
        {"universal", RobotJointType::kUniversal},     {"spherical", RobotJointType::kSpherical},
        {"cylindrical", RobotJointType::kCylindrical}, {"parallelogram", RobotJointType::kParallelogram}};
    RobotJoint j;
    j.type = kTypes.at(kind);
    j.label = fmt::format("{} ({}, {})", label, kind, source(n));
    check_map(n, label, {"at", "axis", "axes", "to", "actuated", "stiffness", "spring", "limits", "bars"});
    j.at = turn * point(require(n, label, "at"), label, "at");
    const int naxes = j.type == RobotJointType::kSpherical ? 3 : j.type == RobotJointType::kUniversal ? 2 : 1;
    if (naxes == 1) {
      j.axes[0] = turn * axis(require(n, label, "axis"), label, "axis");
      if (n["axes"].IsDefined()) fail(n["axes"], label, "a one-axis joint takes 'axis'");
    } else if (const YAML::Node a = n["axes"]; a.IsDefined()) {
      if (!a.IsSequence() || static_cast<int>(a.size()) != naxes)
        fail(a, label, fmt::format("'axes' must list {} directions", naxes));
      for (int i = 0; i < naxes; ++i) j.axes[i] = turn * axis(a[static_cast<std::size_t>(i)], label, "axes");
    } else if (j.type == RobotJointType::kUniversal) {
      fail(n, label, "a universal joint needs 'axes: [[..], [..]]' (the first turns the second)");
    } else {
      for (int i = 0; i < 3; ++i) j.axes[i] = turn * Vec3::Unit(i);  // spherical: x, y, z by default
    }
    if (j.type == RobotJointType::kParallelogram)
      j.to = turn * point(require(n, label, "to"), label, "to");
    else if (n["to"].IsDefined())
      fail(n["to"], label, "'to' belongs to a parallelogram");
    if (const YAML::Node b = n["bars"]; b.IsDefined()) {
      // Two bars from `at` to `to`, `width` apart, pinned about the axis at both plates.
      if (j.type != RobotJointType::kParallelogram) fail(b, label, "'bars' belong to a parallelogram");
      const std::string it = label + " bars";
      check_map(b, it, {"material", "section", "theory", "width"});
      RobotParallelogramBars bars;
      bars.beam = RobotBeam{named(materials_, require(b, it, "material"), it, "material"),
                            named(sections_, require(b, it, "section"), it, "section"), (j.to - j.at).norm(),
                            beam_theory(b, it)};
      bars.width = quantity(require(b, it, "width"), it, "width", Quantity::kLength, Sign::kPositive);
      if (!(bars.beam.length > 0.0)) fail(b, it, "the bars have no length: `to` is at `at`");
      bars.stiffness =
          vjm::cantilever_spring(bars.beam.material, bars.beam.section, bars.beam.length, bars.beam.theory);
      j.bars = bars;
    }
    if (const YAML::Node a = n["actuated"]; a.IsDefined()) {
      if (!a.IsScalar() || (a.Scalar() != "true" && a.Scalar() != "false")) fail(a, label, "actuated: true or false");
      j.actuated = a.Scalar() == "true";
    }
    const bool prismatic_first = j.type == RobotJointType::kPrismatic;
    if (const YAML::Node k = n["stiffness"]; k.IsDefined()) {
      if (!j.actuated)
        fail(k, label, "'stiffness' is the actuator's; a passive joint's compliance is a 'spring' (6x6)");
      j.actuator_stiffness = quantity(
          k, label, "stiffness", prismatic_first ? Quantity::kTranslationalStiffness : Quantity::kRotationalStiffness,
          Sign::kPositive);
    }
    if (const YAML::Node s = n["spring"]; s.IsDefined()) {
      RobotSpring sp = spring(s, j.label, turn, label + " spring fea");
      if (s["axes"].IsDefined()) sp.axes = turn * sp.axes;
      j.spring = sp;
    }
    if (const YAML::Node lim = n["limits"]; lim.IsDefined()) {
      const int nc = coordinate_count(j.type);
      if (!lim.IsSequence() || static_cast<int>(lim.size()) != nc)
        fail(lim, label, fmt::format("'limits' lists [low, high] for each of its {} coordinates", nc));
      for (int c = 0; c < nc; ++c) {
        const YAML::Node r = lim[static_cast<std::size_t>(c)];
        if (!r.IsSequence() || r.size() != 2) fail(r, label, "each limit is [low, high]");
        const bool translation = mechanisms::coordinate_is_length(j.type, c);
        const auto value = [&](const YAML::Node& v) {
          return translation ? length(v, label, "limits") : degrees(v, label, "limits");
        };
        j.limits.emplace_back(value(r[0]), value(r[1]));
        if (!(j.limits.back().first <= j.limits.back().second))
          fail(r, label, "a limit is [low, high]: this one's low is above its high");
      }
    }
    return j;
  }

  void parse_leg(const YAML::Node& n, int index, RobotDescription& d) {
    const std::string item = fmt::format("legs[{}]", index);
    check_map(n, item, {"name", "copies", "turn", "turn_axis", "chain"});
    const bool named_leg = n["name"].IsDefined();
    const std::string name = named_leg ? text(n["name"], item, "name") : "leg";
    // Messages name legs by these names (with a copy's number): two alike would not tell which.
    if (named_leg && !leg_names_.insert(name).second)
      fail(n["name"], item, fmt::format("a leg is already named '{}'; give each its own name", name));
    int copies = 1;
    if (const YAML::Node c = n["copies"]; c.IsDefined()) {
      const double x = expr(c, item, "copies");
      if (!(x >= 1 && x <= 64 && x == std::floor(x))) fail(c, item, "'copies' is a whole number from 1 to 64");
      copies = static_cast<int>(x);
    }
    double turn = 0.0;
    if (const YAML::Node t = n["turn"]; t.IsDefined())
      turn = degrees(t, item, "turn");
    else if (copies > 1)
      turn = 2.0 * M_PI / copies;
    const Vec3 turn_axis = n["turn_axis"].IsDefined() ? axis(n["turn_axis"], item, "turn_axis") : Vec3::UnitZ();
    const YAML::Node chain = require(n, item, "chain");
    if (!chain.IsSequence() || chain.size() == 0) fail(chain, item, "'chain' lists the leg's joints and links");
    for (int k = 0; k < copies; ++k) {
      RobotLeg leg;
      // Unnamed legs are numbered through the file, copies of a named one by copy.
      leg.name = !named_leg   ? fmt::format("leg {}", d.legs.size() + 1)
                 : copies > 1 ? fmt::format("{} {}", name, k + 1)
                              : name;
      const Mat3 R = Eigen::AngleAxisd(k * turn, turn_axis).toRotationMatrix();
      Vec3 at = Vec3::Zero();
      int joints = 0, links = 0;
      for (const YAML::Node& e : chain) {
        if (!e.IsMap() || e.size() != 1)
          fail(e, item,
               "each chain entry is one of revolute, prismatic, universal, spherical, cylindrical, "
               "parallelogram or link, with its fields in braces");
        const std::string kind = e.begin()->first.Scalar();
        const YAML::Node body = e.begin()->second;
        if (kind == "link") {
          RobotLink l = link(body, fmt::format("{} link {}", leg.name, ++links), at, R);
          at = l.to;
          leg.items.emplace_back(std::move(l));
        } else if (kind == "revolute" || kind == "prismatic" || kind == "universal" || kind == "spherical" ||
                   kind == "cylindrical" || kind == "parallelogram") {
          RobotJoint j = joint(body, kind, fmt::format("{} joint {}", leg.name, ++joints), R);
          at = j.type == RobotJointType::kParallelogram ? j.to : j.at;
          leg.items.emplace_back(std::move(j));
        } else {
          fail(e, item,
               fmt::format("unknown chain entry '{}'; use revolute, prismatic, universal, spherical, "
                           "cylindrical, parallelogram or link",
                           kind));
        }
      }
      d.legs.push_back(std::move(leg));
    }
  }

  const ParamOverrides& overrides_;
  FileUnits u_;
  mu::Parser parser_;
  std::vector<std::pair<std::string, std::unique_ptr<double>>> params_;  // muParser keeps their addresses
  std::set<std::string> leg_names_;
  std::map<std::string, Material> materials_;
  std::map<std::string, Section> sections_;
  std::map<std::pair<int, int>, int> fea_entries_;  // `fea:` springs by their line and column
};

}  // namespace

StatusOr<RobotDescription> read_robot_description_string(const std::string& text, const std::string& display_name,
                                                         const ParamOverrides& overrides) {
  RobotReader reader(display_name, overrides);
  return parse_yaml_text<RobotDescription>(text, display_name, kDoc,
                                           [&](const YAML::Node& root) { return reader.parse(root); });
}

StatusOr<RobotDescription> read_robot_description(const std::string& path, const ParamOverrides& overrides) {
  StatusOr<std::string> text = read_text_file(path, "robot file");
  if (!text.ok()) return text.status();
  return read_robot_description_string(*text, path, overrides);
}

StatusOr<RobotModel> read_robot_model(const std::string& path, const ParamOverrides& overrides) {
  StatusOr<RobotDescription> d = read_robot_description(path, overrides);
  if (!d.ok()) return d.status();
  return make_robot_model(std::move(*d));
}

StatusOr<bool> is_robot_file(const std::string& path) {
  StatusOr<std::string> text = read_text_file(path, "model file");
  if (!text.ok()) return text.status();
  return parse_yaml_text<bool>(*text, path, kDoc, [](const YAML::Node& root) {
    // `legs:` without `robot:` is a robot file that lacks its name (the reader says so).
    return root.IsMap() && (root["robot"].IsDefined() || root["legs"].IsDefined());
  });
}

StatusOr<RobotParams> read_robot_params(const std::string& path) {
  StatusOr<RobotDescription> d = read_robot_description(path);
  if (!d.ok()) return d.status();
  StatusOr<std::string> text = read_text_file(path, "robot file");
  if (!text.ok()) return text.status();
  return parse_yaml_text<RobotParams>(*text, path, kDoc, [&](const YAML::Node& root) {
    RobotParams p;
    const FileUnits u = YamlFields(path, kDoc).units(root["units"]);
    p.length_unit = u.length_name;
    p.force_unit = u.force_name;
    p.length_scale = u.length;
    p.values = d->params;
    return p;
  });
}

}  // namespace kinestat::io
