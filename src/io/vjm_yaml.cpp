#include "kinestat/io/vjm_yaml.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "io/yaml_fields.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/vjm/link_spring.hpp"
#include "kinestat/vjm/platform.hpp"

namespace kinestat::io {
namespace {

using units::kDeg;
constexpr const char* kDoc = "docs/vjm.md";
const UnitOfInput kDegrees{kDeg, "deg"};
constexpr int kNoSizeLimit = std::numeric_limits<int>::max();

class VjmParser : public YamlFields {
 public:
  explicit VjmParser(std::string file) : YamlFields(std::move(file), kDoc) {}

  VjmModel parse(const YAML::Node& root) {
    if (!root.IsDefined() || root.IsNull())
      fail(root, "file", "the file is empty; start with 'mechanism: orthoglide' or a 'chains:' list (see docs/vjm.md)");
    check_map(root, "file", {"units", "title", "mechanism", "orthoglide", "chains"});
    u_ = units(root["units"]);
    VjmModel m;
    if (const YAML::Node t = root["title"]; t.IsDefined()) m.title = text(t, "file", "title");
    if (const YAML::Node mech = root["mechanism"]; mech.IsDefined()) {
      if (text(mech, "file", "mechanism") != "orthoglide")
        fail(mech, "file",
             fmt::format("unknown mechanism '{}'; the only one is orthoglide (or omit it and give chains)",
                         mech.Scalar()));
      if (root["chains"].IsDefined())
        fail(root["chains"], "file", "an orthoglide model builds its chains; remove 'chains' or 'mechanism'");
      parse_orthoglide(require(root, "file", "orthoglide"), m);
      return m;
    }
    if (root["orthoglide"].IsDefined())
      fail(root["orthoglide"], "file", "an 'orthoglide' block needs 'mechanism: orthoglide'; add it");
    for_each(root, "chains", true,
             [&](const YAML::Node& c, int i) { m.chains.push_back(parse_chain(c, i, m.fea_springs)); });
    if (m.chains.empty()) fail(root["chains"], "chains", "the list is empty; give at least one chain");
    // No size limit here: the computations check the chains' size against their options.
    if (const Status s = vjm::validate_platform(m.chains, kNoSizeLimit); !s.ok())
      fail(root["chains"], "chains", s.message() + "; check the chains' transforms and joint values");
    // Until resolve_fea_springs computes them, FEA springs are NaN: a chain used before that fails
    // its checks instead of giving numbers.
    for (const FeaSpring& f : m.fea_springs)
      (void)m.chains[f.chain].set_spring_stiffness(f.spring, Mat6::Constant(std::numeric_limits<double>::quiet_NaN()));
    return m;
  }

 private:
  Material material(const YAML::Node& n, const std::string& item) const {
    const double nu = number(require(n, item, "nu"), item, "nu");
    if (!(nu > -1.0 && nu < 0.5))
      fail(n["nu"], item, fmt::format("'nu' = {} is not in (-1, 0.5); give Poisson's ratio", nu));
    return Material::from_E_nu(item, quantity(require(n, item, "E"), item, "E", Quantity::kModulus, Sign::kPositive),
                               nu);
  }

  Section section(const YAML::Node& n, const std::string& item) const {
    check_map(n, item + " section", {"type", "d", "t", "b", "h"});
    return shape_section(n, item + " section", require(n, item + " section", "type"), u_, "");
  }

