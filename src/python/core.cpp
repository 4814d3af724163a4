// kinestat core: status codes, frames and rigid transfer, stiffness indices (core/*.hpp).
#include "kinestat/core/frame.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/stiffness_indices.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

// The fields of MatrixIndices, shared by both index classes (one implementation over the size).
template <class Indices>
void def_matrix_indices(py::class_<Indices>& c) {
  c.def(py::init<>())
      .def_readonly("det_sign", &Indices::det_sign)
      .def_readonly("log10_abs_det", &Indices::log10_abs_det)
      .def_readonly("determinant", &Indices::determinant, "eq. (7); +-inf on overflow (use log10_abs_det)")
      .def_readonly("trace", &Indices::trace, "eq. (8)")
      .def_readonly("norm_1", &Indices::norm_1, "eq. (9): max column sum of |k_ij|")
      .def_readonly("norm_2", &Indices::norm_2, "eq. (10): spectral norm")
      .def_readonly("norm_frobenius", &Indices::norm_frobenius, "eq. (11)")
      .def_readonly("norm_inf", &Indices::norm_inf, "max row sum of |k_ij|")
      .def_readonly("max_abs_entry", &Indices::max_abs_entry, "eq. (12)")
      .def_readonly("condition_number", &Indices::condition_number, "eq. (13), 2-norm; inf if singular")
      .def_readonly("eigenvalues", &Indices::eigenvalues, "of the symmetric part, ascending")
      .def_readonly("symmetry_error", &Indices::symmetry_error, "||K - K^T||_F / ||K||_F");
}

}  // namespace

void bind_core(py::module_& m) {
  m.attr("DOFS_PER_NODE") = kDofsPerNode;
  m.def("dof_name", &dof_name, py::arg("dof"), "Name of a nodal dof 0..5: 'ux', 'uy', 'uz', 'rx', 'ry', 'rz'.");

  py::enum_<StatusCode>(m, "StatusCode", "What a failed computation reports (the exceptions' .code).")
      .value("OK", StatusCode::kOk)
      .value("INVALID_INPUT", StatusCode::kInvalidInput)
      .value("SINGULAR", StatusCode::kSingular)
      .value("NOT_CONVERGED", StatusCode::kNotConverged)
      .value("INTERNAL", StatusCode::kInternal);

  py::class_<Status>(m, "Status", "A status code and its message (kinestat::Status).")
      .def_property_readonly("ok", &Status::ok)
      .def_property_readonly("code", &Status::code)
      .def_property_readonly("message", &Status::message)
      .def("__repr__", [](const Status& s) { return "Status(" + std::string(s.ok() ? "OK" : s.message()) + ")"; });

  // frame.hpp
  m.def("skew", &skew, py::arg("v"), "Skew-symmetric 3x3 matrix [v]x with [v]x w = v x w.");
  m.def(
      "element_axes",
      [](const Vec3& p1, const Vec3& p2, const Vec3& orientation) -> std::optional<Mat3> {
        Mat3 axes;
        if (!element_axes(p1, p2, orientation, axes)) return std::nullopt;
        return axes;
      },
      py::arg("p1"), py::arg("p2"), py::arg("orientation"),
      "Local axes (columns x, y, z in global coordinates) of a line element from p1 to p2 whose local x-y plane "
      "contains `orientation`; None for a zero length or an orientation parallel to the element.");
  m.def("default_orientation", &default_orientation, py::arg("direction"),
        "Default orientation vector of an element along `direction`: global z, or global y when nearly parallel to z.");
  m.def("rotation6", &rotation6, py::arg("R"), "6x6 block-diagonal diag(R, R) acting on (translation, rotation).");
  m.def(
      "rigid_transfer", &rigid_transfer, py::arg("offset"),
      "A = [I, -[offset]x; 0, I]: the motion of a point at `offset` (m) from a reference point moving by (u, theta).");
  m.def("direction_words", &direction_words, py::arg("v"), "A direction in words: '+y' or '(0.707, 0.707, 0.000)'.");
  m.def("axis_angle", &axis_angle, py::arg("axis"), py::arg("angle"),
        "Rotation matrix about a unit axis by an angle (rad).");

  // stiffness_indices.hpp (Goncalves et al. 2010, eq. 7-13)
  py::class_<StiffnessIndices> indices(m, "StiffnessIndices",
                                       "Stiffness indices of a symmetric matrix (Goncalves et al. 2010, eq. 7-13), in "
                                       "the matrix's units. eigenvalues ascending, eigenvectors as columns.");
  def_matrix_indices(indices);
  indices.def_readonly("size", &StiffnessIndices::size).def_readonly("eigenvectors", &StiffnessIndices::eigenvectors);
  m.def(
      "stiffness_indices",
      [](const MatX& K) {
        if (K.rows() != K.cols()) raise_status(Status::Invalid("stiffness_indices: K must be a square matrix"));
        check(check_finite(K, "K"));
        return stiffness_indices(K);
      },
      py::arg("K"), "Every index of a dense symmetric matrix K.");

  py::class_<CartesianIndices> cartesian(m, "CartesianIndices",
                                         "Indices of a 6x6 Cartesian stiffness (ux uy uz rx ry rz; N/m, N, N m/rad), "
                                         "with the eigenvalues of the translational (N/m) and rotational (N m/rad) "
                                         "3x3 blocks; eigenvalues of the 6x6 mix units.");
  def_matrix_indices(cartesian);
  cartesian.def_readonly("translational_eigenvalues", &CartesianIndices::translational_eigenvalues, "of K[:3, :3], N/m")
      .def_readonly("rotational_eigenvalues", &CartesianIndices::rotational_eigenvalues, "of K[3:, 3:], N m/rad");
  m.def(
      "cartesian_indices",
      [](const Mat6& K) {
        check(check_finite(K, "K"));
        return cartesian_indices(K);
      },
      py::arg("K"), "Indices of a 6x6 Cartesian stiffness. InputError for a non-finite entry.");
}

}  // namespace kinestat::python
