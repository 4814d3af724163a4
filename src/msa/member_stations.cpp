// Along-member results (static_analysis.hpp, beam_stations): equilibrium of the part [0, x] gives the
// internal forces, their curvatures and strains integrated from the end displacements give the
// deflected shape.
#include <algorithm>
#include <array>
#include <vector>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::msa {
namespace {

// A span load in local axes: distributed (w1 at a to w2 at b) or concentrated (force, moment at a).
struct LocalLoad {
  bool distributed = true;
  double a = 0.0, b = 0.0;
  Vec3 w1 = Vec3::Zero(), w2 = Vec3::Zero();
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
};

class BeamField {
 public:
  BeamField(const Structure& s, const LoadCase& lc, const LoadCaseResult& r, int beam)
      : b_(s.beams()[beam]),
        m_(s.materials()[b_.material]),
        sec_(s.sections()[b_.section]),
        L_(s.beam_length(b_)),
        end1_(r.beam_end_forces[beam].head<6>()) {
    const Mat3 axes = s.beam_axes(b_);
    auto local = [&](const Vec3& v, bool global) { return global ? Vec3(axes.transpose() * v) : v; };
    if (lc.gravity.squaredNorm() > 0.0 && m_.density > 0.0) {
      const Vec3 w = local(m_.density * sec_.A * lc.gravity, true);
      loads_.push_back({true, 0.0, L_, w, w});
    }
    for (const MemberLoad& ml : lc.member_loads) {
      if (ml.beam != beam) continue;
      switch (ml.type) {
        case MemberLoadType::kUniform:
          loads_.push_back({true, 0.0, L_, local(ml.w1, ml.global_axes), local(ml.w1, ml.global_axes)});
          break;
        case MemberLoadType::kTrapezoidal:
          loads_.push_back({true, ml.a, ml.b, local(ml.w1, ml.global_axes), local(ml.w2, ml.global_axes)});
          break;
        case MemberLoadType::kPoint:
          loads_.push_back({false, ml.a, ml.a, Vec3::Zero(), Vec3::Zero(), local(ml.force, ml.global_axes),
                            local(ml.moment, ml.global_axes)});
          break;
        case MemberLoadType::kTemperature: {
          const ThermalLoad& t = ml.thermal;
          strain_ += t.alpha * t.dT;
          // A hotter +y face bends towards -y: d(rz)/dx = -alpha dTy / hy; likewise d(-ry)/dx about y.
          if (t.dTy != 0.0) kappa_y_ -= t.alpha * t.dTy / t.hy;
          if (t.dTz != 0.0) kappa_z_ -= t.alpha * t.dTz / t.hz;
          break;
        }
      }
    }
    Mat12 T = Mat12::Zero();
    for (int k = 0; k < 4; ++k) T.block<3, 3>(3 * k, 3 * k) = axes.transpose();
    Vec12 ug;
    ug << r.displacement[b_.node1], r.displacement[b_.node2];
    ends_ = T * ug;
    if (b_.theory == BeamTheory::kTimoshenko) {
      if (sec_.Asy > 0) gas_y_ = m_.G * sec_.Asy;
      if (sec_.Asz > 0) gas_z_ = m_.G * sec_.Asz;
    }
    breaks_ = {0.0, L_};
    for (const LocalLoad& l : loads_) {
      breaks_.push_back(l.a);
      breaks_.push_back(l.b);
    }
    std::sort(breaks_.begin(), breaks_.end());
  }

  double length() const { return L_; }

  // Force and moment on the +x face of [0, x], from its equilibrium: minus the end-1 force and the
  // span loads on [0, x] (those at x included), moments about the section's centre.
  Vec6 forces(double x) const {
    Vec3 F = end1_.head<3>(), M = end1_.tail<3>() + Vec3(-x, 0, 0).cross(Vec3(end1_.head<3>()));
    static constexpr double kG = 0.5773502691896257;  // two Gauss points: exact for linear loads
    for (const LocalLoad& l : loads_) {
      if (!l.distributed) {
        if (l.a <= x) {
          F += l.force;
          M += l.moment + Vec3(l.a - x, 0, 0).cross(l.force);
        }
        continue;
      }
      const double hi = std::min(l.b, x);
      if (hi <= l.a) continue;
      const double half = 0.5 * (hi - l.a), mid = 0.5 * (hi + l.a);
      for (double g : {-kG, kG}) {
        const double xi = mid + half * g, t = (xi - l.a) / (l.b - l.a);
        const Vec3 q = half * ((1.0 - t) * l.w1 + t * l.w2);
        F += q;
        M += Vec3(xi - x, 0, 0).cross(q);
      }
    }
    Vec6 out;
    out << -F, -M;
    return out;
  }

  // Strains at x: axial, twist rate, and per bending plane (y: v, theta = rz; z: w, theta = -ry) the
  // curvature d theta/dx and the shear strain d(deflection)/dx - theta.
  std::array<double, 6> strains(double x) const {
    const Vec6 f = forces(x);
    const double E = m_.E;
    return {f(0) / (E * sec_.A) + strain_,    f(3) / (m_.G * sec_.J),           f(5) / (E * sec_.Iz) + kappa_y_,
            gas_y_ > 0 ? f(1) / gas_y_ : 0.0, -f(4) / (E * sec_.Iy) + kappa_z_, gas_z_ > 0 ? f(2) / gas_z_ : 0.0};
  }