  void parse_orthoglide(const YAML::Node& n, VjmModel& m) const {
    const std::string item = "orthoglide";
    check_map(
        n, item,
        {"architecture", "link_length", "parallelogram_width", "platform_offset", "actuator_stiffness", "bar", "foot"});
    const YAML::Node a = require(n, item, "architecture");
    const std::string arch = text(a, item, "architecture");
    const std::optional<mechanisms::OrthoglideArchitecture> known = mechanisms::architecture_from_name(arch);
    if (!known) fail(a, item, fmt::format("unknown architecture '{}'; write 3-PUU or 3-PRPaR", arch));
    m.architecture = *known;
    mechanisms::OrthoglideStiffnessModel o;
    auto length = [&](const YAML::Node& map, const std::string& it, const char* key) {
      return quantity(require(map, it, key), it, key, Quantity::kLength, Sign::kPositive);
    };
    o.link_length = length(n, item, "link_length");
    if (m.architecture == mechanisms::OrthoglideArchitecture::kPRPaR)
      o.parallelogram_width = length(n, item, "parallelogram_width");
    else if (n["parallelogram_width"].IsDefined())
      fail(n["parallelogram_width"], item, "a 3-PUU has no parallelogram; remove 'parallelogram_width'");
    if (const YAML::Node d = n["platform_offset"]; d.IsDefined()) {  // optional, default 0
      // The legs' attachment distance from the tool point.
      o.platform_offset = quantity(d, item, "platform_offset", Quantity::kLength, Sign::kNonNegative);
    }
    o.actuator_stiffness = quantity(require(n, item, "actuator_stiffness"), item, "actuator_stiffness",
                                    Quantity::kTranslationalStiffness, Sign::kPositive);
    const YAML::Node bar = require(n, item, "bar");
    check_map(bar, "orthoglide bar", {"E", "nu", "section"});
    o.bar_material = material(bar, "orthoglide bar");
    o.bar_section = section(require(bar, "orthoglide bar", "section"), "orthoglide bar");
    const YAML::Node foot = require(n, item, "foot");
    check_map(foot, "orthoglide foot", {"E", "nu", "section", "length"});
    o.foot_material = material(foot, "orthoglide foot");
    o.foot_section = section(require(foot, "orthoglide foot", "section"), "orthoglide foot");
    o.foot_length = length(foot, "orthoglide foot", "length");
    // The model's own checks, here where the block's line is known.
    if (const Status s = mechanisms::validate_stiffness_model(o); !s.ok()) fail(n, item, s.message());
    m.orthoglide = o;
  }

  vjm::JointType joint_type(const YAML::Node& n, const std::string& item) const {
    const YAML::Node t = require(n, item, "type");
    const std::string s = text(t, item, "type");
    if (s == "revolute") return vjm::JointType::kRevolute;
    if (s == "prismatic") return vjm::JointType::kPrismatic;
    fail(t, item, fmt::format("unknown joint type '{}'; write revolute or prismatic", s));
  }

  Vec3 axis(const YAML::Node& n, const std::string& item) const {
    return direction(require(n, item, "axis"), item, "axis");
  }

  // A joint coordinate: length units for prismatic, degrees for revolute.
  double coordinate(const YAML::Node& v, vjm::JointType t, const std::string& item, const std::string& key) const {
    if (t == vjm::JointType::kPrismatic) return quantity(v, item, key, Quantity::kLength);
    return value(v, item, key, Quantity::kAngle, kDegrees);
  }

  // A spring's 6x6; for `fea:` a placeholder, and *fea says what to compute.
  Mat6 spring(const YAML::Node& n, const std::string& item, std::optional<FeaSpring>* fea) const {
    check_map(n, item, {"matrix", "cantilever", "parallelogram", "fea"});
    if (n.size() != 1) fail(n, item, "give exactly one of matrix, cantilever, parallelogram, fea");
    if (const YAML::Node f = n["fea"]; f.IsDefined()) {
      const std::string it = item + " fea";
      // Convention (docs/vjm.md): the mesh's axes are the current frame's axes and the reference
      // point is the current frame's origin: the spring sits at the link's far end, after the
      // `translate` along the link, exactly like `cantilever`.
      *fea = FeaSpring{.where = where(f, it), .request = fea_request(*this, f, it, u_)};
      return Mat6::Identity();  // valid for the checks of the chain's geometry; made NaN after them
    }
    if (const YAML::Node k = n["matrix"]; k.IsDefined()) {
      if (!k.IsSequence() || k.size() != 6) fail(k, item, "'matrix' must be 6 rows of 6 numbers");
      // File units: N/mm, N/rad (= N mm/mm), N mm/rad for mm-N-s; K_SI = force D K D, D = diag(l^-1/2 I, l^1/2 I).
      Vec6 d;
      d << Vec3::Constant(1.0 / std::sqrt(u_.length)), Vec3::Constant(std::sqrt(u_.length));
      Mat6 K;
      for (int i = 0; i < 6; ++i) {
        const YAML::Node row = k[static_cast<std::size_t>(i)];
        if (!row.IsSequence() || row.size() != 6)
          fail(row, item, fmt::format("'matrix' row {} must have 6 numbers", i + 1));
        for (int j = 0; j < 6; ++j) {
          // Translation block N/m, rotation block N m/rad, coupling N (in the file's units).
          const Quantity q = i < 3 && j < 3     ? Quantity::kTranslationalStiffness
                             : i >= 3 && j >= 3 ? Quantity::kRotationalStiffness
                                                : Quantity::kForce;
          UnitOfInput unit = u_.of(q);
          unit.scale = u_.force * d(i) * d(j);
          K(i, j) =
              value(row[static_cast<std::size_t>(j)], item, fmt::format("matrix ({}, {})", i + 1, j + 1), q, unit);
        }
      }
      return K;
    }
    if (const YAML::Node c = n["cantilever"]; c.IsDefined()) {
      const std::string it = item + " cantilever";
      check_map(c, it, {"E", "nu", "section", "length", "theory", "bars"});
      BeamTheory theory = BeamTheory::kEulerBernoulli;
      if (const YAML::Node t = c["theory"]; t.IsDefined()) {
        const std::string s = text(t, it, "theory");
        if (s == "timoshenko")
          theory = BeamTheory::kTimoshenko;
        else if (s != "euler")
          fail(t, it, fmt::format("unknown theory '{}'; write euler or timoshenko", s));
      }
      // `bars`: identical bars side by side on the same axis (the paper's doubled leg section).
      double bars = 1.0;
      if (const YAML::Node b = c["bars"]; b.IsDefined())
        bars = value(b, it, "bars", Quantity::kRatio, {}, Sign::kPositive);
      return bars * vjm::cantilever_spring(
                        material(c, it), section(require(c, it, "section"), it),
                        quantity(require(c, it, "length"), it, "length", Quantity::kLength, Sign::kPositive), theory);
    }
    const YAML::Node p = n["parallelogram"];
    const std::string it = item + " parallelogram";
    check_map(p, it, {"E", "nu", "section", "length", "width", "q"});
    mechanisms::OrthoglideStiffnessModel o;
    o.bar_material = material(p, it);
    o.bar_section = section(require(p, it, "section"), it);
    o.link_length = quantity(require(p, it, "length"), it, "length", Quantity::kLength, Sign::kPositive);
    o.parallelogram_width = quantity(require(p, it, "width"), it, "width", Quantity::kLength, Sign::kPositive);
    StatusOr<Mat6> K =
        mechanisms::parallelogram_spring(o, value(require(p, it, "q"), it, "q", Quantity::kAngle, kDegrees));
    if (!K.ok()) fail(p, it, K.status().message());
    return *K;
  }

