// Lumped (beam) models of a link against its FEA 6x6 stiffness (Pashkevich, Klimchik, Chablat,
// Wenger 2009, section 4.3: one beam is said to approximate the Orthoglide links to ~50 %, four
// beams to ~30 %). For each link of meshes/ (foot and parallelogram bar, with the plain bar and
// tube as controls where beam theory is known to hold) the program prints, before the timings:
//   - the FEA stiffness (rigid reference coupling) on two meshes, and their largest diagonal change;
//   - the relative difference (K_beam - K_FEA) / K_FEA of the six diagonal terms and of the main
//     couplings (|K_ij| / sqrt(K_ii K_jj) > 0.2 in the FEA) for a one-beam and a four-beam chain;
//   - the relative difference of the sorted eigenvalues of K (SI units, so they mix N/m and
//     N m/rad: compare them link against link, not across dof types).
// The beam chains are vjm::serial_link_spring chains of Timoshenko cantilevers; their sections are
// read from the link dimensions in docs/fea.md (table "Geometry"), chosen as documented next to
// each link below. Steel (E = 210 GPa, nu = 0.3) throughout: the ratios barely depend on it.
// Then the Orthoglide's Cartesian 6x6 at Q0 (mechanisms::orthoglide_stiffness, both architectures)
// with the FEA foot and bar springs (and, to separate geometry from modelling, the beam chains of the
// same meshes) in place of the model's default beam springs: ratios of diagonal terms and eigenvalues.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "kinestat/core/frame.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/region.hpp"
#include "kinestat/fea/surface_mesher.hpp"
#include "kinestat/mechanisms/orthoglide_stiffness.hpp"
#include "kinestat/vjm/link_spring.hpp"

