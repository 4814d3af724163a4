#include "kinestat/io/frame3dd.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>
#include <utility>

#include "io/roll_orientation.hpp"
#include "io/yaml_fields.hpp"
#include "kinestat/core/units.hpp"

namespace kinestat::io {
namespace {

using units::kDeg;

// Thrown by Reader::fail and caught by read_frame3dd_string: never crosses the io layer.
struct Frame3ddError {
  std::string message;
};

// One line of the file without its comment, split at white space (Frame3DD reads with fscanf, but
// its files hold one record a line, which lets a wrong count be named where it shows).
struct Line {
  int number = 0;
  std::vector<std::string> tokens;
};

// What a count introduced, for the messages of the records it counts.
struct Block {
  std::string what;    // "nodes"
  int line = 0;        // where its count is
  std::string hint{};  // instead of "check the number of WHAT at line LINE"
};

struct NodeRecord {
  Vec3 position = Vec3::Zero();
  int line = 0;
};

struct ElementRecord {
  int n1 = 0, n2 = 0;
  double A = 0, Asy = 0, Asz = 0, J = 0, Iy = 0, Iz = 0, E = 0, G = 0, roll = 0, density = 0;
  int line = 0;
};

// Files of Frame3DD versions before the zoom and dx lines fail at these lines or at the load-case
// count after them.
const Block kSettingsHint{"", 0,
                          "after the elements come five lines: shear flag, geometric stiffness flag, exaggeration, "
                          "zoom, dx (files of older Frame3DD versions lack zoom and dx: add them)"};

class Reader {
 public:
  Reader(std::string file, const FileUnits& units) : file_(std::move(file)), units_(units) {}

