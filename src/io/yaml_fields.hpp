// Checked access to the fields of a YAML model file, shared by the file readers (structure_yaml,
// vjm_yaml, robot_yaml). Every check fails with one message "FILE:LINE: ITEM: what is wrong; what to do"
// (yaml-cpp's 0-based Mark() line printed 1-based; omitted when the node has no position).
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/io/file_units.hpp"

namespace kinestat::io {

// Thrown by YamlFields::fail and caught by parse_yaml_text: never crosses the io layer.
struct YamlInputError {
  std::string message;
};

// "a, b, c"
std::string join_keys(std::initializer_list<const char*> names);

class YamlFields {
 public:
  // `file` names the file in messages; `format_doc` is the page that documents the format.
  YamlFields(std::string file, std::string format_doc) : file_(std::move(file)), doc_(std::move(format_doc)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& item, const std::string& what) const;
  // "FILE:LINE" of a node (the file name alone when the node has no position): an item's source.
  std::string source(const YAML::Node& at) const;
  // "FILE:LINE: ITEM", the start of fail's message, for checks made after reading.
  std::string where(const YAML::Node& at, const std::string& item) const;

  // `node` must be a map whose keys are all in `allowed`, each once.
  void check_map(const YAML::Node& node, const std::string& item, std::initializer_list<const char*> allowed) const;
  void check_keys(const YAML::Node& map, const std::string& item, std::initializer_list<const char*> allowed) const;
  // `map`'s keys, names the file chooses (parameters, materials), each once.
  void check_unique_keys(const YAML::Node& map, const std::string& item) const;
  YAML::Node require(const YAML::Node& map, const std::string& item, const char* key) const;

  // Runs `f(entry, index)` on each entry of the list root[key] (absent is allowed unless `required`).
  template <class F>
  void for_each(const YAML::Node& root, const char* key, bool required, F f) const {
    const YAML::Node list = root[key];
    if (!list.IsDefined() || list.IsNull()) {
      if (required) fail(root, "file", "missing required key '" + std::string(key) + "'; add a list of " + key);
      return;
    }
    if (!list.IsSequence()) fail(list, key, "expected a list; write one '- ...' entry per item");
    for (std::size_t i = 0; i < list.size(); ++i) f(list[i], static_cast<int>(i));
  }

  double number(const YAML::Node& v, const std::string& item, const std::string& key) const;
  // A number written in `unit`, returned in SI, checked finite and in the range of `q` after the
  // conversion (core/input_checks.hpp); the message names the item, the key and the unit.
  double value(const YAML::Node& v, const std::string& item, const std::string& key, Quantity q,
               const UnitOfInput& unit, Sign sign = Sign::kAny) const;
  std::string text(const YAML::Node& v, const std::string& item, const std::string& key) const;
  // [x, y, z] in `unit`, returned in SI, each component checked as value() does.
  Vec3 vec3(const YAML::Node& v, const std::string& item, const std::string& key, Quantity q,
            const UnitOfInput& unit) const;
  // [x, y, z]: a direction, finite and non-zero, returned as a unit vector.
  Vec3 direction(const YAML::Node& v, const std::string& item, const std::string& key) const;
  // A standard shape `type` from the keys of `n`: circle (d), tube (d, t), rectangle (b, h),
  // hollow_rectangle (b, h, t), lengths in the file's unit; a wall must be thinner than half the outer
  // size. An unknown type fails at `type_node` naming `other_form` as the alternative.
  Section shape_section(const YAML::Node& n, const std::string& item, const YAML::Node& type_node,
                        const FileUnits& units, const std::string& other_form) const;
  // The `units:` value (absent: SI); `any_units`: also the map form {length: L, force: F}.
  FileUnits units(const YAML::Node& v, bool any_units = false) const;

  const std::string& file() const { return file_; }
  const std::string& format_doc() const { return doc_; }

 private:
  std::string file_;
  std::string doc_;
};

// A `fea:` link spring's keys (docs/vjm.md; robots' links, docs/robots.md): mesh, material or E and
// nu, clamp, reference, reference_point, unit, size, max_elements, cache. Only what to compute: the
// mesh is not read, but it must exist. Paths are relative to the file's folder; `units` are the
// file's (the mesh's unit by default, E's unit). Plain numbers (no expressions). Shared by the VJM
// and robot readers.
fea::LinkStiffnessRequest fea_request(const YamlFields& y, const YAML::Node& f, const std::string& item,
                                      const FileUnits& units);

// `text` with its control characters as \xNN: a message stays on one line.
std::string printable(const std::string& text);

// Loads `text` and runs parse(root), turning YamlInputError and yaml-cpp's exceptions into
// kInvalidInput messages that name `display_name` and the line.
template <class T, class Parse>
StatusOr<T> parse_yaml_text(const std::string& text, const std::string& display_name, const std::string& format_doc,
                            Parse parse) {
  try {
    return parse(YAML::Load(text));
  } catch (const YamlInputError& e) {
    return Status::Invalid(e.message);
  } catch (const YAML::ParserException& e) {
    return Status::Invalid(display_name + ":" + std::to_string(e.mark.line + 1) +
                           ": malformed YAML: " + printable(e.msg) + "; check indentation, colons and brackets");
  } catch (const YAML::Exception& e) {
    const std::string where = e.mark.is_null() ? display_name : display_name + ":" + std::to_string(e.mark.line + 1);
    return Status::Invalid(where + ": " + printable(e.msg) + "; check the file against " + format_doc);
  }
}

// The whole file as text; kInvalidInput naming the path and `what` ("structure file") if unreadable.
StatusOr<std::string> read_text_file(const std::string& path, const std::string& what);

}  // namespace kinestat::io