namespace {

using namespace kinestat;

const Material kSteel = Material::from_E_nu("steel", 210e9, 0.3);
constexpr const char* kDofNames[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};

// A straight beam segment from `from` to `to` (m, link frame, in the link's x-z plane): local x along
// the segment, local y = the link's y, so a rectangle's b is its extent along the link's y.
struct Segment {
  Vec3 from, to;
  Section section;
};

// The spring of the reference point relative to the clamp, link axes, about the reference point:
// a serial chain (rigid offsets where the segments do not meet, e.g. inside a rigidly coupled region).
StatusOr<Mat6> beam_link_spring(const std::vector<Segment>& segments, const Vec3& reference_point,
                                const Material& material = kSteel) {
  vjm::Chain chain("beam model");
  Vec3 at = segments.front().from;
  for (const Segment& s : segments) {
    if ((s.from - at).norm() > 0) chain.add_translation(s.from - at, "rigid offset");
    const Vec3 x = (s.to - s.from).normalized();
    vjm::Transform axes = vjm::Transform::Identity();
    axes.linear() << x, Vec3::UnitY(), x.cross(Vec3::UnitY());
    chain.add_transform(axes, "beam axes");
    const double length = (s.to - s.from).norm();
    chain.add_translation(length * Vec3::UnitX(), "beam");
    chain.add_spring(vjm::cantilever_spring(material, s.section, length, BeamTheory::kTimoshenko), "beam");
    chain.add_transform(axes.inverse(), "link axes");
    at = s.to;
  }
  if ((reference_point - at).norm() > 0) chain.add_translation(reference_point - at, "rigid offset");
  return vjm::serial_link_spring(chain);
}

struct LinkCase {
  std::string file;  // in meshes/
  fea::Region clamp, reference;
  Vec3 reference_point;           // m
  double coarse_size, fine_size;  // m
  std::vector<Segment> one_beam, four_beams;
  std::string sections;  // how the sections were chosen
};

Vec3 mm(double x, double y, double z) { return 1e-3 * Vec3(x, y, z); }

// Controls: a prismatic link along x, clamped at x = 0, reference face at x = length (m); one beam
// is the exact lumped model and four equal beams are the same model.
LinkCase prismatic_case(std::string file, double length, const Section& s, double coarse, double fine,
                        std::string sections) {
  const Vec3 end = length * Vec3::UnitX();
  LinkCase c{std::move(file),
             fea::Region::plane(Vec3::Zero(), Vec3::UnitX()),
             fea::Region::plane(end, Vec3::UnitX()),
             end,
             coarse,
             fine,
             {{Vec3::Zero(), end, s}},
             {},
             std::move(sections)};
  for (int i = 0; i < 4; ++i) c.four_beams.push_back({end * i / 4.0, end * (i + 1) / 4.0, s});
  return c;
}

std::vector<LinkCase> link_cases() {
  std::vector<LinkCase> cases;
  cases.push_back(prismatic_case("bar.off", 0.2, rectangle_section(0.020, 0.030), 6e-3, 4e-3,
                                 "20 x 30 mm rectangle, 1 x 200 or 4 x 50 mm"));
  cases.push_back(prismatic_case("tube.off", 0.3, tube_section(0.040, 0.004), 7.5e-3, 5e-3,
                                 "tube D40 x 4 mm, 1 x 300 or 4 x 75 mm"));
  {  // Foot: clamped face x = 0 (centre z = 7.5 mm), reference = the bore (x 102.5, z 30 mm).
     // One beam: the straight line between them with the base's 50 x 15 mm section. Four beams
     // along the centre line of the material: the base in two halves (50 x 15 mm), the step along
     // x to below the bore (50 wide, the step's full 45 mm height), then up to the bore (50 mm
     // along y, 35 mm along x: the step's width).
    const Section base = rectangle_section(0.050, 0.015);
    cases.push_back(LinkCase{"foot.off",
                             fea::Region::plane(Vec3::Zero(), Vec3::UnitX()),
                             fea::Region::box(mm(94, -25, 21), mm(111, 25, 39)),
                             mm(102.5, 0, 30),
                             5e-3,
                             3.5e-3,
                             {{mm(0, 0, 7.5), mm(102.5, 0, 30), base}},
                             {{mm(0, 0, 7.5), mm(42.5, 0, 7.5), base},
                              {mm(42.5, 0, 7.5), mm(85, 0, 7.5), base},
                              {mm(85, 0, 7.5), mm(102.5, 0, 7.5), rectangle_section(0.050, 0.045)},
                              {mm(102.5, 0, 7.5), mm(102.5, 0, 30), rectangle_section(0.050, 0.035)}},
                             "1: base 50x15 mm on the straight line; 4: base 2x(50x15), step 50x45, riser 50x35"});
  }
  {  // Parallelogram bar: bores 310.6 mm apart, both coupled through 13 mm boxes (rigid to 6.5 mm
     // from each bore axis). One beam: the 20 x 10 mm bar from bore axis to bore axis. Four beams:
     // rigid to 6.5 mm, boss to 15 mm (the bar's 20 mm width, the boss's 16 mm height), the bar in
     // two halves, boss, rigid.
    const double L = 310.6;
    const Section bar = rectangle_section(0.020, 0.010), boss = rectangle_section(0.020, 0.016);
    cases.push_back(LinkCase{"parallelogram_bar.off",
                             fea::Region::box(mm(-6.5, -6.5, -8), mm(6.5, 6.5, 8)),
                             fea::Region::box(mm(L - 6.5, -6.5, -8), mm(L + 6.5, 6.5, 8)),
                             mm(L, 0, 0),
                             4e-3,
                             3e-3,
                             {{Vec3::Zero(), mm(L, 0, 0), bar}},
                             {{mm(6.5, 0, 0), mm(15, 0, 0), boss},
                              {mm(15, 0, 0), mm(L / 2, 0, 0), bar},
                              {mm(L / 2, 0, 0), mm(L - 15, 0, 0), bar},
                              {mm(L - 15, 0, 0), mm(L - 6.5, 0, 0), boss}},
                             "1: bar 20x10 mm axis to axis; 4: boss 20x16 (6.5-15 mm), bar 2x(20x10), boss"});
  }
  return cases;
}

StatusOr<fea::LinkStiffness> fea_link(const LinkCase& c, double size, const Material& material = kSteel) {
  fea::MeshingOptions mo;
  mo.size = size;
  StatusOr<fea::TetMesh> mesh = fea::mesh_surface_file(std::string(KINESTAT_SOURCE_DIR) + "/meshes/" + c.file, mo);
  if (!mesh.ok()) return Status::Invalid(fmt::format("meshing at size {} mm: {}", size * 1e3, mesh.status().message()));
  fea::LinkStiffnessOptions o;
  o.clamp = c.clamp;
  o.reference = c.reference;
  o.reference_point = c.reference_point;
  o.keep_fields = false;
  StatusOr<fea::LinkStiffness> r = fea::link_stiffness(*mesh, material, o);
  if (!r.ok()) return Status::Invalid(fmt::format("FEA at size {} mm: {}", size * 1e3, r.status().message()));
  return r;
}

Vec6 eigenvalues(const Mat6& K) { return Eigen::SelfAdjointEigenSolver<Mat6>(0.5 * (K + K.transpose())).eigenvalues(); }

std::string percent(double beam, double reference) {
  return fmt::format("{:+7.1f}%", 100.0 * (beam / reference - 1.0));
}

// Prints the comparison of one link; returns false when a model failed.
bool compare_link(const LinkCase& c) {
  StatusOr<fea::LinkStiffness> coarse = fea_link(c, c.coarse_size), fine = fea_link(c, c.fine_size);
  StatusOr<Mat6> one = beam_link_spring(c.one_beam, c.reference_point);
  StatusOr<Mat6> four = beam_link_spring(c.four_beams, c.reference_point);
  for (const Status& s : {coarse.status(), fine.status(), one.status(), four.status()})
    if (!s.ok()) {
      std::printf("%s: %s\n", c.file.c_str(), s.message().c_str());
      return false;
    }
  const Mat6& K = fine->cartesian.stiffness;
  double mesh_change = 0.0;
  for (int i = 0; i < 6; ++i)
    mesh_change = std::max(mesh_change, std::abs(coarse->cartesian.stiffness(i, i) / K(i, i) - 1.0));
  std::printf(
      "\n== %s  (FEA: quadratic tets, size %.1f mm, %d dofs; largest diagonal change from size %.1f mm "
      "(%d dofs): %.1f %%)\n   beam sections: %s\n",
      c.file.c_str(), c.fine_size * 1e3, fine->num_dofs, c.coarse_size * 1e3, coarse->num_dofs, 100.0 * mesh_change,
      c.sections.c_str());
  std::printf("   %-8s %14s %10s %10s\n", "entry", "K_FEA [SI]", "1 beam", "4 beams");
  for (int i = 0; i < 6; ++i)
    std::printf("   %-8s %14.4e %10s %10s\n", fmt::format("{}-{}", kDofNames[i], kDofNames[i]).c_str(), K(i, i),
                percent((*one)(i, i), K(i, i)).c_str(), percent((*four)(i, i), K(i, i)).c_str());
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j)
      if (std::abs(K(i, j)) > 0.2 * std::sqrt(K(i, i) * K(j, j)))
        std::printf("   %-8s %14.4e %10s %10s\n", fmt::format("{}-{}", kDofNames[i], kDofNames[j]).c_str(), K(i, j),
                    percent((*one)(i, j), K(i, j)).c_str(), percent((*four)(i, j), K(i, j)).c_str());
  const Vec6 e = eigenvalues(K), e1 = eigenvalues(*one), e4 = eigenvalues(*four);
  for (int i = 0; i < 6; ++i)
    std::printf("   %-8s %14.4e %10s %10s\n", fmt::format("eig {}", i + 1).c_str(), e(i), percent(e1(i), e(i)).c_str(),
                percent(e4(i), e(i)).c_str());
  return true;
}