  vjm::Chain parse_chain(const YAML::Node& c, int index, std::vector<FeaSpring>& fea_springs) const {
    std::string item = fmt::format("chain #{}", index + 1);
    check_map(c, item, {"name", "elements"});
    vjm::Chain chain(c["name"].IsDefined() ? text(c["name"], item, "name") : item);
    item = fmt::format("chain '{}'", chain.name());
    std::map<std::string, int> passive_ids;
    const YAML::Node list = require(c, item, "elements");
    if (!list.IsSequence() || list.size() == 0)
      fail(list, item, "'elements' must be a non-empty list, in eq. (1)'s order");
    for (std::size_t e = 0; e < list.size(); ++e) {
      const YAML::Node el = list[e];
      const std::string it = fmt::format("{} element {}", item, e + 1);
      check_map(el, it, {"name", "rotate", "translate", "actuator", "spring", "passive", "coupled"});
      if (el.size() != (el["name"].IsDefined() ? 2u : 1u))
        fail(el, it,
             "give exactly one of rotate, translate, actuator, spring, passive, coupled (and an optional name)");
      const std::string kind =
          el.begin()->first.Scalar() == "name" ? std::next(el.begin())->first.Scalar() : el.begin()->first.Scalar();
      const std::string label =
          el["name"].IsDefined() ? text(el["name"], it, "name") : fmt::format("{} {}", kind, e + 1);
      const YAML::Node v = el[kind];
      const std::string vit = fmt::format("{} ({})", it, kind);
      if (kind == "translate") {
        chain.add_translation(vec3(v, vit, "translate", Quantity::kLength, u_.of(Quantity::kLength)), label);
      } else if (kind == "rotate") {
        check_map(v, vit, {"axis", "angle"});
        chain.add_rotation(axis(v, vit), value(require(v, vit, "angle"), vit, "angle", Quantity::kAngle, kDegrees),
                           label);
      } else if (kind == "spring") {
        std::optional<FeaSpring> fea;
        const Mat6 K = spring(v, vit, &fea);
        if (fea) {
          fea->chain = index;
          fea->spring = static_cast<int>(chain.springs().size());
          fea_springs.push_back(std::move(*fea));
        }
        chain.add_spring(K, label);
      } else if (kind == "actuator") {
        check_map(v, vit, {"type", "axis", "value", "stiffness"});
        const vjm::JointType t = joint_type(v, vit);
        const YAML::Node k = require(v, vit, "stiffness");
        const double stiff = k.IsScalar() && k.Scalar() == "locked"
                                 ? std::numeric_limits<double>::infinity()
                                 : quantity(k, vit, "stiffness",
                                            t == vjm::JointType::kPrismatic ? Quantity::kTranslationalStiffness
                                                                            : Quantity::kRotationalStiffness,
                                            Sign::kPositive);
        chain.add_actuator(t, axis(v, vit), coordinate(require(v, vit, "value"), t, vit, "value"), stiff, label);
      } else if (kind == "passive") {
        check_map(v, vit, {"id", "type", "axis", "q"});
        const vjm::JointType t = joint_type(v, vit);
        const int k = chain.add_passive(t, axis(v, vit), coordinate(require(v, vit, "q"), t, vit, "q"), label);
        if (const YAML::Node id = v["id"]; id.IsDefined() && !passive_ids.emplace(text(id, vit, "id"), k).second)
          fail(id, vit,
               fmt::format("passive id '{}' is already used in this chain; give each a unique id", id.Scalar()));
      } else {  // coupled
        check_map(v, vit, {"to", "type", "axis", "coefficient"});
        const YAML::Node to = require(v, vit, "to");
        const auto k = passive_ids.find(text(to, vit, "to"));
        if (k == passive_ids.end())
          fail(to, vit,
               fmt::format("no passive joint with id '{}' before this element; give that joint 'id: {}'", to.Scalar(),
                           to.Scalar()));
        chain.add_coupled(joint_type(v, vit), axis(v, vit), k->second,
                          value(require(v, vit, "coefficient"), vit, "coefficient", Quantity::kRatio, {}), label);
      }
    }
    if (const Status s = chain.validate(kNoSizeLimit); !s.ok()) fail(c, item, s.message());
    return chain;
  }

