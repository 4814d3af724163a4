// Robots from files (docs/robots.md): mechanisms.RobotModel with its kinematics (solve_posture),
// VJM chains and posture kernel (mechanisms/robot_model.hpp, robot_kernel.hpp), and
// io.read_robot_model / read_robot_params (io/robot_yaml.hpp). The package's kinestat.robots
// (python/kinestat/robots.py) is the short way in: robots.load(path, params) = io.read_robot_model.
//
// A RobotModel is built once and then only read (as Pinocchio's Model): Python holds it through a
// shared_ptr and sees only its const members, so kernels made from it share it with no copy.
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/mechanisms/robot_model.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

using namespace mechanisms;
// Python's holder; the model is never changed after it is built (no mutating member is bound).
using ModelPtr = std::shared_ptr<RobotModel>;

// What RobotModel.solve returns: the kinematics' verdict and the posture it reached.
struct RobotSolution {
  KinematicsResult result;
  RobotPosture posture;
  VecX task;  // the task values asked for
};

std::vector<std::string> task_names(const RobotModel& m) {
  std::vector<std::string> names;
  for (TaskCoordinate c : m.description().task) names.emplace_back(to_string(c));
  return names;
}

// InputError unless `task` has one finite value per task coordinate (m, rad).
void check_task(const RobotModel& m, const VecX& task, const char* what) {
  const auto names = task_names(m);
  if (task.size() != static_cast<Eigen::Index>(names.size()))
    raise_status(
        Status::Invalid(fmt::format("{}: {} values given; '{}' has {} task coordinates ({}), in m and rad", what,
                                    task.size(), m.description().name, names.size(), fmt::join(names, ", "))));
  if (!task.allFinite())
    raise_status(Status::Invalid(fmt::format("{}: a value is not finite: [{}]", what, fmt::join(task, ", "))));
}

RobotSolution solve(const RobotModel& m, const VecX& task, const std::optional<RobotSolution>& start,
                    bool continuation) {
  check_task(m, task, "solve: task");
  RobotSolution s;
  s.task = task;
  s.posture = start ? start->posture : m.home();
  if (s.posture.q.size() != m.num_coordinates())
    raise_status(Status::Invalid(fmt::format("solve: start has {} joint coordinates; '{}' has {}", s.posture.q.size(),
                                             m.description().name, m.num_coordinates())));
  s.result = without_gil([&] {
    RobotData data = make_robot_data(m);
    return solve_posture(m, task, s.posture, data, continuation);
  });
  return s;
}

// The chains at a solved posture; InputError naming the status otherwise.
std::vector<vjm::Chain> chains_at(const RobotModel& m, const RobotSolution& s) {
  if (s.result.status != KinematicsStatus::kOk)
    raise_status(Status::Invalid(fmt::format("vjm_chains: the posture is {} ({}); the chains need a solved posture",
                                             to_string(s.result.status), s.result.message)));
  if (s.posture.q.size() != m.num_coordinates())
    raise_status(Status::Invalid("vjm_chains: the solution is of another robot"));
  return robot_vjm_chains(m, s.posture);
}

std::unique_ptr<PostureKernel> make_kernel(RobotKernelOptions o) {
  check(validate(o));
  return make_robot_kernel(o);
}

// A dict {name: value} as the reader's overrides (in the file's units), in the dict's order.
io::ParamOverrides overrides(const std::optional<py::dict>& params) {
  io::ParamOverrides o;
  if (!params) return o;
  for (const auto& [key, value] : *params) {
    if (!py::isinstance<py::str>(key))
      raise_status(Status::Invalid(
          fmt::format("params: the key {} is not a parameter name (a str)", py::repr(key).cast<std::string>())));
    double v = 0.0;
    try {
      v = value.cast<double>();
    } catch (const py::cast_error&) {
      raise_status(Status::Invalid(fmt::format("params: '{}' = {} is not a number (give it in the file's units)",
                                               key.cast<std::string>(), py::repr(value).cast<std::string>())));
    }
    if (!std::isfinite(v))
      raise_status(Status::Invalid(fmt::format("params: '{}' = {} is not finite", key.cast<std::string>(), v)));
    o.emplace_back(key.cast<std::string>(), v);
  }
  return o;
}