// The Orthoglide's link springs from meshes/, rotated from the mesh axes into the frames
// OrthoglideStiffnessModel documents for its overrides. Both 6x6 are about the distal bore axis,
// the point where the chain's spring acts, so only the axes turn:
// K_chain = T K_mesh T^T, T = rotation6(R), R's columns = the mesh axes in chain axes.
//   foot: mesh x (clamp to bore) = chain x (along the slider axis, towards the workspace); the bore
//     (mesh y) holds the first joint, whose axis is chain z: R = R_x(+90 deg) (mesh z = chain -y).
//   bar: mesh x (bore to bore) = chain x; the pin axis (mesh z) = chain y: R = R_x(-90 deg).
struct OrthoglideLinks {
  Mat6 foot, bar;
};

Mat6 to_chain_axes(const Mat6& K_mesh, double angle_about_x) {
  const Mat6 T = rotation6(Eigen::AngleAxisd(angle_about_x, Vec3::UnitX()).toRotationMatrix());
  return T * K_mesh * T.transpose();
}

enum class LinkSource { kFea, kOneBeam, kFourBeams };

// Foot and bar springs of the meshes' geometry with the model's materials: FEA at the fine size or
// the beam chains of link_cases().
StatusOr<OrthoglideLinks> mesh_links(const mechanisms::OrthoglideStiffnessModel& m, LinkSource source) {
  const std::vector<LinkCase> cases = link_cases();
  const LinkCase &foot = cases[2], &bar = cases[3];
  StatusOr<Mat6> Kf = Status::Ok(), Kb = Status::Ok();
  if (source == LinkSource::kFea) {
    StatusOr<fea::LinkStiffness> f = fea_link(foot, foot.fine_size, m.foot_material);
    StatusOr<fea::LinkStiffness> b = fea_link(bar, bar.fine_size, m.bar_material);
    if (!f.ok()) return f.status();
    if (!b.ok()) return b.status();
    Kf = f->cartesian.stiffness;
    Kb = b->cartesian.stiffness;
  } else {
    const bool one = source == LinkSource::kOneBeam;
    Kf = beam_link_spring(one ? foot.one_beam : foot.four_beams, foot.reference_point, m.foot_material);
    Kb = beam_link_spring(one ? bar.one_beam : bar.four_beams, bar.reference_point, m.bar_material);
  }
  if (!Kf.ok()) return Kf.status();
  if (!Kb.ok()) return Kb.status();
  return OrthoglideLinks{to_chain_axes(*Kf, EIGEN_PI / 2), to_chain_axes(*Kb, -EIGEN_PI / 2)};
}

