// The MSA model of a RobotModel at a posture (robot_msa.hpp). Two passes: the legs are walked into
// bodies and connections (elements: beams and springs; ties: joints with rigid components), then
// the ties are oriented as trees from the base and the platform (each body's master node is the
// node its one incoming tie makes a slave), and the nodes, elements and rigid links are made.
#include "kinestat/mechanisms/robot_msa.hpp"

#include <fmt/format.h>

#include <cmath>
#include <deque>
#include <optional>

namespace kinestat::mechanisms {
namespace {

constexpr int kBase = 0, kPlatform = 1;

// An orthonormal, right-handed frame whose x axis is along `x`.
Mat3 frame_with_x(const Vec3& x) {
  const Vec3 e1 = x.normalized();
  const Vec3 t = std::abs(e1.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e2 = (t - t.dot(e1) * e1).normalized();
  Mat3 R;
  R << e1, e2, e1.cross(e2);
  return R;
}

// A connection between two bodies: a beam, or a joint element between coincident nodes.
struct Connection {
  std::string label;
  int body1 = -1, body2 = -1;  // body1 on the base's side of the leg
  Vec3 p1 = Vec3::Zero(), p2 = Vec3::Zero();
  bool beam = false;
  // a joint element
  Mat3 frame = Mat3::Identity();
  Vec6 stiffness = Vec6::Zero();
  Mat6 coupling = Mat6::Zero();  // a coupled spring's off-diagonal terms (msa::Joint::coupling)
  // a beam
  const RobotBeam* beam_data = nullptr;
  Vec3 orientation = Vec3::Zero();
  bool tie() const {
    if (beam) return false;
    for (int i = 0; i < 6; ++i)
      if (std::isinf(stiffness(i))) return true;
    return false;
  }
};

// The joint element of a robot joint at the posture: its frame and stiffness (0: free, k: the
// actuator, kRigid: constrained) and its point.
struct JointElement {
  Mat3 frame = Mat3::Identity();
  Vec6 stiffness = Vec6::Constant(msa::kRigid);
  Vec3 point = Vec3::Zero();
};

JointElement joint_element(const RobotJoint& j, const RobotItemFrames& f) {
  JointElement e;
  e.point = f.at.translation();
  auto axis = [&](int motion, int a) -> Vec3 { return (f.motions[motion].linear() * j.axes[a]).normalized(); };
  const double k = j.actuated ? j.actuator_stiffness : 0.0;  // the first coordinate
  switch (j.type) {
    case RobotJointType::kRevolute:
      e.frame = frame_with_x(axis(0, 0));
      e.stiffness(3) = k;
      break;
    case RobotJointType::kPrismatic:
      e.frame = frame_with_x(axis(0, 0));
      e.stiffness(0) = k;
      break;
    case RobotJointType::kCylindrical:
      e.frame = frame_with_x(axis(0, 0));
      e.stiffness(3) = k;
      e.stiffness(0) = 0.0;
      break;
    case RobotJointType::kUniversal: {
      // Rotations in span(a1, a2) are free but for the actuator's share: theta_1 = d . w with d in
      // the span, d . a1 = 1, d . a2 = 0; |d| = 1 / sin(a1, a2). In a frame (d, a2, n): k |d|^2, 0.
      const Vec3 a1 = axis(0, 0), a2 = axis(1, 1);
      const double c = a1.dot(a2), s2 = 1.0 - c * c;
      if (j.actuated) {
        const Vec3 d = (a1 - c * a2).normalized();
        e.frame << d, a2, d.cross(a2);
        e.stiffness(3) = k / s2;
      } else {
        const Vec3 n = a1.cross(a2).normalized();
        e.frame << a1, n.cross(a1), n;
        e.stiffness(3) = 0.0;
      }
      e.stiffness(4) = 0.0;
      break;
    }
    case RobotJointType::kSpherical: {
      // Every rotation free but for the actuator's share: d = (a2 x a3) / (a1 . (a2 x a3)).
      e.stiffness.tail<3>().setZero();
      if (j.actuated) {
        const Vec3 w = axis(1, 1).cross(axis(2, 2));
        const double t = axis(0, 0).dot(w);
        e.frame = frame_with_x(w);
        e.stiffness(3) = k * w.squaredNorm() / (t * t);
      }
      break;
    }
    case RobotJointType::kParallelogram: {
      // The plate translates along a x (to - at) without turning: a slider at `to`.
      const Vec3 a = axis(0, 0);
      e.point = f.after.translation();
      e.frame = frame_with_x(a.cross(e.point - f.at.translation()));
      e.stiffness(0) = 0.0;
      break;
    }
  }
  return e;
}

// A joint's spring (diagonal in `axes`) and the joint after it as one joint element in `axes`, when
// every spring axis lies in the span of the joint frame's axes of one value (rigid, free or the
// actuator's): then the two are diagonal in the same frame and in series component by component.
// One element instead of two about a node between them: the matrix of the built-in five-bar.
std::optional<JointElement> merged(const JointElement& e, const Mat3& axes, const Vec6& spring) {
  JointElement out = e;
  out.frame = axes;
  for (int i = 0; i < 6; ++i) {
    const int part = i < 3 ? 0 : 3;
    const Vec3 a = axes.col(i - part);
    std::optional<double> value;
    for (int k = 0; k < 3 && !value; ++k) {
      // a in the span of the frame's axes whose value is e.stiffness(part + k)?
      const double v = e.stiffness(part + k);
      double along = 0.0;
      for (int m = 0; m < 3; ++m)
        if (e.stiffness(part + m) == v) along += std::pow(a.dot(e.frame.col(m)), 2);
      if (along > 1.0 - 1e-12) value = v;
    }
    if (!value) return std::nullopt;
    const double k = spring(i);
    out.stiffness(i) = std::isinf(*value) ? k : *value == 0.0 ? 0.0 : k * *value / (k + *value);
  }
  return out;
}

bool diagonal(const Mat6& K) {
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 6; ++k)
      if (i != k && std::abs(K(i, k)) > 1e-12 * std::sqrt(std::abs(K(i, i) * K(k, k)))) return false;
  return true;
}

class Builder {
 public:
  Builder(const RobotModel& m, const RobotPosture& p) : m_(m), p_(p), tol_(1e-12 * m.length_scale()) {
    parent_ = {kBase, kPlatform};
  }

