// Shared by the binding files of the Python module kinestat._kinestat: one bind_* function per C++
// namespace (the Python submodules mirror them, as Pinocchio's bindings mirror its C++ API), the
// translation of a failed Status into a Python exception, and conversions to NumPy arrays.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <Eigen/Geometry>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"

namespace kinestat::mechanisms {
enum class MapField : int;
class PostureKernel;
}  // namespace kinestat::mechanisms

namespace kinestat::python {

namespace py = pybind11;

// kinestat (core, elements), kinestat.solver, .msa, .vjm, .fea, .mechanisms, .io.
void bind_core(py::module_& m);
void bind_elements(py::module_& m);
void bind_solver(py::module_& m);
void bind_msa(py::module_& m);
void bind_vjm(py::module_& m);
void bind_fea(py::module_& m);
void bind_mechanisms(py::module_& m);
void bind_io(py::module_& m);
// Workspace maps and the five-bar design sweep, into kinestat.mechanisms (workspace_map.cpp).
void bind_workspace_maps(py::module_& mechanisms);
// Robots from files: RobotModel and its kernel into kinestat.mechanisms, read_robot_model into
// kinestat.io (robots.cpp).
void bind_robots(py::module_& mechanisms, py::module_& io);
// True for a posture kernel written in Python (a subclass of mechanisms.PostureKernel) or a clone
// of one: its evaluate() needs the GIL, so sweeps run it on one thread (mechanisms.cpp).
bool is_python_kernel(const mechanisms::PostureKernel& kernel);
// A map field given as a MapField or by its name ("k_t_min"); InputError listing the names otherwise.
using MapFieldArg = std::variant<mechanisms::MapField, std::string>;
mechanisms::MapField map_field(const MapFieldArg& f);
// The Cartesian stiffness types of msa and vjm, in one file (cartesian_stiffness.cpp) because the
// library is about to merge them into one core type: only that file changes then.
void bind_msa_cartesian_stiffness(py::module_& msa);
void bind_vjm_cartesian_stiffness(py::module_& vjm);
// Linear buckling (msa/buckling.hpp, buckling.cpp) and vibration modes (msa/modes.hpp, modes.cpp),
// into kinestat.msa: one binding file per header.
void bind_msa_buckling(py::module_& msa);
void bind_msa_modes(py::module_& msa);
// The library versions (solver/library_versions.hpp, library_versions.cpp) into kinestat.solver.
void bind_library_versions(py::module_& solver);

// The exception classes, created in module.cpp: KinestatError and its subclasses InputError,
// SingularError, NotConvergedError.
void create_exceptions(py::module_& m);

// Raises the exception of a failed status: InputError (kInvalidInput, the same "FILE:LINE: ..."
// message the CLI prints), SingularError (kSingular; `diagnosis` becomes its .diagnosis),
// NotConvergedError (kNotConverged), KinestatError (kInternal). Needs the GIL.
[[noreturn]] void raise_status(const Status& status, py::object diagnosis = py::none());

inline void check(const Status& status) {
  if (!status.ok()) raise_status(status);
}

template <class T>
T unwrap(StatusOr<T>&& r) {
  if (!r.ok()) raise_status(r.status());
  return std::move(r).value();
}

// Indices and sizes are checked before they reach C++ code that trusts them (an out-of-range index
// there would crash the interpreter): InputError "WHAT: INDEX is not in 0..SIZE-1".
void check_index(long index, long size, const char* what);

// Runs f() with the GIL released (long computations that touch no Python object), so that other
// Python threads run meanwhile.
template <class F>
auto without_gil(F&& f) {
  py::gil_scoped_release release;
  return f();
}

// A list of fixed-size vectors as one (n, N) array (a copy), and back.
template <int N>
py::array_t<double> rows(const std::vector<Eigen::Matrix<double, N, 1>>& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(N)});
  auto w = a.template mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < w.shape(0); ++i)
    for (int j = 0; j < N; ++j) w(i, j) = v[static_cast<size_t>(i)](j);
  return a;
}

template <int N>
using RowsRef = Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, N, Eigen::RowMajor>>;

template <int N>
std::vector<Eigen::Matrix<double, N, 1>> from_rows(const RowsRef<N>& a) {
  std::vector<Eigen::Matrix<double, N, 1>> v(static_cast<size_t>(a.rows()));
  for (Eigen::Index i = 0; i < a.rows(); ++i) v[static_cast<size_t>(i)] = a.row(i).transpose();
  return v;
}

// Rigid transforms (vjm::Transform) travel as 4x4 homogeneous matrices.
Eigen::Matrix4d to_matrix4(const Eigen::Isometry3d& T);
// kInvalidInput (InputError) unless the last row is (0 0 0 1) and the rotation block orthonormal.
Eigen::Isometry3d from_matrix4(const Eigen::Matrix4d& M);

}  // namespace kinestat::python