// Prints K_variant / K_default - 1 of the Orthoglide's unloaded 6x6 at Q0; false when a model failed.
bool compare_orthoglide() {
  using mechanisms::OrthoglideArchitecture;
  const mechanisms::OrthoglideStiffnessModel model;
  const Section &fs = model.foot_section, &bs = model.bar_section;
  std::printf(
      "\n== Orthoglide, unloaded Cartesian stiffness at Q0 (p = 0), (K / K_default - 1): link springs from\n"
      "   meshes/ with the model's materials (foot %s, bar %s) against the model's default beam springs\n"
      "   (foot: A %.0f mm2, Iy = Iz %.3g mm4, %.1f mm along the slider axis;\n"
      "   bar: A %.0f mm2, Iy = Iz %.3g mm4, L = %.1f mm; the 3-PUU leg = 2 bars)\n",
      model.foot_material.id.c_str(), model.bar_material.id.c_str(), fs.A * 1e6, fs.Iy * 1e12, model.foot_length * 1e3,
      bs.A * 1e6, bs.Iy * 1e12, model.link_length * 1e3);
  std::printf(
      "   GEOMETRY DIFFERS: foot.off is an L bracket (base 50 x 15 mm, bore 102.5 mm along and 22.5 mm\n"
      "   off the clamped face's centre; the chain puts the joint on the slider axis, no offset),\n"
      "   parallelogram_bar.off a 20 x 10 mm rectangle with bosses (same length). 'FEA' mixes geometry and\n"
      "   modelling error; 'mesh n b.' (the meshes' n-beam chains) is the geometry change alone.\n");
  std::vector<mechanisms::OrthoglideStiffnessModel> models(4, model);  // default, FEA, 1 beam, 4 beams
  const std::array sources{LinkSource::kFea, LinkSource::kOneBeam, LinkSource::kFourBeams};
  for (int v = 0; v < 3; ++v) {
    StatusOr<OrthoglideLinks> links = mesh_links(model, sources[v]);
    if (!links.ok()) {
      std::printf("   %s\n", links.status().message().c_str());
      return false;
    }
    models[v + 1].foot_spring = links->foot;
    models[v + 1].bar_spring = links->bar;
  }
  for (OrthoglideArchitecture a : {OrthoglideArchitecture::kPUU, OrthoglideArchitecture::kPRPaR}) {
    std::vector<Mat6> K;
    for (const mechanisms::OrthoglideStiffnessModel& m : models) {
      StatusOr<mechanisms::OrthoglideStiffness> s = mechanisms::orthoglide_stiffness(m, a, Vec3::Zero(), Vec6::Zero());
      const Status& st = s.ok() ? s->unloaded.status : s.status();
      if (!st.ok()) {
        std::printf("   %s\n", st.message().c_str());
        return false;
      }
      K.push_back(s->unloaded.stiffness);
    }
    std::printf("   %-8s %-8s %14s %10s %10s %10s\n", a == OrthoglideArchitecture::kPUU ? "3-PUU" : "3-PRPaR", "entry",
                "K_default [SI]", "FEA", "mesh 1 b.", "mesh 4 b.");
    const std::array e{eigenvalues(K[0]), eigenvalues(K[1]), eigenvalues(K[2]), eigenvalues(K[3])};
    for (int i = 0; i < 12; ++i) {
      // Rows 0-5: diagonal terms; 6-11: sorted eigenvalues.
      auto value = [&](int v) { return i < 6 ? K[v](i, i) : e[v](i - 6); };
      const std::string name = i < 6 ? fmt::format("{}-{}", kDofNames[i], kDofNames[i]) : fmt::format("eig {}", i - 5);
      std::printf("   %-8s %-8s %14.4e %10s %10s %10s\n", "", name.c_str(), value(0),
                  percent(value(1), value(0)).c_str(), percent(value(2), value(0)).c_str(),
                  percent(value(3), value(0)).c_str());
    }
  }
  return true;
}