  StatusOr<msa::Structure> build() {
    const RobotDescription& d = m_.description();
    s_.set_title(fmt::format("{} (MSA at the tool pose ({:.6g}, {:.6g}, {:.6g}) m)", d.name, p_.tool.translation().x(),
                             p_.tool.translation().y(), p_.tool.translation().z()));
    s_.set_source(d.source);
    for (int l = 0; l < m_.num_legs(); ++l)
      if (Status st = walk_leg(l); !st.ok()) return st;
    if (Status st = orient_ties(); !st.ok()) return st;
    make_items();
    const int tool = port(kPlatform, p_.tool.translation(), "the platform (tool point)");
    s_.set_report_node(tool);
    if (Status st = s_.validate(); !st.ok()) return st;
    return std::move(s_);
  }

 private:
  Status invalid(const std::string& what) const {
    return Status::Invalid(fmt::format("{}: MSA model: {}", m_.description().source, what));
  }

  int new_body() {
    parent_.push_back(static_cast<int>(parent_.size()));
    return parent_.back();
  }
  int find(int b) {
    while (parent_[b] != b) b = parent_[b] = parent_[parent_[b]];
    return b;
  }

  // A 6x6 spring between the body `cur` and a new body at `p`, in `axes` (base axes): a joint element,
  // its off-diagonal terms (a coupled spring: `fea:`, a full `matrix:`) the joint's coupling.
  int spring(int cur, const Vec3& p, const Mat3& axes, const RobotSpring& sp) {
    Connection c;
    c.label = sp.label + " (spring)";
    c.body1 = cur;
    c.body2 = new_body();
    c.p1 = c.p2 = p;
    c.frame = axes;
    c.stiffness = sp.stiffness.diagonal();
    c.coupling = sp.stiffness;
    c.coupling.diagonal().setZero();
    conn_.push_back(c);
    return c.body2;
  }

