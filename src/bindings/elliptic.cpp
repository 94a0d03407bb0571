// Python bindings of gecko/elliptic: flat float64 arrays in, a float64 array out, the loop run
// without the GIL on the one pool (vectorize.hpp). Broadcasting, scalars and the `errors=` keyword live in python/gecko/elliptic.py.
#include <cstddef>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "bindings.hpp"
#include "vectorize.hpp"
#include "gecko/elliptic.hpp"

namespace gecko {
namespace bindings {
namespace {

// Binds name(arrays..., errors) choosing the policy once per call, outside the loop.
template <class Raise, class Nan, class... Arrays>
py::array_t<double> dispatch(int errors, Raise raise, Nan nan, const Arrays&... in) {
  if (errors == static_cast<int>(on_error::nan)) return map_elements(nan, 0, in...);
  return map_elements(raise, 0, in...);
}

using policies::default_policy;
using policies::nan_policy;

}  // namespace

void bind_elliptic(py::module_& m) {
  bind_elliptic_ufuncs(m);
  m.def("ellint_f", [](const darray& phi, const darray& mm, int errors) {
    return dispatch(errors, [](double p, double q) { return gecko::ellint_f(p, q, default_policy()); },
                    [](double p, double q) { return gecko::ellint_f(p, q, nan_policy()); }, phi, mm);
  }, py::arg("phi"), py::arg("m"), py::arg("errors") = 0);
  m.def("ellint_e", [](const darray& phi, const darray& mm, int errors) {
    return dispatch(errors, [](double p, double q) { return gecko::ellint_e(p, q, default_policy()); },
                    [](double p, double q) { return gecko::ellint_e(p, q, nan_policy()); }, phi, mm);
  }, py::arg("phi"), py::arg("m"), py::arg("errors") = 0);
  m.def("ellint_k", [](const darray& mm, int errors) {
    return dispatch(errors, [](double q) { return gecko::ellint_k(q, default_policy()); },
                    [](double q) { return gecko::ellint_k(q, nan_policy()); }, mm);
  }, py::arg("m"), py::arg("errors") = 0);
  // Both complete integrals from one call; returned as the pair (E, K) of arrays.
  m.def("ellint_ek", [](const darray& mm, int errors) {
    const py::ssize_t n = mm.size();
    py::array_t<double> e(n), k(n);
    double* pe = e.mutable_data();
    double* pk = k.mutable_data();
    const double* q = mm.data();
    for_each_element(static_cast<std::size_t>(n), threads_for(static_cast<std::size_t>(n), 0), [&](std::size_t i) {
      const auto r = errors == static_cast<int>(on_error::nan) ? gecko::ellint_ek(q[i], nan_policy())
                                                               : gecko::ellint_ek(q[i], default_policy());
      pe[i] = r.E;
      pk[i] = r.K;
    });
    return py::make_tuple(e, k);
  }, py::arg("m"), py::arg("errors") = 0);
  m.def("carlson_rf", [](const darray& x, const darray& y, const darray& z, int errors) {
    return dispatch(errors, [](double a, double b, double c) { return gecko::carlson_rf(a, b, c, default_policy()); },
                    [](double a, double b, double c) { return gecko::carlson_rf(a, b, c, nan_policy()); }, x, y, z);
  }, py::arg("x"), py::arg("y"), py::arg("z"), py::arg("errors") = 0);
  m.def("carlson_rd", [](const darray& x, const darray& y, const darray& z, int errors) {
    return dispatch(errors, [](double a, double b, double c) { return gecko::carlson_rd(a, b, c, default_policy()); },
                    [](double a, double b, double c) { return gecko::carlson_rd(a, b, c, nan_policy()); }, x, y, z);
  }, py::arg("x"), py::arg("y"), py::arg("z"), py::arg("errors") = 0);
  m.def("carlson_rj", [](const darray& x, const darray& y, const darray& z, const darray& p, int errors) {
    return dispatch(errors,
                    [](double a, double b, double c, double d) { return gecko::carlson_rj(a, b, c, d, default_policy()); },
                    [](double a, double b, double c, double d) { return gecko::carlson_rj(a, b, c, d, nan_policy()); },
                    x, y, z, p);
  }, py::arg("x"), py::arg("y"), py::arg("z"), py::arg("p"), py::arg("errors") = 0);
  m.def("carlson_rc", [](const darray& x, const darray& y, int errors) {
    return dispatch(errors, [](double a, double b) { return gecko::carlson_rc(a, b, default_policy()); },
                    [](double a, double b) { return gecko::carlson_rc(a, b, nan_policy()); }, x, y);
  }, py::arg("x"), py::arg("y"), py::arg("errors") = 0);
}

}  // namespace bindings
}  // namespace gecko
