// gecko._core — the compiled half of the Python package. Each concern binds itself in its own
// file (elliptic.cpp, seta_types.cpp, seta.cpp, friction.cpp); the pure-Python package gecko/ wraps these with
// numpy broadcasting and re-exports them.
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "gecko compiled kernels (private; use the gecko package)";
  m.attr("__version__") = GECKO_VERSION;
  gecko::bindings::bind_elliptic(m);
  gecko::bindings::bind_seta_types(m);
  gecko::bindings::bind_seta(m);
  gecko::bindings::bind_friction(m);
}