py::dict params_dict(const std::vector<std::pair<std::string, double>>& values) {
  py::dict d;
  for (const auto& [name, value] : values) d[py::str(name)] = value;
  return d;
}

void bind_model(py::module_& m) {
  py::enum_<KinematicsStatus>(m, "KinematicsStatus")
      .value("OK", KinematicsStatus::kOk)
      .value("UNREACHABLE", KinematicsStatus::kUnreachable)
      .value("SINGULAR", KinematicsStatus::kSingular)
      .value("OTHER_BRANCH", KinematicsStatus::kOtherBranch);

  py::class_<RobotSolution>(m, "RobotSolution",
                            "RobotModel.solve's answer: status ('ok', 'unreachable', 'singular', 'other branch'), the "
                            "joint values q and the tool pose (4x4, m) reached, the singularity measure and why it "
                            "failed (message). Give it as `start` to solve a neighbouring posture from it.")
      .def_property_readonly("status", [](const RobotSolution& s) { return std::string(to_string(s.result.status)); })
      .def_property_readonly(
          "kinematics_status", [](const RobotSolution& s) { return s.result.status; },
          "the status as a KinematicsStatus")
      .def_property_readonly("ok", [](const RobotSolution& s) { return s.result.status == KinematicsStatus::kOk; })
      .def_property_readonly(
          "q", [](const RobotSolution& s) { return s.posture.q; },
          "every joint coordinate (legs in order; m or rad), from home")
      .def_property_readonly(
          "tool", [](const RobotSolution& s) { return to_matrix4(s.posture.tool); },
          "the tool pose, 4x4 homogeneous (m), base frame")
      .def_property_readonly(
          "task", [](const RobotSolution& s) { return s.task; }, "the task values asked for")
      .def_property_readonly(
          "singularity_measure", [](const RobotSolution& s) { return s.result.singularity_measure; },
          "in [0, 1], 0 at a singularity (Type 1 or 2)")
      .def_property_readonly(
          "closed", [](const RobotSolution& s) { return s.result.closed; },
          "q closes the loop on home's working mode, regular: status 'ok', or 'unreachable' with a joint "
          "beyond its limits, or 'other branch' (another assembly mode)")
      .def_property_readonly("iterations", [](const RobotSolution& s) { return s.result.iterations; })
      .def_property_readonly(
          "message", [](const RobotSolution& s) { return s.result.message; }, "why, when not ok")
      .def("__repr__", [](const RobotSolution& s) {
        return fmt::format("<RobotSolution {} q=[{:.6g}]{}>", to_string(s.result.status), fmt::join(s.posture.q, ", "),
                           s.result.message.empty() ? "" : ": " + s.result.message);
      });

  py::class_<RobotModel, ModelPtr>(
      m, "RobotModel",
      "A parallel robot read from a file (docs/robots.md): legs of joints and links, the task coordinates, named "
      "parameters. Built once and then only read; solve() gives a posture, kernel() the posture kernel of maps. "
      "SI units (m, rad) in and out; params in the file's units. io.read_robot_model or robots.load make one.")
      .def_property_readonly("name", [](const RobotModel& r) { return r.description().name; })
      .def_property_readonly(
          "source", [](const RobotModel& r) { return r.description().source; }, "the file")
      .def_property_readonly("task", &task_names, "the task coordinates' names, e.g. ['x', 'y', 'z']")
      .def_property_readonly(
          "params", [](const RobotModel& r) { return params_dict(r.description().params); },
          "{name: value} after evaluation, in the file's units (its `units:`)")
      .def_property_readonly("num_legs", &RobotModel::num_legs)
      .def_property_readonly("leg_names",
                             [](const RobotModel& r) {
                               std::vector<std::string> names;
                               for (const RobotLeg& leg : r.description().legs) names.push_back(leg.name);
                               return names;
                             })
      .def_property_readonly(
          "redundant_equations",
          [](const RobotModel& r) {
            static constexpr const char* kNames[] = {"x", "y", "z", "rx", "ry", "rz"};
            std::vector<std::string> out;
            for (const auto& e : r.redundant_equations())
              out.push_back(r.description().legs[e.leg].name + " " + kNames[e.component]);
            return out;
          },
          "the closure equations that hold by the geometry of an overconstrained robot, e.g. ['leg 2 ry'] "
          "(docs/robots.md, 'Overconstrained robots'); empty for most robots")
      .def_property_readonly("num_coordinates", &RobotModel::num_coordinates, "joint coordinates, all legs")
      .def_property_readonly("coordinate_names",
                             [](const RobotModel& r) {
                               std::vector<std::string> names;
                               for (int k = 0; k < r.num_coordinates(); ++k) names.push_back(r.coordinate_name(k));
                               return names;
                             })
      .def_property_readonly(
          "actuated",
          [](const RobotModel& r) {
            std::vector<bool> a;
            for (const auto& c : r.coordinates()) a.push_back(r.actuated(c));
            return a;
          },
          "per joint coordinate: driven by a motor")
      .def_property_readonly("planar", [](const RobotModel& r) { return r.description().planar; })
      .def_property_readonly("home_task", &RobotModel::home_task, "the task values at home (m, rad)")
      .def_property_readonly(
          "home_tool", [](const RobotModel& r) { return to_matrix4(r.home().tool); }, "the tool pose at home (4x4, m)")
      .def_property_readonly(
          "workspace",
          [](const RobotModel& r) -> py::object {
            if (!r.description().workspace) return py::none();
            return py::cast(*r.description().workspace);
          },
          "the file's map region: [(x lo, hi), (y lo, hi), (z lo, hi)] (m), or None")
      .def_property_readonly("length_scale", &RobotModel::length_scale, "m: the largest joint distance from the base")
      .def_property_readonly(
          "default_map_axes", [](const RobotModel& r) { return default_map_axes(r); },
          "which task coordinate the grid's x, y, z set (-1: none)")
      .def(
          "solve",
          [](const ModelPtr& r, const VecX& task, const std::optional<RobotSolution>& start, bool continuation) {
            return solve(*r, task, start, continuation);
          },
          py::arg("task"), py::arg("start") = py::none(), py::arg("continuation") = true,
          "Every joint value and the tool pose at the task values (m, rad; one per task coordinate) by Newton on the "
          "loop closure, from home (or `start`, a RobotSolution), walking there by continuation (or, with "
          "continuation=False, one Newton solve). Failures are statuses, not exceptions; InputError for a task "
          "vector of the wrong size or not finite.")
      .def(
          "kernel",
          [](const ModelPtr& r, std::optional<VecX> task, std::optional<Vec6> wrench, std::optional<Vec6> displacement,
             std::optional<std::array<int, 3>> map_axes) {
            RobotKernelOptions o;
            o.model = r;
            if (task) check_task(*r, *task, "kernel: task");
            o.task = task.value_or(VecX());
            o.wrench = wrench;
            o.displacement = displacement;
            o.map_axes = map_axes;
            return make_kernel(std::move(o));
          },
          py::arg("task") = py::none(), py::arg("wrench") = py::none(), py::arg("displacement") = py::none(),
          py::arg("map_axes") = py::none(),
          "The posture kernel (VJM) for compute_workspace_map and evaluate_postures, what `kinestat map ROBOT.yaml` "
          "runs: a point's x, y, z set the task coordinates of map_axes (default: the task's x, y, z), the others "
          "keep `task` (default: home's). wrench (N, N m) or displacement (m, rad) at the tool: the loaded mode.")
      .def(
          "vjm_chains", [](const ModelPtr& r, const RobotSolution& s) { return chains_at(*r, s); }, py::arg("solution"),
          "The legs' VJM chains (vjm.Chain) at a solved posture, for the vjm functions; InputError if not solved.")
      .def(
          "vjm_chains",
          [](const ModelPtr& r, const VecX& task) { return chains_at(*r, solve(*r, task, std::nullopt, true)); },
          py::arg("task"), "The same at the task values (m, rad), solved from home.")
      .def("__repr__", [](const RobotModel& r) {
        return fmt::format("<RobotModel '{}': {} legs, task [{}]>", r.description().name, r.num_legs(),
                           fmt::join(task_names(r), ", "));
      });

  py::class_<RobotKernelOptions>(m, "RobotKernelOptions", "make_robot_kernel's options (robot_kernel.hpp).")
      .def(py::init<>())
      .def_property(
          "model", [](const RobotKernelOptions& o) { return std::const_pointer_cast<RobotModel>(o.model); },
          [](RobotKernelOptions& o, const ModelPtr& m) { o.model = m; })
      .def_readwrite("task", &RobotKernelOptions::task, "task values (m, rad) at every point; empty: home's")
      .def_readwrite("map_axes", &RobotKernelOptions::map_axes, "task coordinate set by the grid's x, y, z, or None")
      .def_readwrite("wrench", &RobotKernelOptions::wrench, "loaded mode: external wrench (N, N m), or None")
      .def_readwrite("displacement", &RobotKernelOptions::displacement,
                     "loaded mode: prescribed tool displacement (m, rad), or None");
  m.def("make_robot_kernel", &make_kernel, py::arg("options"),
        "The posture kernel of a RobotModel (RobotModel.kernel() in C++ terms); InputError for bad options.");
  m.def(
      "task_values", [](const ModelPtr& r, const Eigen::Matrix4d& tool) { return task_values(*r, from_matrix4(tool)); },
      py::arg("model"), py::arg("tool"), "The task coordinate values (m, rad) of a tool pose (4x4).");
}

