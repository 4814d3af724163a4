// Fuzz harness: the robot file reader (io::read_robot_description_string), the model's checks
// (mechanisms::make_robot_model) and, for a model that builds, the kernel at home and at a point
// beside it: a status, never a crash, and no number that is not finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>

#include "fuzz_checks.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kinestat;
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto d = io::read_robot_description_string(text, "fuzz.yaml");
  if (fuzz::refused(d)) return 0;
  int coordinates = 0;
  for (const auto& leg : d->legs) coordinates += static_cast<int>(leg.items.size()) * 3;
  if (coordinates > 300) return 0;  // keeps each input fast (dense Jacobians of this size)
  auto m = mechanisms::make_robot_model(std::move(*d));
  if (fuzz::refused(m)) return 0;
  mechanisms::RobotKernelOptions o;
  o.model = std::make_shared<const mechanisms::RobotModel>(std::move(*m));
  if (!mechanisms::validate(o).ok()) return 0;
  const auto kernel = mechanisms::make_robot_kernel(o);
  const Vec3 home = o.model->description().tool;
  for (const Vec3& p : {home, Vec3(home + Vec3::Constant(0.01 * o.model->length_scale()))}) {
    const mechanisms::PostureResult r = kernel->evaluate(p);
    if (r.status == mechanisms::PostureStatus::kOk && (!r.stiffness.allFinite() || !r.compliance.allFinite()))
      std::abort();
    if (!std::isfinite(r.singularity_measure)) std::abort();
  }
  return 0;
}