  msa::Structure parse(const std::string& text, std::vector<std::string>* notes) {
    split(text);
    s_.set_source(file_);
    s_.set_title(title_);
    // Frame3DD's geometric stiffness: the first end's axial force and no axial term
    // (msa::GeometricStiffnessConvention; docs/stability-and-modes.md).
    s_.set_geometric_stiffness_convention(msa::GeometricStiffnessConvention::kFrame3dd);
    read_nodes();
    read_reactions();
    read_elements();
    read_settings();
    add_beams();
    count_block_ = {};
    const auto [cases, cases_line] = count("number of static load cases", kSettingsHint);
    if (cases < 1) fail(cases_line, "number of static load cases", "at least one load case is needed; write 1 or more");
    for (int k = 1; k <= cases; ++k) read_load_case(k);
    // The modal data follows the mode count and ends the file: a static solve needs none of it.
    if (pos_ >= lines_.size())
      fail(last_line_, "number of dynamic modes",
           fmt::format("the file ends before it; add a last line 0 (no modes), or check the number of static load "
                       "cases at line {}",
                       cases_line));
    const auto [modes, modes_line] = count("number of dynamic modes", {"static load cases", cases_line});
    analysis_.modes = modes;
    analysis_.modes_source = source(modes_line);
    if (modes > 0) read_modal_data(modes_line, notes);
    return std::move(s_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& item, const std::string& what) const {
    throw Frame3ddError{fmt::format("{}:{}: {}: {}", file_, line, item, what)};
  }
  std::string source(int line) const { return fmt::format("{}:{}", file_, line); }

  void split(const std::string& text) {
    std::istringstream in(text);
    std::string raw;
    int number = 0;
    while (std::getline(in, raw)) {
      ++number;
      if (!raw.empty() && raw.back() == '\r') raw.pop_back();
      if (number == 1) {  // the title, a line of free text
        const auto first = raw.find_first_not_of(" \t"), last = raw.find_last_not_of(" \t");
        title_ = first == std::string::npos ? "" : raw.substr(first, last - first + 1);
        continue;
      }
      Line line{number, {}};
      std::istringstream words(raw.substr(0, raw.find('#')));
      for (std::string w; words >> w;) line.tokens.push_back(w);
      if (!line.tokens.empty()) lines_.push_back(std::move(line));
    }
    if (number == 0) fail(1, "file", "the file is empty; a .3dd file starts with a title line, then the nodes");
    last_line_ = number;
  }

  // The next line, which must hold `n` values described by `fields`; `block` names the count to
  // check when it holds another number (a count that does not match its records shows this way).
  const Line& next(const std::string& item, std::size_t n, const std::string& fields, const Block& block) {
    const std::string hint = !block.hint.empty() ? "; " + block.hint
                             : block.line > 0
                                 ? fmt::format("; check the number of {} at line {}", block.what, block.line)
                                 : "";
    if (pos_ >= lines_.size()) fail(last_line_, item, fmt::format("the file ends here, before {}{}", fields, hint));
    const Line& l = lines_[pos_++];
    if (l.tokens.size() != n)
      fail(l.number, item,
           fmt::format("expected {} value{} ({}) on this line, found {}{}", n, n == 1 ? "" : "s", fields,
                       l.tokens.size(), hint));
    return l;
  }

  int integer(const std::string& t, int line, const std::string& item) const {
    int v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      fail(line, item, fmt::format("'{}' is not a whole number; write an integer such as 3", t));
    return v;
  }

  double real(const std::string& t, int line, const std::string& item) const {
    const char* first = t.data() + (t.size() > 1 && t[0] == '+' ? 1 : 0);
    double v = 0;
    const auto [end, ec] = std::from_chars(first, t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      fail(line, item, fmt::format("'{}' is not a number; write a number such as 1.5 or 2e-3", t));
    return v;
  }

  // A number written in the file's unit of `q`, returned in SI, checked as check_quantity does.
  double value(const std::string& t, int line, const std::string& item, Quantity q, Sign sign = Sign::kAny,
               std::optional<UnitOfInput> unit = std::nullopt) const {
    const double v = real(t, line, item);
    const UnitOfInput u = unit ? *unit : units_.of(q);
    // check_quantity's message starts with the item: "ITEM = VALUE UNIT is ...; fix".
    if (const Status st = check_quantity(v, q, item, u, sign); !st.ok())
      throw Frame3ddError{fmt::format("{}: {}", source(line), st.message())};
    return v * (u.scale > 0.0 ? u.scale : 1.0);
  }

  // A line holding one count >= 0; returns it and its line.
  std::pair<int, int> count(const std::string& item, const Block& previous) {
    const Line& l = next(item, 1, "one whole number, the " + item, previous);
    const int n = integer(l.tokens[0], l.number, item);
    if (n < 0) fail(l.number, item, "a count cannot be negative; write 0 or more");
    return {n, l.number};
  }

  // A list with one line per node: `seen` (node -> line) holds the nodes read so far, and a node
  // read again fails: "node N is <twice> (also at line L); give one line per node<advice>".
  void once_per_node(std::map<int, int>& seen, int node, const Line& l, const std::string& item, const char* twice,
                     const char* advice = "") {
    if (const auto it = seen.find(node); it != seen.end())
      fail(l.number, item,
           fmt::format("node {} is {} (also at line {}); give one line per node{}", node, twice, it->second, advice));
    seen[node] = l.number;
  }

  // A node or element number 1..n.
  int index(const std::string& t, int line, const std::string& item, int n, const char* kind) const {
    const int i = integer(t, line, item);
    if (i < 1 || i > n)
      fail(line, item,
           fmt::format("{} {} does not exist: the file has {} {}s, numbered 1 to {}; refer to one of them", kind, i, n,
                       kind, n));
    return i;
  }

  int flag(const std::string& t, int line, const std::string& item) const {
    const int f = integer(t, line, item);
    if (f != 0 && f != 1) fail(line, item, fmt::format("{} is not a flag; write 0 or 1", f));
    return f;
  }

  // --- blocks ----------------------------------------------------------------------------------

  void read_nodes() {
    const auto [n, count_line] = count("number of nodes", {});
    if (n < 1) fail(count_line, "number of nodes", "a frame needs nodes; write their number and one line per node");
    const Block block{"nodes", count_line};
    std::map<int, NodeRecord> records;
    for (int k = 0; k < n; ++k) {
      const Line& l = next("node record", 5, "node x y z r", block);
      const int id = index(l.tokens[0], l.number, "node record", n, "node");
      const std::string item = fmt::format("node {}", id);
      if (const auto it = records.find(id); it != records.end())
        fail(l.number, item,
             fmt::format("node {} is defined twice (also at line {}); number the nodes 1 to {}", id, it->second.line,
                         n));
      NodeRecord r{Vec3::Zero(), l.number};
      for (int c = 0; c < 3; ++c)
        r.position[c] = value(l.tokens[1 + c], l.number, fmt::format("{} {}", item, "xyz"[c]), Quantity::kLength);
      // Frame3DD shortens the elements by the radii of their nodes (rigid end zones).
      const double radius = value(l.tokens[4], l.number, item + " r", Quantity::kLength, Sign::kNonNegative);
      if (radius != 0.0)
        fail(l.number, item,
             "a node radius r > 0 (rigid end zones that shorten the elements) is not supported; write r = 0, or "
             "model the zones with rigid links in a YAML structure file");
      records[id] = r;
    }
    for (const auto& [id, r] : records) s_.add_node(std::to_string(id), r.position, source(r.line));
    nodes_ = n;
    count_block_ = block;
  }

  void read_reactions() {
    const auto [n, count_line] = count("number of nodes with reactions", count_block_);
    const Block block{"nodes with reactions", count_line};
    std::map<int, int> seen;
    for (int k = 0; k < n; ++k) {
      const Line& l = next("reaction record", 7, "node and six flags x y z xx yy zz, 1 = fixed", block);
      const int node = index(l.tokens[0], l.number, "reaction record", nodes_, "node");
      const std::string item = fmt::format("reactions of node {}", node);
      once_per_node(seen, node, l, item, "listed twice");
      msa::DofMask fixed{};
      bool any = false;
      for (int d = 0; d < 6; ++d) {
        fixed[static_cast<std::size_t>(d)] = flag(l.tokens[1 + d], l.number, item) == 1;
        any = any || fixed[static_cast<std::size_t>(d)];
      }
      if (!any) continue;  // all free: no support
      s_.add_support({node - 1, fixed, Mat3::Identity(), source(l.number)});
      fixed_[node - 1] = fixed;
    }
    count_block_ = block;
  }

  void read_elements() {
    const auto [n, count_line] = count("number of frame elements", count_block_);
    if (n < 1)
      fail(count_line, "number of frame elements", "a frame needs elements; write their number and one line each");
    const Block block{"frame elements", count_line};
    for (int k = 0; k < n; ++k) {
      const Line& l = next("frame element record", 13, "e n1 n2 Ax Asy Asz Jxx Iyy Izz E G roll density", block);
      const int id = index(l.tokens[0], l.number, "frame element record", n, "element");
      const std::string item = fmt::format("element {}", id);
      if (const auto it = elements_.find(id); it != elements_.end())
        fail(l.number, item,
             fmt::format("element {} is defined twice (also at line {}); number the elements 1 to {}", id,
                         it->second.line, n));
      ElementRecord e;
      e.line = l.number;
      e.n1 = index(l.tokens[1], l.number, item + " n1", nodes_, "node");
      e.n2 = index(l.tokens[2], l.number, item + " n2", nodes_, "node");
      auto v = [&](int t, const char* key, Quantity q, Sign sign) {
        return value(l.tokens[static_cast<std::size_t>(t)], l.number, fmt::format("{} {}", item, key), q, sign);
      };
      e.A = v(3, "Ax", Quantity::kArea, Sign::kPositive);
      e.Asy = v(4, "Asy", Quantity::kArea, Sign::kNonNegative);
      e.Asz = v(5, "Asz", Quantity::kArea, Sign::kNonNegative);
      e.J = v(6, "Jxx", Quantity::kInertia, Sign::kPositive);
      e.Iy = v(7, "Iyy", Quantity::kInertia, Sign::kPositive);
      e.Iz = v(8, "Izz", Quantity::kInertia, Sign::kPositive);
      e.E = v(9, "E", Quantity::kModulus, Sign::kPositive);
      e.G = v(10, "G", Quantity::kModulus, Sign::kPositive);
      e.roll = value(l.tokens[11], l.number, item + " roll", Quantity::kAngle, Sign::kAny, UnitOfInput{kDeg, "deg"});
      e.density = v(12, "density", Quantity::kDensity, Sign::kNonNegative);
      const Vec3 d = s_.nodes()[static_cast<std::size_t>(e.n2 - 1)].position -
                     s_.nodes()[static_cast<std::size_t>(e.n1 - 1)].position;
      if (!(d.norm() > 1e-9 * s_.length_scale()))
        fail(l.number, item,
             fmt::format("its nodes {} and {} are at the same place (zero length); connect two distinct nodes", e.n1,
                         e.n2));
      elements_[id] = e;
    }
    count_block_ = block;
  }

  // Shear flag, geometric-stiffness flag, then three plot and output settings (deformation
  // exaggeration, zoom, the x increment of internal-force output): they change no result.
  void read_settings() {
    const Line& sh = next("shear deformation flag", 1, "0 or 1, the shear deformation flag", count_block_);
    shear_ = flag(sh.tokens[0], sh.number, "shear deformation flag") == 1;
    shear_line_ = sh.number;
    const Line& g = next("geometric stiffness flag", 1, "0 or 1, the geometric stiffness flag", {});
    // 1 asks for a second-order analysis: recorded for the caller (kinestat solve honours it).
    analysis_.geometric_stiffness = flag(g.tokens[0], g.number, "geometric stiffness flag") == 1;
    analysis_.geometric_stiffness_source = fmt::format("{}:{}", file_, g.number);
    for (const char* item : {"exaggeration of deformations", "zoom scale", "x increment for internal forces (dx)"}) {
      const Line& l = next(item, 1, std::string("one number, the ") + item, kSettingsHint);
      real(l.tokens[0], l.number, item);
    }
  }

  // One material, section and beam per element, all named by the element's number.
  void add_beams() {
    for (const auto& [id, e] : elements_) {
      const std::string name = std::to_string(id);
      const std::string item = fmt::format("element {}", id);
      if (shear_ && (e.Asy == 0.0 || e.Asz == 0.0))
        fail(e.line, item,
             fmt::format("the shear deformation flag at line {} is 1 but Asy or Asz is 0; give both shear areas, or "
                         "write 0 for the flag",
                         shear_line_));
      const int m = s_.add_material(Material{name, e.E, e.G, e.density});
      // The shear areas count only with the shear flag, as in Frame3DD. The polar moment of the twist
      // (its rotary mass and K_G's Wagner term) is J: Frame3DD's mass and geometric stiffness matrices
      // take Jxx there (docs/structure-format.md), where kinestat's default is Iy + Iz.
      const int sec =
          s_.add_section(Section{name, e.A, e.Iy, e.Iz, e.J, shear_ ? e.Asy : 0.0, shear_ ? e.Asz : 0.0, e.J});
      msa::Beam b;
      b.id = name;
      b.node1 = e.n1 - 1;
      b.node2 = e.n2 - 1;
      b.material = m;
      b.section = sec;
      b.orientation = roll_orientation(s_.nodes()[static_cast<std::size_t>(b.node2)].position -
                                           s_.nodes()[static_cast<std::size_t>(b.node1)].position,
                                       e.roll);
      b.theory = shear_ ? BeamTheory::kTimoshenko : BeamTheory::kEulerBernoulli;
      b.source = source(e.line);
      s_.add_beam(b);
      lengths_[id] = s_.beam_length(s_.beams().back());
    }
  }

  // Frame3DD's modal data after a mode count > 0: method, lumped flag, tolerance, shift and
  // exaggeration; the nodes with extra mass and inertia; the elements with extra mass; the modes to
  // animate and the pan rate (plot settings); optionally the matrix condensation method and its data.
  void read_modal_data(int modes_line, std::vector<std::string>* notes) {
    const Block modes_block{"dynamic modes", modes_line,
                            "after a number of dynamic modes > 0 come the modal data: method, lumped mass flag, "
                            "tolerance, shift, exaggeration, the nodes with extra inertia, the elements with extra "
                            "mass, the modes to animate and the pan rate (write 0 modes to give none)"};
    const Line& m = next("modal analysis method", 1, "1 (subspace Jacobi) or 2 (Stodola)", modes_block);
    analysis_.method = integer(m.tokens[0], m.number, "modal analysis method");
    if (analysis_.method != 1 && analysis_.method != 2)
      fail(m.number, "modal analysis method",
           fmt::format("{} is not a method; write 1 (subspace Jacobi) or 2 (Stodola)", analysis_.method));
    const Line& lump = next("lumped mass flag", 1, "0 (consistent masses) or 1 (lumped masses)", modes_block);
    analysis_.lumped = flag(lump.tokens[0], lump.number, "lumped mass flag") == 1;
    analysis_.lumped_source = source(lump.number);
    const Line& tol = next("mode shape tolerance", 1, "one number > 0, the convergence tolerance", modes_block);
    analysis_.tolerance = real(tol.tokens[0], tol.number, "mode shape tolerance");
    if (!(analysis_.tolerance > 0.0))
      fail(tol.number, "mode shape tolerance",
           fmt::format("{:g} is not a tolerance; write a number > 0 such as 1e-9", analysis_.tolerance));
    const Line& sh = next("frequency shift", 1, "one number, the shift (0 for a supported structure)", modes_block);
    analysis_.shift = real(sh.tokens[0], sh.number, "frequency shift");  // 1/s^2 in any units
    const Line& ex = next("exaggeration of mode shapes", 1, "one number, the exaggeration of mode shapes", modes_block);
    real(ex.tokens[0], ex.number, "exaggeration of mode shapes");

    // Extra node masses: n M Ixx Iyy Izz, the inertias about global axes (Frame3DD adds them to the
    // diagonal of its mass matrix, as kinestat's nodal masses are).
    auto [n, line] = count("number of nodes with extra inertia", modes_block);
    Block block{"nodes with extra inertia", line};
    for (int i = 0; i < n; ++i) {
      const Line& l = next("extra node inertia", 5, "n M Ixx Iyy Izz", block);
      const int node = index(l.tokens[0], l.number, "extra node inertia", nodes_, "node");
      const std::string item = fmt::format("extra inertia of node {}", node);
      msa::NodalMass nm;
      nm.node = node - 1;
      nm.source = source(l.number);
      nm.mass = value(l.tokens[1], l.number, item + " M", Quantity::kMass, Sign::kNonNegative);
      static constexpr std::array<const char*, 3> kKeys = {"Ixx", "Iyy", "Izz"};
      for (int d = 0; d < 3; ++d)
        nm.inertia[d] = value(l.tokens[static_cast<std::size_t>(2 + d)], l.number,
                              fmt::format("{} {}", item, kKeys[static_cast<std::size_t>(d)]), Quantity::kMassInertia,
                              Sign::kNonNegative);
      s_.add_mass(nm);
    }

    // Extra element masses: e mass. Frame3DD adds half of it to each end node's translations (its
    // consistent_M and lumped_M, "rotatory inertia of extra mass is neglected"): two nodal masses.
    std::tie(n, line) = count("number of frame elements with extra mass", block);
    block = {"frame elements with extra mass", line};
    for (int i = 0; i < n; ++i) {
      const Line& l = next("extra element mass", 2, "e mass", block);
      const int e = element(l, "extra element mass");
      const double mass =
          value(l.tokens[1], l.number, fmt::format("extra mass of element {}", e), Quantity::kMass, Sign::kNonNegative);
      if (mass == 0.0) continue;
      const ElementRecord& r = elements_.at(e);
      for (const int node : {r.n1, r.n2}) s_.add_mass({node - 1, mass / 2.0, Vec3::Zero(), source(l.number)});
    }

    // Plot settings: the modes to animate (their list omitted when there are none), the pan rate.
    std::tie(n, line) = count("number of modes to animate", block);
    block = {"modes to animate", line};
    if (n > 0) {
      const Line& l = next("modes to animate", static_cast<std::size_t>(n), fmt::format("{} mode numbers", n), block);
      for (const std::string& t : l.tokens) integer(t, l.number, "modes to animate");
    }
    const Line& pan = next("pan rate", 1, "one number, the pan rate of the animation", block);
    real(pan.tokens[0], pan.number, "pan rate");

    // Matrix condensation (optional, newer Frame3DD files): its method; a condensed model is not
    // computed, so the data after a method > 0 is not read.
    if (pos_ >= lines_.size()) return;
    const Line& c = next("matrix condensation method", 1, "0 (none), 1 (static), 2 (Guyan) or 3 (dynamic)", {});
    analysis_.condensation = integer(c.tokens[0], c.number, "matrix condensation method");
    if (analysis_.condensation < 0 || analysis_.condensation > 3)
      fail(c.number, "matrix condensation method",
           fmt::format("{} is not a method; write 0 (none), 1 (static), 2 (Guyan) or 3 (dynamic)",
                       analysis_.condensation));
    if (analysis_.condensation > 0) {
      if (notes)
        notes->push_back(
            fmt::format("{}:{}: matrix condensation method {} asked for: kinestat computes no condensed "
                        "model (the modes are those of the full model); the condensation data after this "
                        "line is not read",
                        file_, c.number, analysis_.condensation));
      pos_ = lines_.size();
    }
  }

  int element(const Line& l, const std::string& item) const {
    return index(l.tokens[0], l.number, item, static_cast<int>(elements_.size()), "element");
  }

  // One kind of element load of load case `cs`: the count of the `listed` loads after `block` (which
  // becomes theirs), then per load its first line of `n` fields, the first the element;
  // `read(line, element, item)` reads the rest, `item` naming the load ("load case 1: uniform load
  // on element 3").
  template <class Read>
  void read_element_loads(const std::string& cs, const std::string& listed, const std::string& load, std::size_t n,
                          const std::string& fields, Block& block, Read&& read) {
    const auto [count_n, line] = count(fmt::format("{}: number of {}s", cs, listed), block);
    block = {listed + "s", line};
    for (int i = 0; i < count_n; ++i) {
      const Line& l = next(cs + " " + load, n, fields, block);
      const int e = element(l, cs + " " + load);
      read(l, e, fmt::format("{}: {} on element {}", cs, load, e));
    }
  }

  // A load on element `e` (numbered from 1) read from line `l`.
  msa::MemberLoad member_load(int e, msa::MemberLoadType type, const Line& l) const {
    return {.beam = e - 1, .type = type, .source = source(l.number)};
  }

  // A distance from an element's first node, within its length.
  double distance(const std::string& t, int line, const std::string& item, int e) const {
    const double x = value(t, line, item, Quantity::kLength);
    const double length = lengths_.at(e);
    if (x < 0.0 || x > length * (1.0 + 1e-12)) {
      const UnitOfInput u = units_.of(Quantity::kLength);
      const double s = u.scale > 0.0 ? u.scale : 1.0;
      fail(line, item,
           fmt::format("{:g} {} is not on element {} (length {:g} {}); give a distance from its first node between 0 "
                       "and the length",
                       x / s, units_.length_name, e, length / s, units_.length_name));
    }
    return std::min(x, length);
  }

  void read_load_case(int k) {
    msa::LoadCase lc;
    lc.name = fmt::format("case {}", k);
    const std::string cs = fmt::format("load case {}", k);
    const Line& g = next(cs + " gravity", 3, "gX gY gZ, the gravitational acceleration", count_block_);
    lc.source = source(g.number);
    for (int c = 0; c < 3; ++c)
      lc.gravity[c] = value(g.tokens[static_cast<std::size_t>(c)], g.number, fmt::format("{} g{}", cs, "XYZ"[c]),
                            Quantity::kAcceleration);

    // Loaded nodes: n Fx Fy Fz Mxx Myy Mzz, global axes.
    auto [n, line] = count(cs + ": number of loaded nodes", {});
    Block block{"loaded nodes", line};
    std::map<int, int> seen;
    for (int i = 0; i < n; ++i) {
      const Line& l = next(cs + " nodal load", 7, "n Fx Fy Fz Mxx Myy Mzz", block);
      const int node = index(l.tokens[0], l.number, cs + " nodal load", nodes_, "node");
      const std::string item = fmt::format("{}: load on node {}", cs, node);
      once_per_node(seen, node, l, item, "loaded twice in this case", " with the sum");
      msa::NodalLoad load;
      load.node = node - 1;
      load.source = source(l.number);
      static constexpr std::array<const char*, 6> kKeys = {"Fx", "Fy", "Fz", "Mxx", "Myy", "Mzz"};
      for (int d = 0; d < 6; ++d)
        load.wrench[d] = value(l.tokens[static_cast<std::size_t>(1 + d)], l.number,
                               fmt::format("{} {}", item, kKeys[static_cast<std::size_t>(d)]),
                               d < 3 ? Quantity::kForce : Quantity::kMoment);
      lc.loads.push_back(load);
    }

    // Uniform loads: e Ux Uy Uz, local axes, force per length.
    auto uniform = [&](const Line& l, int e, const std::string& item) {
      msa::MemberLoad ml = member_load(e, msa::MemberLoadType::kUniform, l);
      for (int c = 0; c < 3; ++c)
        ml.w1[c] = value(l.tokens[static_cast<std::size_t>(1 + c)], l.number, fmt::format("{} U{}", item, "xyz"[c]),
                         Quantity::kForcePerLength);
      lc.member_loads.push_back(ml);
    };
    read_element_loads(cs, "uniform load", "uniform load", 4, "e Ux Uy Uz", block, uniform);

    // Trapezoidal loads: e, then x1 x2 w1 w2 for local x, y and z on three lines; one kinestat load
    // per direction with a loaded stretch (x1 = x2 loads nothing, as in Frame3DD).
    auto trapezoidal = [&](const Line& first, int e, const std::string& item) {
      for (int c = 0; c < 3; ++c) {
        const Line& l = c == 0 ? first : next(item, 4, fmt::format("x1 x2 w1 w2 (local {})", "xyz"[c]), block);
        const std::size_t o = c == 0 ? 1 : 0;
        const std::string key = fmt::format("{} local {}", item, "xyz"[c]);
        const double x1 = distance(l.tokens[o], l.number, key + " x1", e);
        const double x2 = distance(l.tokens[o + 1], l.number, key + " x2", e);
        const double w1 = value(l.tokens[o + 2], l.number, key + " w1", Quantity::kForcePerLength);
        const double w2 = value(l.tokens[o + 3], l.number, key + " w2", Quantity::kForcePerLength);
        if (x1 > x2) fail(l.number, key, "x1 > x2: the loaded stretch is reversed; give x1 <= x2");
        if (x1 == x2) continue;
        msa::MemberLoad ml = member_load(e, msa::MemberLoadType::kTrapezoidal, l);
        ml.a = x1;
        ml.b = x2;
        ml.w1[c] = w1;
        ml.w2[c] = w2;
        lc.member_loads.push_back(ml);
      }
    };
    read_element_loads(cs, "trapezoidal load", "trapezoidal load", 5, "e x1 x2 w1 w2 (local x)", block, trapezoidal);

    // Internal concentrated loads: e Px Py Pz x, local axes, x from the first node.
    auto concentrated = [&](const Line& l, int e, const std::string& item) {
      msa::MemberLoad ml = member_load(e, msa::MemberLoadType::kPoint, l);
      for (int c = 0; c < 3; ++c)
        ml.force[c] = value(l.tokens[static_cast<std::size_t>(1 + c)], l.number, fmt::format("{} P{}", item, "xyz"[c]),
                            Quantity::kForce);
      ml.a = distance(l.tokens[4], l.number, item + " x", e);
      lc.member_loads.push_back(ml);
    };
    read_element_loads(cs, "internal concentrated load", "concentrated load", 5, "e Px Py Pz x", block, concentrated);

    // Temperature loads: e alpha hy hz Ty+ Ty- Tz+ Tz-. alpha and the temperatures share the file's
    // degree (F or C): only their products enter, so they are taken as written (1/K and K).
    auto temperature = [&](const Line& l, int e, const std::string& item) {
      msa::MemberLoad ml = member_load(e, msa::MemberLoadType::kTemperature, l);
      ThermalLoad& t = ml.thermal;
      t.alpha = value(l.tokens[1], l.number, item + " alpha", Quantity::kThermalExpansion, Sign::kPositive,
                      UnitOfInput{1.0, "1/deg"});
      t.hy = value(l.tokens[2], l.number, item + " hy", Quantity::kLength, Sign::kPositive);
      t.hz = value(l.tokens[3], l.number, item + " hz", Quantity::kLength, Sign::kPositive);
      std::array<double, 4> face{};  // Ty+ Ty- Tz+ Tz-
      static constexpr std::array<const char*, 4> kFaces = {"Ty+", "Ty-", "Tz+", "Tz-"};
      for (std::size_t f = 0; f < 4; ++f)
        face[f] = value(l.tokens[4 + f], l.number, fmt::format("{} {}", item, kFaces[f]), Quantity::kTemperature,
                        Sign::kAny, UnitOfInput{1.0, "deg"});
      // The temperature varies linearly through each depth, so the centroid's change is the mean of
      // the two faces of a direction, the same for y and z: the mean of the four (Frame3DD's axial
      // term, alpha (Ty+ + Ty- + Tz+ + Tz-)/4 E A). The gradients are the face differences over the
      // depths, as ThermalLoad defines dTy and dTz (elements/member_loads.hpp): a hotter +y face
      // lengthens the +y fibres and bends the beam towards -y. Term by term, the fixed-end forces of
      // temperature_fixed_end_forces are then minus Frame3DD's equivalent end loads: N1 = E A alpha
      // dT, Mz1 = -E Iz alpha (Ty+ - Ty-)/hy, My1 = E Iy alpha (Tz+ - Tz-)/hz.
      t.dT = (face[0] + face[1] + face[2] + face[3]) / 4.0;
      t.dTy = face[0] - face[1];
      t.dTz = face[2] - face[3];
      lc.member_loads.push_back(ml);
    };
    read_element_loads(cs, "temperature load", "temperature load", 8, "e alpha hy hz Ty+ Ty- Tz+ Tz-", block,
                       temperature);

    // Prescribed displacements: n Dx Dy Dz Dxx Dyy Dzz (length and rad). A non-zero value must be on
    // a fixed dof (Frame3DD requires it too); zeros on fixed dofs are the supports themselves.
    std::tie(n, line) = count(cs + ": number of nodes with prescribed displacements", block);
    block = {"nodes with prescribed displacements", line};
    seen.clear();
    for (int i = 0; i < n; ++i) {
      const Line& l = next(cs + " prescribed displacement", 7, "n Dx Dy Dz Dxx Dyy Dzz", block);
      const int node = index(l.tokens[0], l.number, cs + " prescribed displacement", nodes_, "node");
      const std::string item = fmt::format("{}: prescribed displacement of node {}", cs, node);
      once_per_node(seen, node, l, item, "listed twice in this case");
      static constexpr std::array<const char*, 6> kKeys = {"Dx", "Dy", "Dz", "Dxx", "Dyy", "Dzz"};
      for (int d = 0; d < 6; ++d) {
        const std::string key = fmt::format("{} {}", item, kKeys[static_cast<std::size_t>(d)]);
        const double v = d < 3 ? value(l.tokens[static_cast<std::size_t>(1 + d)], l.number, key, Quantity::kLength)
                               : value(l.tokens[static_cast<std::size_t>(1 + d)], l.number, key, Quantity::kAngle);
        if (v == 0.0) continue;
        const auto fixed = fixed_.find(node - 1);
        if (fixed == fixed_.end() || !fixed->second[static_cast<std::size_t>(d)])
          fail(l.number, key,
               fmt::format("this dof of node {} is not fixed in the reactions; a prescribed displacement needs a "
                           "reaction flag 1 there (or write 0)",
                           node));
        lc.prescribed.push_back({node - 1, d, v, source(l.number)});
      }
    }
    count_block_ = block;
    s_.add_load_case(lc);
  }

  std::string file_;
  FileUnits units_;
  std::string title_;
  std::vector<Line> lines_;
  std::size_t pos_ = 0;
  int last_line_ = 0;
  Block count_block_{};  // the last block read: a count line after it may be one of its records
  int nodes_ = 0;
  std::map<int, msa::DofMask> fixed_;      // node index -> fixed dofs
  std::map<int, ElementRecord> elements_;  // element number -> record
  std::map<int, double> lengths_;          // element number -> length (m)
  bool shear_ = false;
  int shear_line_ = 0;
  msa::Structure s_;

 public:
  io::Frame3ddAnalysis analysis_;
};

}  // namespace

StatusOr<msa::Structure> read_frame3dd_string(const std::string& text, const std::string& display_name,
                                              const FileUnits& units, std::vector<std::string>* notes,
                                              Frame3ddAnalysis* analysis) {
  try {
    Reader reader(display_name, units);
    msa::Structure s = reader.parse(text, notes);
    if (analysis) *analysis = reader.analysis_;
    // Its messages start with the item's "FILE:LINE".
    if (const Status st = s.validate(); !st.ok()) return st;
    return s;
  } catch (const Frame3ddError& e) {
    return Status::Invalid(e.message);
  }
}

bool is_frame3dd_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".3dd";
}

StatusOr<msa::Structure> read_frame3dd(const std::string& path, const FileUnits& units, std::vector<std::string>* notes,
                                       Frame3ddAnalysis* analysis) {
  StatusOr<std::string> text = read_text_file(path, "Frame3DD file");
  if (!text.ok()) return text.status();
  return read_frame3dd_string(*text, path, units, notes, analysis);
}

}  // namespace kinestat::io