// Cost of the lumped model, for comparison with the FEA run (bench_fea).
void BM_FourBeamLinkSpring(benchmark::State& state) {
  const LinkCase c = link_cases()[3];
  for (auto _ : state) benchmark::DoNotOptimize(beam_link_spring(c.four_beams, c.reference_point));
}
BENCHMARK(BM_FourBeamLinkSpring)->Unit(benchmark::kMicrosecond);

// Meshing + FEA of the parallelogram bar at the comparison's fine size.
void BM_FeaLinkStiffness(benchmark::State& state) {
  const LinkCase c = link_cases()[3];
  int dofs = 0;
  for (auto _ : state) {
    StatusOr<fea::LinkStiffness> r = fea_link(c, c.fine_size);
    if (!r.ok())
      state.SkipWithError(r.status().message().c_str());
    else
      dofs = r->num_dofs;
  }
  state.counters["dofs"] = dofs;
}
BENCHMARK(BM_FeaLinkStiffness)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  std::printf(
      "Link 6x6 stiffness: beam chains against FEA (rigid reference coupling), steel; "
      "(K_beam / K_FEA - 1) per entry, K in N/m, N/rad, N m/rad\n");
  bool ok = true;
  for (const LinkCase& c : link_cases()) ok &= compare_link(c);
  ok &= compare_orthoglide();
  std::printf("\n");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return ok ? 0 : 1;
}