  // A value of quantity `q` in the file's unit of it, returned in SI.
  double quantity(const YAML::Node& v, const std::string& item, const std::string& key, Quantity q,
                  Sign sign = Sign::kAny) const {
    return value(v, item, key, q, u_.of(q), sign);
  }

  FileUnits u_;
};

}  // namespace

StatusOr<VjmModel> read_vjm_model_yaml_string(const std::string& text, const std::string& display_name) {
  return parse_yaml_text<VjmModel>(text, display_name, kDoc,
                                   [&](const YAML::Node& root) { return VjmParser(display_name).parse(root); });
}

StatusOr<VjmModel> read_vjm_model_yaml(const std::string& path) {
  StatusOr<std::string> text = read_text_file(path, "VJM model file");
  if (!text.ok()) return text.status();
  return read_vjm_model_yaml_string(*text, path);
}

Status resolve_fea_springs(VjmModel& model, const std::function<void(const std::string&)>& progress,
                           const std::function<void(const std::string&)>& warning) {
  for (FeaSpring& f : model.fea_springs) {
    if (f.resolved) continue;
    fea::LinkStiffnessRequest request = f.request;
    request.options.progress = progress;
    StatusOr<fea::LinkStiffnessRun> run = fea::compute_link_stiffness(request);
    if (!run.ok()) {
      // A mesh or region the FEA cannot use is the model file's fault; a library failure is not.
      const std::string message = f.where + ": " + run.status().message();
      return run.status().code() == StatusCode::kInternal ? Status::Internal(message) : Status::Invalid(message);
    }
    if (warning)
      for (const std::string& w : run->warnings) warning(f.where + ": " + w);
    // The stiffness is symmetric (the compliance is symmetrized; its asymmetry is round-off).
    if (Status s = model.chains[f.chain].set_spring_stiffness(f.spring, run->result.cartesian.stiffness); !s.ok())
      return s;
    f.resolved = true;
  }
  return Status::Ok();
}

StatusOr<std::vector<vjm::Chain>> vjm_model_chains(const VjmModel& model, const std::optional<Vec3>& point) {
  for (const FeaSpring& f : model.fea_springs)
    if (!f.resolved)
      return Status::Invalid(f.where + ": this spring is not computed yet; call io::resolve_fea_springs first");
  if (model.orthoglide)
    return mechanisms::orthoglide_chains(*model.orthoglide, model.architecture, point.value_or(Vec3::Zero()));
  if (point)
    return Status::Invalid(
        "a posture (--point) needs a model with 'mechanism: orthoglide'; a 'chains:' file gives its own joint values");
  return model.chains;
}

}  // namespace kinestat::io
