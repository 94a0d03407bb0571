// Shared declarations and helpers of the binding files.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>

namespace gecko {
namespace bindings {

namespace py = pybind11;

void bind_elliptic(py::module_& m);
void bind_seta_types(py::module_& m);  // the design type and status enums, before their users
void bind_seta(py::module_& m);
void bind_friction(py::module_& m);

// Flat, C-contiguous float64 input: the Python layer broadcasts and flattens first, so the
// C++ loops see plain 1-D arrays of equal length and can run without the GIL.
using darray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Error handling choice passed down from Python: errors="raise" -> 0, errors="nan" -> 1.
enum class on_error : int { raise = 0, nan = 1 };

}  // namespace bindings
}  // namespace gecko