void bind_files(py::module_& io) {
  io.def(
      "read_robot_model",
      [](const std::string& path, const std::optional<py::dict>& params) {
        const io::ParamOverrides o = overrides(params);
        // The links' `fea:` springs computed between reading and building (docs/robots.md); their
        // warnings (a rejected cache entry, recomputed) as RuntimeWarnings once the GIL is back.
        std::vector<std::string> warnings;
        StatusOr<RobotModel> model = without_gil([&]() -> StatusOr<RobotModel> {
          StatusOr<RobotDescription> d = io::read_robot_description(path, o);
          if (!d.ok()) return d.status();
          if (Status s = resolve_robot_fea_springs(*d, {}, [&](const std::string& w) { warnings.push_back(w); });
              !s.ok())
            return s;
          return make_robot_model(std::move(*d));
        });
        for (const std::string& w : warnings)
          if (PyErr_WarnEx(PyExc_RuntimeWarning, w.c_str(), 1) != 0) throw py::error_already_set();
        return std::make_shared<RobotModel>(unwrap(std::move(model)));
      },
      py::arg("path"), py::arg("params") = py::none(),
      "Reads and checks a robot file (docs/robots.md; models/robots/) into a mechanisms.RobotModel, its links' "
      "`fea:` springs computed (meshing and FEA, or their cache); params "
      "({name: value}, the file's units) replace the file's values. InputError 'FILE:LINE: ...' as the CLI prints, "
      "also for a name that is no parameter of the file.");
  io.def(
      "read_robot_params",
      [](const std::string& path) {
        const io::RobotParams p = unwrap(io::read_robot_params(path));
        return py::make_tuple(params_dict(p.values), p.length_unit);
      },
      py::arg("path"), "(params {name: value}, length unit) of a robot file, values in the file's units.");
  io.def(
      "is_robot_file", [](const std::string& path) { return unwrap(io::is_robot_file(path)); }, py::arg("path"),
      "True for a YAML file with a top-level `robot:` key.");
}

}  // namespace

void bind_robots(py::module_& mechanisms, py::module_& io) {
  bind_model(mechanisms);
  bind_files(io);
}

}  // namespace kinestat::python
