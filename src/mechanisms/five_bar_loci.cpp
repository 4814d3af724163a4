#include "kinestat/mechanisms/five_bar_loci.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <fmt/format.h>

namespace kinestat::mechanisms {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

// Collects samples into polylines, breaking where a sample is missing.
class PolylineBuilder {
 public:
  explicit PolylineBuilder(MapCurve& out) : out_(out.lines) {}
  ~PolylineBuilder() { flush(); }
  void add(const std::optional<Vec2>& point) {
    if (point) {
      current_.emplace_back(point->x(), point->y(), 0.0);
    } else {
      flush();
    }
  }

 private:
  void flush() {
    if (current_.size() >= 2) out_.push_back(std::move(current_));
    current_.clear();
  }
  std::vector<std::vector<Vec3>>& out_;
  std::vector<Vec3> current_;
};

// Intersection of the circles (c1, r1) and (c2, r2) on the side `side` (+1: left of c1 -> c2).
std::optional<Vec2> circle_intersection(const Vec2& c1, double r1, const Vec2& c2, double r2, int side) {
  const Vec2 d = c2 - c1;
  const double dist = d.norm();
  if (dist == 0.0 || dist > r1 + r2 || dist < std::abs(r1 - r2)) return std::nullopt;
  const double a = (r1 * r1 - r2 * r2 + dist * dist) / (2.0 * dist);
  const double h = std::sqrt(std::max(0.0, r1 * r1 - a * a));
  const Vec2 n(-d.y(), d.x());
  return c1 + (a / dist) * d + side * (h / dist) * n;
}

}  // namespace

std::vector<MapCurve> five_bar_singular_loci(const FiveBarParams& p, WorkingMode mode, Assembly assembly, int samples) {
  std::vector<MapCurve> loci{{"workspace boundary", {}}, {"parallel singularity", {}}};
  if (!validate(p).ok() || !check_loci_samples(samples).ok()) return loci;
  const double step = 2.0 * std::numbers::pi / samples;
  const Vec2 A[2] = {Vec2(-p.r3, 0.0), Vec2(p.r3, 0.0)};

  // Serial singularity of leg i: the circles about A_i; a point belongs to the region's boundary
  // when the inverse kinematics of the mode reaches it with the chosen assembly mode.
  for (const Vec2& centre : A) {
    for (const double radius : {p.r1 + p.r2, std::abs(p.r1 - p.r2)}) {
      if (radius <= 1e-12 * (p.r1 + p.r2)) continue;  // r1 = r2: the inner "circle" is the point A_i
      PolylineBuilder line(loci[0]);
      for (int k = 0; k <= samples; ++k) {
        const Vec2 P = centre + radius * unit(-std::numbers::pi + k * step);
        const auto q = inverse_kinematics(p, P, mode);
        line.add(q.ok() && q->assembly == assembly ? std::optional<Vec2>(P) : std::nullopt);
      }
    }
  }

  // Parallel singularity, B1P and PB2 aligned. (a) P between B1 and B2: for each theta1, B2 on its
  // circle at distance 2 r2 from B1 (two branches), P the midpoint. (b) B1 = B2 = C, where the
  // proximal circles meet (r3 <= r1): P anywhere on the circle of radius r2 about C. Kept where the
  // legs bend as the working mode says ((B_i - A_i) x (P - B_i) <= 0 for the "+" root, five_bar.hpp).
  const auto in_mode = [&](const Vec2& B1, const Vec2& B2, const Vec2& P) {
    const int sign1 = cross2(B1 - A[0], P - B1) <= 0.0 ? 1 : -1;
    const int sign2 = cross2(B2 - A[1], P - B2) <= 0.0 ? 1 : -1;
    return sign1 == mode.sign1 && sign2 == mode.sign2;
  };
  for (const int side : {1, -1}) {
    PolylineBuilder line(loci[1]);
    for (int k = 0; k <= samples; ++k) {
      const Vec2 B1 = A[0] + p.r1 * unit(-std::numbers::pi + k * step);
      const std::optional<Vec2> B2 = circle_intersection(A[1], p.r1, B1, 2.0 * p.r2, side);
      const std::optional<Vec2> P = B2 ? std::optional<Vec2>(0.5 * (B1 + *B2)) : std::nullopt;
      line.add(P && in_mode(B1, *B2, *P) ? P : std::nullopt);
    }
  }
  if (p.r3 <= p.r1) {
    const double h = std::sqrt(p.r1 * p.r1 - p.r3 * p.r3);
    for (const double cy : h > 0.0 ? std::vector<double>{h, -h} : std::vector<double>{0.0}) {
      const Vec2 C(0.0, cy);
      PolylineBuilder line(loci[1]);
      for (int k = 0; k <= samples; ++k) {
        const Vec2 P = C + p.r2 * unit(-std::numbers::pi + k * step);
        line.add(in_mode(C, C, P) ? std::optional<Vec2>(P) : std::nullopt);
      }
    }
  }
  return loci;
}

StatusOr<Box2> five_bar_workspace_box(const FiveBarParams& p, WorkingMode mode, Assembly assembly) {
  if (Status s = validate(p); !s.ok()) return s;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Box2 box{Vec2::Constant(kInf), Vec2::Constant(-kInf)};
  for (const MapCurve& curve : five_bar_singular_loci(p, mode, assembly))
    for (const std::vector<Vec3>& line : curve.lines)
      for (const Vec3& P : line) {
        box.min = box.min.cwiseMin(P.head<2>());
        box.max = box.max.cwiseMax(P.head<2>());
      }
  if (!(box.min.x() <= box.max.x()))
    return Status::Invalid("five-bar working mode " + to_string(mode) + ", assembly " + to_string(assembly) +
                           ": no posture of this mode exists");
  return box;
}

Status check_loci_samples(int samples) {
  if (samples < 8 || samples > kMaxLociSamples)
    return Status::Invalid(
        fmt::format("samples = {}: the loci take 8 to {} samples per turn (default 4096)", samples, kMaxLociSamples));
  return Status::Ok();
}

}  // namespace kinestat::mechanisms
