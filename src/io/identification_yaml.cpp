#include "kinestat/io/identification_yaml.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>

#include "io/yaml_fields.hpp"

namespace kinestat::io {
namespace {

using mechanisms::OrthoglideInput;

constexpr const char* kDoc = "docs/vjm.md";
constexpr OrthoglideInput kAllInputs[] = {OrthoglideInput::kActuatorStiffness, OrthoglideInput::kBarScale,
                                          OrthoglideInput::kParallelogramWidth, OrthoglideInput::kPlatformOffset,
                                          OrthoglideInput::kFootLength};

class TargetsParser : public YamlFields {
 public:
  explicit TargetsParser(std::string file) : YamlFields(std::move(file), kDoc) {}

  IdentificationTargets parse(const YAML::Node& root) {
    if (!root.IsDefined() || root.IsNull())
      fail(root, "file", "the file is empty; give 'inputs:' and 'targets:' (see docs/vjm.md)");
    check_map(root, "file", {"units", "inputs", "targets"});
    const FileUnits u = units(root["units"]);
    IdentificationTargets t;
    for_each(root, "inputs", true, [&](const YAML::Node& n, int) {
      const std::string name = text(n, "inputs", "inputs");
      for (OrthoglideInput i : kAllInputs) {
        if (name != input_key(i)) continue;
        for (OrthoglideInput seen : t.inputs)
          if (seen == i) fail(n, "inputs", fmt::format("'{}' is listed twice; list each input once", name));
        t.inputs.push_back(i);
        return;
      }
      fail(n, "inputs",
           fmt::format("unknown input '{}'; write actuator_stiffness, bar_scale, parallelogram_width, "
                       "platform_offset or foot_length",
                       name));
    });
    for_each(root, "targets", true, [&](const YAML::Node& n, int index) {
      const std::string item = fmt::format("target #{}", index + 1);
      check_map(n, item, {"label", "architecture", "point", "row", "col", "value"});
      mechanisms::ComplianceTarget c;
      c.source = source(n);
      c.label = n["label"].IsDefined() ? text(n["label"], item, "label") : item;
      const YAML::Node a = require(n, item, "architecture");
      const auto arch = mechanisms::architecture_from_name(text(a, item, "architecture"));
      if (!arch) fail(a, item, fmt::format("unknown architecture '{}'; write 3-PUU or 3-PRPaR", a.Scalar()));
      c.architecture = *arch;
      c.point = vec3(require(n, item, "point"), item, "point", Quantity::kLength, u.of(Quantity::kLength));
      c.row = dof(n, item, "row");
      c.col = dof(n, item, "col");
      // Translation rows/columns carry length / force, rotation ones 1 / (force length) together.
      const int rotations = (c.row >= 3) + (c.col >= 3);
      const bool si = u.length == 1.0;
      const UnitOfInput unit = rotations == 0 ? UnitOfInput{u.length / u.force, si ? "m/N" : "mm/N"}
                               : rotations == 1
                                   ? UnitOfInput{1.0 / u.force, "1/N"}
                                   : UnitOfInput{1.0 / (u.force * u.length), si ? "rad/(N m)" : "rad/(N mm)"};
      // A diagonal term of a compliance is positive (C is positive definite); another one is non-zero.
      const YAML::Node v = require(n, item, "value");
      c.value = value(v, item, "value", Quantity::kCompliance, unit, c.row == c.col ? Sign::kPositive : Sign::kAny);
      if (c.value == 0.0) fail(v, item, "'value' is zero; give a measured, non-zero compliance");
      t.targets.push_back(std::move(c));
    });
    if (t.targets.size() < t.inputs.size())
      fail(root["targets"], "targets",
           fmt::format("{} target(s) for {} input(s); give at least as many targets as inputs", t.targets.size(),
                       t.inputs.size()));
    return t;
  }

 private:
  int dof(const YAML::Node& n, const std::string& item, const char* key) const {
    const double v = number(require(n, item, key), item, key);
    if (!(v >= 0 && v <= 5 && v == std::floor(v)))
      fail(n[key], item, fmt::format("'{}' = {} is not a dof index; give 0-5 (dx dy dz rx ry rz)", key, v));
    return static_cast<int>(v);
  }
};

}  // namespace

const char* input_key(OrthoglideInput input) {
  switch (input) {
    case OrthoglideInput::kActuatorStiffness:
      return "actuator_stiffness";
    case OrthoglideInput::kBarScale:
      return "bar_scale";
    case OrthoglideInput::kParallelogramWidth:
      return "parallelogram_width";
    case OrthoglideInput::kPlatformOffset:
      return "platform_offset";
    case OrthoglideInput::kFootLength:
      return "foot_length";
  }
  return "?";
}

StatusOr<IdentificationTargets> read_identification_targets_yaml_string(const std::string& text,
                                                                        const std::string& display_name) {
  return parse_yaml_text<IdentificationTargets>(
      text, display_name, kDoc, [&](const YAML::Node& root) { return TargetsParser(display_name).parse(root); });
}

StatusOr<IdentificationTargets> read_identification_targets_yaml(const std::string& path) {
  StatusOr<std::string> text = read_text_file(path, "identification targets file");
  if (!text.ok()) return text.status();
  return read_identification_targets_yaml_string(*text, path);
}

}  // namespace kinestat::io
