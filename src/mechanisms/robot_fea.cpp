// The `fea:` springs of a robot description's links and joints (docs/robots.md): computed after
// reading, before make_robot_model, through fea::compute_link_stiffness and its cache.
#include <fmt/format.h>

#include <map>
#include <variant>

#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/mechanisms/robot_model.hpp"

namespace kinestat::mechanisms {

Status resolve_robot_fea_springs(RobotDescription& d, const std::function<void(const std::string&)>& progress,
                                 const std::function<void(const std::string&)>& warning) {
  std::map<int, Mat6> computed;  // by file entry: a pattern's copies share their mesh and result
  for (RobotLeg& leg : d.legs)
    for (auto& item : leg.items) {
      std::optional<RobotSpring>& spring =
          std::visit([](auto& x) -> std::optional<RobotSpring>& { return x.spring; }, item);
      if (!spring || !spring->fea) continue;
      RobotSpring& s = *spring;
      if (s.stiffness.allFinite()) continue;  // resolved already
      if (const auto it = computed.find(s.fea_entry); s.fea_entry >= 0 && it != computed.end()) {
        s.stiffness = it->second;
        continue;
      }
      fea::LinkStiffnessRequest request = *s.fea;
      request.options.progress = progress;
      StatusOr<fea::LinkStiffnessRun> run = fea::compute_link_stiffness(request);
      if (!run.ok()) {
        // A mesh or region the FEA cannot use is the robot file's fault; a library failure is not.
        const std::string message = s.fea_where + ": " + run.status().message();
        return run.status().code() == StatusCode::kInternal ? Status::Internal(message) : Status::Invalid(message);
      }
      if (warning)
        for (const std::string& w : run->warnings) warning(s.fea_where + ": " + w);
      s.stiffness = run->result.cartesian.stiffness;
      if (!s.stiffness.allFinite())
        return Status::Internal(s.fea_where + ": the FEA gave a stiffness that is not finite");
      if (s.fea_entry >= 0) computed.emplace(s.fea_entry, s.stiffness);
    }
  return Status::Ok();
}

}  // namespace kinestat::mechanisms