  Status walk_leg(int l) {
    const RobotLeg& leg = m_.description().legs[l];
    const std::vector<RobotItemFrames> frames = robot_leg_frames(m_, l, p_);
    int cur = kBase, coordinate = m_.leg_offset(l);
    for (std::size_t i = 0; i < leg.items.size(); ++i) {
      const RobotItemFrames& f = frames[i];
      if (const auto* link = std::get_if<RobotLink>(&leg.items[i])) {
        if (!link->spring) continue;  // rigid: the same body
        const Vec3 end = f.after.translation();
        const Mat3 axes = f.after.linear() * link->spring->axes;
        if (link->beam) {
          Connection c;
          c.label = link->label;
          c.beam = true;
          c.beam_data = &*link->beam;
          c.body1 = cur;
          c.body2 = cur = new_body();
          c.p1 = end - link->beam->length * axes.col(0);
          c.p2 = end;
          c.orientation = axes.col(1);
          conn_.push_back(c);
        } else {
          cur = spring(cur, end, axes, *link->spring);
        }
        continue;
      }
      const RobotJoint& j = std::get<RobotJoint>(leg.items[i]);
      const double q = p_.q(coordinate);
      coordinate += coordinate_count(j.type);
      JointElement e = joint_element(j, f);
      if (j.spring) {
        const Mat3 axes = f.at.linear() * j.spring->axes;
        std::optional<JointElement> one;
        if (diagonal(j.spring->stiffness) && e.point == f.at.translation())
          one = merged(e, axes, j.spring->stiffness.diagonal());
        if (one) {
          e = *one;
        } else {
          cur = spring(cur, f.at.translation(), axes, *j.spring);
        }
      }
      if (e.stiffness.array().isInf().all()) continue;  // locked: the same body
      Connection c;
      c.label = j.label;
      c.body1 = cur;
      c.body2 = cur = new_body();
      c.p1 = c.p2 = e.point;
      c.frame = e.frame;
      c.stiffness = e.stiffness;
      conn_.push_back(c);
      if (j.bars) {  // the bars' spring at the distal plate, after the plate's slide
        const StatusOr<Mat6> K = robot_parallelogram_spring(j, q);
        if (!K.ok()) return invalid(K.status().message());
        RobotSpring bars;
        bars.label = j.label + " bars";
        bars.stiffness = *K;
        cur = spring(cur, f.after.translation(), f.after.linear() * robot_parallelogram_axes(j), bars);
      }
    }
    // The leg's end is the platform.
    const int end = find(cur);
    if (end == find(kBase))
      return invalid(
          fmt::format("{} is rigid from the base to the platform (no free joint, spring or beam): the "
                      "platform cannot move",
                      leg.name));
    parent_[end] = find(kPlatform);
    return Status::Ok();
  }

  // Each tie makes one of its nodes a slave: orient the ties as trees from the base, the platform
  // and then any body, so that every body has at most one incoming tie (whose node is its master).
  // A tie that reaches a body already reached closes a loop: it stays as it is, and msa eliminates it
  // as a constraint on the trees' unknowns (msa/dof_map.hpp).
  Status orient_ties() {
    const int nb = static_cast<int>(parent_.size());
    std::vector<std::vector<int>> adj(nb);
    for (int c = 0; c < static_cast<int>(conn_.size()); ++c) {
      Connection& x = conn_[c];
      x.body1 = find(x.body1);
      x.body2 = find(x.body2);
      if (!x.tie()) continue;
      if (x.body1 == x.body2) return loop(x);
      adj[x.body1].push_back(c);
      adj[x.body2].push_back(c);
    }
    incoming_.assign(nb, -1);
    std::vector<bool> seen(nb, false), used(conn_.size(), false);
    std::vector<int> roots = {kBase, find(kPlatform)};
    for (int b = 0; b < nb; ++b) roots.push_back(b);
    for (int root : roots) {
      if (seen[root] || find(root) != root) continue;
      seen[root] = true;
      std::deque<int> queue = {root};
      while (!queue.empty()) {
        const int u = queue.front();
        queue.pop_front();
        for (int c : adj[u]) {
          if (used[c]) continue;
          used[c] = true;
          const int v = conn_[c].body1 == u ? conn_[c].body2 : conn_[c].body1;
          if (seen[v]) continue;  // a loop (above)
          seen[v] = true;
          incoming_[v] = c;
          queue.push_back(v);
        }
      }
    }
    return Status::Ok();
  }

