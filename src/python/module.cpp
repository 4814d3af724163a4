// The compiled part of the Python package `kinestat`: kinestat._kinestat with one submodule per C++
// namespace (solver, msa, vjm, fea, mechanisms, io); core and elements (namespace kinestat) at the
// top. The package's __init__.py re-exports them (and python/kinestat/robots.py gathers the robot
// names of mechanisms and io); docs/python.md describes the API.
#include <string>

#include <fmt/format.h>

#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

// Created once at import; the module keeps them alive.
PyObject* kinestat_error = nullptr;
PyObject* input_error = nullptr;
PyObject* singular_error = nullptr;
PyObject* not_converged_error = nullptr;

PyObject* new_exception(py::module_& m, const char* name, PyObject* bases, const char* doc) {
  const std::string qualified = std::string("kinestat.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return type;
}

}  // namespace

void create_exceptions(py::module_& m) {
  kinestat_error = new_exception(m, "KinestatError", PyExc_RuntimeError,
                                 "A kinestat computation failed. Base class of kinestat's exceptions; raised itself "
                                 "for internal failures (the CLI's exit status 1).");
  py::tuple input_bases = py::make_tuple(py::handle(kinestat_error), py::handle(PyExc_ValueError));
  input_error = new_exception(m, "InputError", input_bases.ptr(),
                              "Bad input: a model, file, mesh or value to fix. The message is the CLI's: it names "
                              "the file, line and item (\"FILE:LINE: ITEM: what is wrong; what to do\"). CLI exit "
                              "status 2.");
  singular_error = new_exception(m, "SingularError", kinestat_error,
                                 "The structure or mechanism is singular at this posture: some motion is free. "
                                 "str(e) is the diagnosis in words; e.diagnosis holds it as data (for MSA a "
                                 "msa.SingularityDiagnosis whose modes give the free motions as arrays; for VJM the "
                                 "vjm.CartesianStiffness with its free_directions). CLI exit status 3.");
  not_converged_error = new_exception(m, "NotConvergedError", kinestat_error,
                                      "An iterative method (loaded equilibrium, identification) stopped before its "
                                      "tolerance; the message is its convergence report.");
}

void raise_status(const Status& status, py::object diagnosis) {
  PyObject* type = kinestat_error;
  switch (status.code()) {
    case StatusCode::kInvalidInput:
      type = input_error;
      break;
    case StatusCode::kSingular:
      type = singular_error;
      break;
    case StatusCode::kNotConverged:
      type = not_converged_error;
      break;
    default:
      break;
  }
  py::object error = py::reinterpret_borrow<py::object>(type)(status.message());
  error.attr("diagnosis") = std::move(diagnosis);
  error.attr("code") = status.code();
  PyErr_SetObject(type, error.ptr());
  throw py::error_already_set();
}

void check_index(long index, long size, const char* what) {
  if (index < 0 || index >= size)
    raise_status(Status::Invalid(fmt::format("{}: {} is not in 0..{}", what, index, size - 1)));
}

Eigen::Matrix4d to_matrix4(const Eigen::Isometry3d& T) { return T.matrix(); }

Eigen::Isometry3d from_matrix4(const Eigen::Matrix4d& M) {
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
  const bool last_row = M.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1), 0.0);
  if (!M.allFinite() || !last_row || !(R.transpose() * R).isIdentity(1e-9) || !(R.determinant() > 0.0))
    raise_status(Status::Invalid(
        fmt::format("transform: not a rigid transform (a 4x4 [[R, p], [0, 0, 0, 1]] with R a rotation); got\n{}",
                    fmt::join(M.data(), M.data() + 16, " "))));
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = M.topRightCorner<3, 1>();
  return T;
}

}  // namespace kinestat::python

PYBIND11_MODULE(_kinestat, m) {
  namespace kp = kinestat::python;
  m.doc() =
      "kinestat: stiffness of robots and frames (MSA, VJM, FEA, five-bar, Orthoglide). The C++ API's "
      "namespaces are the submodules solver, msa, vjm, fea, mechanisms, io; core and elements are at the "
      "top. SI units (m, N, rad, Pa) everywhere; see docs/python.md.";
  m.attr("__version__") = KINESTAT_VERSION;
  kp::create_exceptions(m);
  kp::bind_core(m);
  kp::bind_elements(m);
  auto solver = m.def_submodule("solver", "Linear-solver options and factorization reports (C++ kinestat::solver).");
  kp::bind_solver(solver);
  kp::bind_library_versions(solver);
  auto msa =
      m.def_submodule("msa", "Matrix structural analysis: Structure -> solve() -> Solution (C++ kinestat::msa).");
  kp::bind_msa(msa);
  auto vjm = m.def_submodule("vjm", "Virtual joint method: chains, equilibrium, stiffness (C++ kinestat::vjm).");
  kp::bind_vjm(vjm);
  auto fea = m.def_submodule("fea", "FEA link stiffness from tetrahedral meshes (C++ kinestat::fea).");
  kp::bind_fea(fea);
  auto mech = m.def_submodule("mechanisms",
                              "Five-bar and Orthoglide: kinematics, design, stiffness models, "
                              "identification; robots from files (RobotModel); posture kernels "
                              "(C++ kinestat::mechanisms).");
  kp::bind_mechanisms(mech);
  kp::bind_workspace_maps(mech);
  auto io = m.def_submodule("io", "Structure and model files, JSON results, VTK and PNG output (C++ kinestat::io).");
  kp::bind_io(io);
  kp::bind_robots(mech, io);
}