  // Integrals over [0, x]: of each strain (0..5) and, for the curvatures, of (x - xi) kappa (6, 7).
  // Three Gauss points per piece between load breakpoints: the fields are polynomials of degree <= 3
  // there, times (x - xi): degree 4, integrated exactly.
  std::array<double, 8> integrals(double x) const {
    static constexpr double kP[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    static constexpr double kW[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    std::array<double, 8> I{};
    double lo = 0.0;
    for (size_t k = 1; k <= breaks_.size() && lo < x; ++k) {
      const double hi = k < breaks_.size() ? std::min(breaks_[k], x) : x;
      if (hi > lo) {
        const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
        for (int g = 0; g < 3; ++g) {
          const double xi = mid + half * kP[g], w = half * kW[g];
          const auto e = strains(xi);
          for (int i = 0; i < 6; ++i) I[i] += w * e[i];
          I[6] += w * (x - xi) * e[2];
          I[7] += w * (x - xi) * e[4];
        }
      }
      lo = std::max(lo, hi);
    }
    return I;
  }

  // Displacements at every station: axial and twist integrated from an unreleased end; each bending
  // plane fitted to both end translations (a released end rotation is not the node's), or when a
  // translation is released, to the translation and rotation of an end that holds both.
  std::vector<Vec6> displacements(const std::vector<double>& xs) const {
    const auto IL = integrals(L_);
    const auto& rel = b_.releases;
    const double u0 = !rel[0] ? ends_(0) : ends_(6) - IL[0];
    const double t0 = !rel[3] ? ends_(3) : ends_(9) - IL[1];
    // Per plane: translation dof, rotation dof, sign of theta in that rotation, curvature and shear
    // integral indices.
    struct Plane {
      int d, r;
      double sign;
      int kappa, gamma, moment;
    };
    const Plane planes[2] = {{1, 5, 1.0, 2, 3, 6}, {2, 4, -1.0, 4, 5, 7}};
    double d0[2], th0[2];
    for (int p = 0; p < 2; ++p) {
      const Plane& P = planes[p];
      const double D_L = IL[P.moment] + IL[P.gamma];
      if (!rel[P.d] && !rel[6 + P.d]) {
        d0[p] = ends_(P.d);
        th0[p] = (ends_(6 + P.d) - d0[p] - D_L) / L_;
      } else if (!rel[P.d] && !rel[P.r]) {
        d0[p] = ends_(P.d);
        th0[p] = P.sign * ends_(P.r);
      } else {
        th0[p] = P.sign * ends_(6 + P.r) - IL[P.kappa];
        d0[p] = ends_(6 + P.d) - th0[p] * L_ - D_L;
      }
    }
    std::vector<Vec6> out;
    for (double x : xs) {
      const auto I = integrals(x);
      Vec6 u;
      u(0) = u0 + I[0];
      u(3) = t0 + I[1];
      for (int p = 0; p < 2; ++p) {
        const Plane& P = planes[p];
        u(P.d) = d0[p] + th0[p] * x + I[P.moment] + I[P.gamma];
        u(P.r) = P.sign * (th0[p] + I[P.kappa]);
      }
      out.push_back(u);
    }
    return out;
  }

 private:
  const Beam& b_;
  const Material& m_;
  const Section& sec_;
  double L_;
  Vec6 end1_;
  std::vector<LocalLoad> loads_;
  double strain_ = 0.0, kappa_y_ = 0.0, kappa_z_ = 0.0;
  double gas_y_ = 0.0, gas_z_ = 0.0;  // G As; 0: no shear deformation
  Vec12 ends_;
  std::vector<double> breaks_;
};

}  // namespace

StatusOr<BeamStations> beam_stations(const Structure& s, const LoadCase& lc, const LoadCaseResult& r, int beam,
                                     int count) {
  if (beam < 0 || beam >= static_cast<int>(s.beams().size()) || beam >= static_cast<int>(r.beam_end_forces.size()))
    return Status::Invalid(fmt::format("beam_stations: no beam #{} in the solved load case '{}'", beam, lc.name));
  if (count < 2)
    return Status::Invalid(fmt::format("{} stations per beam is too few; give at least 2 (the two ends)", count));
  const BeamField field(s, lc, r, beam);
  BeamStations out;
  for (int k = 0; k < count; ++k) out.x.push_back(field.length() * k / (count - 1));
  for (double x : out.x) out.forces.push_back(field.forces(x));
  out.displacement = field.displacements(out.x);
  for (int q = 0; q < 12; ++q) {
    auto value = [&](int k) { return q < 6 ? out.forces[k](q) : out.displacement[k](q - 6); };
    BeamStations::Extreme& e = out.extremes[q];
    e = {value(0), out.x[0], value(0), out.x[0]};
    for (int k = 1; k < count; ++k) {
      if (value(k) > e.max) e.max = value(k), e.x_at_max = out.x[k];
      if (value(k) < e.min) e.min = value(k), e.x_at_min = out.x[k];
    }
  }
  return out;
}

StatusOr<std::vector<std::vector<BeamStations>>> all_beam_stations(const Structure& s, const Solution& sol, int count) {
  std::vector<std::vector<BeamStations>> out;
  for (size_t c = 0; c < sol.cases.size() && c < s.load_cases().size(); ++c) {
    out.emplace_back();
    for (int b = 0; b < static_cast<int>(s.beams().size()); ++b) {
      auto st = beam_stations(s, s.load_cases()[c], sol.cases[c], b, count);
      if (!st.ok()) return st.status();
      out.back().push_back(std::move(*st));
    }
  }
  return out;
}

}  // namespace kinestat::msa