  Status loop(const Connection& c) const {
    return invalid(
        fmt::format("{} ties a rigid body of the MSA model to itself (both its sides are one body): give the joint a "
                    "`spring:` or the links between its sides a `beam:`, or use the VJM (--method vjm)",
                    c.label));
  }

  int add_node(const Vec3& p, const std::string& what) {
    const int n = static_cast<int>(s_.nodes().size());
    s_.add_node(fmt::format("{} {}", n + 1, what), p, what);
    return n;
  }

  // A node of `body` at `p`: the body's master (made here if it has none), or a node tied to it.
  int port(int body, const Vec3& p, const std::string& what) {
    body = find(body);
    if (body == find(kBase)) {
      const int n = add_node(p, what + " (base)");
      s_.add_support({n, msa::kAllDofs, Mat3::Identity()});
      return n;
    }
    int& master = master_[body];
    if (master < 0) return master = add_node(p, what);
    if ((s_.nodes()[master].position - p).norm() <= tol_) return master;
    const int n = add_node(p, what);
    msa::RigidLink r;
    r.id = fmt::format("{}: {}", s_.rigid_links().size() + 1, what);
    r.master = master;
    r.slave = n;
    r.source = what;
    s_.add_rigid_link(r);
    return n;
  }

  void make_items() {
    master_.assign(parent_.size(), -1);
    // The masters first: a body's incoming tie's node on its side.
    for (std::size_t b = 0; b < parent_.size(); ++b)
      if (incoming_[b] >= 0) {
        const Connection& c = conn_[incoming_[b]];
        master_[b] = add_node(c.p1, c.label);
      }
    for (std::size_t i = 0; i < conn_.size(); ++i) {
      const Connection& c = conn_[i];
      const std::string id = fmt::format("{}: {}", i + 1, c.label);
      if (c.beam) {
        const RobotBeam& rb = *c.beam_data;
        Material mat = rb.material;
        mat.id = id;
        Section sec = rb.section;
        sec.id = id;
        msa::Beam b;
        b.id = id;
        b.node1 = port(c.body1, c.p1, c.label + " start");
        b.node2 = port(c.body2, c.p2, c.label + " end");
        b.material = s_.add_material(mat);
        b.section = s_.add_section(sec);
        b.orientation = c.orientation;
        b.theory = rb.theory;
        b.source = c.label;
        s_.add_beam(b);
        continue;
      }
      msa::Joint j;
      j.id = id;
      if (incoming_[c.body2] == static_cast<int>(i)) {
        j.node1 = port(c.body1, c.p1, c.label);
        j.node2 = master_[c.body2];
      } else if (incoming_[c.body1] == static_cast<int>(i)) {
        j.node1 = port(c.body2, c.p2, c.label);
        j.node2 = master_[c.body1];
      } else {
        j.node1 = port(c.body1, c.p1, c.label);
        j.node2 = port(c.body2, c.p2, c.label);
      }
      j.frame = c.frame;
      j.stiffness = c.stiffness;
      j.coupling = c.coupling;
      j.source = c.label;
      s_.add_joint(j);
    }
  }

  const RobotModel& m_;
  const RobotPosture& p_;
  double tol_;
  msa::Structure s_;
  std::vector<int> parent_;  // union-find of bodies: a leg's end joins the platform
  std::vector<Connection> conn_;
  std::vector<int> incoming_;  // per body: its incoming tie (a connection index), or -1
  std::vector<int> master_;    // per body: its master node, or -1
};

}  // namespace

StatusOr<msa::Structure> robot_msa_structure(const RobotModel& model, const RobotPosture& posture) {
  return Builder(model, posture).build();
}

}  // namespace kinestat::mechanisms
