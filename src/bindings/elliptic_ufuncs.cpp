// numpy ufuncs of gecko/elliptic: F, E, K, R_F, R_D, R_J, R_C with float64 and float32 loops,
// built with the numpy C API (PyUFunc_FromFuncAndData), so that broadcasting, out=, where=,
// dtype=, casting and the GIL are numpy's business. Out-of-domain elements give NaN (the
// kernels' nan_policy); errors="raise" lives in python/gecko/elliptic.py, which names the first
// bad element through the scalar functions bound here (ellint_f_scalar, ...) with the throwing
// policy. The float32 loops run the float instantiation of the kernels (tested to 3 eps(float)).
//
// Threads: a loop call of n elements is cut into contiguous blocks on the one pool
// (gecko/core/parallel.hpp), threads_for(n, ufunc_threads) of them: every element is computed by
// the same code whatever the split, so results are bitwise identical for any thread count. numpy
// has released the GIL around the inner loop already (no object dtypes), so none is touched here.
#include "bindings.hpp"

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>
#include <numpy/ufuncobject.h>

#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

#include "gecko/core/parallel.hpp"
#include "gecko/elliptic.hpp"
#include "vectorize.hpp"

namespace gecko {
namespace bindings {
namespace {

using policies::default_policy;
using policies::nan_policy;

// 0: automatic (threads_for); k > 0: exactly k threads per loop call (capped by n).
std::atomic<int> ufunc_threads{0};

struct kernel_f {
  static constexpr const char* name = "ellint_f";
  template <class T, class P> static T eval(T p, T m, P pol) { return gecko::ellint_f(p, m, pol); }
};
struct kernel_e {
  static constexpr const char* name = "ellint_e";
  template <class T, class P> static T eval(T p, T m, P pol) { return gecko::ellint_e(p, m, pol); }
};
struct kernel_k {
  static constexpr const char* name = "ellint_k";
  template <class T, class P> static T eval(T m, P pol) { return gecko::ellint_k(m, pol); }
};
struct kernel_rf {
  static constexpr const char* name = "carlson_rf";
  template <class T, class P> static T eval(T x, T y, T z, P pol) { return gecko::carlson_rf(x, y, z, pol); }
};
struct kernel_rd {
  static constexpr const char* name = "carlson_rd";
  template <class T, class P> static T eval(T x, T y, T z, P pol) { return gecko::carlson_rd(x, y, z, pol); }
};
struct kernel_rj {
  static constexpr const char* name = "carlson_rj";
  template <class T, class P> static T eval(T x, T y, T z, T p, P pol) { return gecko::carlson_rj(x, y, z, p, pol); }
};
struct kernel_rc {
  static constexpr const char* name = "carlson_rc";
  template <class T, class P> static T eval(T x, T y, P pol) { return gecko::carlson_rc(x, y, pol); }
};

// out[i] = K(in_0[i], ..., in_{nin-1}[i]) over [begin, end), any strides.
template <class K, class T, std::size_t... I>
inline void run_range(char** args, const npy_intp* steps, npy_intp begin, npy_intp end,
                      std::index_sequence<I...>) {
  constexpr std::size_t nin = sizeof...(I);
  char* out = args[nin] + begin * steps[nin];
  char* in[nin == 0 ? 1 : nin] = {(args[I] + begin * steps[I])...};
  for (npy_intp i = begin; i < end; ++i) {
    *reinterpret_cast<T*>(out) = K::eval(*reinterpret_cast<const T*>(in[I])..., nan_policy());
    ((in[I] += steps[I]), ...);
    out += steps[nin];
  }
}

template <class K, class T, std::size_t Nin>
void loop(char** args, const npy_intp* dims, const npy_intp* steps, void*) {
  const npy_intp n = dims[0];
  const auto seq = std::make_index_sequence<Nin>();
  const unsigned nt = threads_for(static_cast<std::size_t>(n), ufunc_threads.load(std::memory_order_relaxed));
  if (nt <= 1) {
    run_range<K, T>(args, steps, 0, n, seq);
    return;
  }
  try {
    gecko::detail::parallel_for_blocks(static_cast<std::size_t>(n), nt, [&](std::size_t b, std::size_t e) {
      run_range<K, T>(args, steps, static_cast<npy_intp>(b), static_cast<npy_intp>(e), seq);
    });
  } catch (...) {
    // Only a failure to start a thread can get here (the kernels do not throw under nan_policy):
    // every block is recomputed serially, with identical results.
    run_range<K, T>(args, steps, 0, n, seq);
  }
}

// Static storage for numpy: function table, data and type signatures of one ufunc.
template <class K, std::size_t Nin>
struct ufunc_tables {
  static PyUFuncGenericFunction funcs[2];
  static void* data[2];
  static char types[2 * (Nin + 1)];
};
template <class K, std::size_t Nin>
PyUFuncGenericFunction ufunc_tables<K, Nin>::funcs[2] = {&loop<K, float, Nin>, &loop<K, double, Nin>};
template <class K, std::size_t Nin>
void* ufunc_tables<K, Nin>::data[2] = {nullptr, nullptr};
template <class K, std::size_t Nin>
char ufunc_tables<K, Nin>::types[2 * (Nin + 1)] = {};

template <class K, std::size_t Nin>
py::object make_ufunc(const char* doc) {
  using tab = ufunc_tables<K, Nin>;
  for (std::size_t i = 0; i <= Nin; ++i) {
    tab::types[i] = NPY_FLOAT;
    tab::types[Nin + 1 + i] = NPY_DOUBLE;
  }
  PyObject* u = PyUFunc_FromFuncAndData(tab::funcs, tab::data, tab::types, 2, static_cast<int>(Nin), 1,
                                        PyUFunc_None, K::name, doc, 0);
  if (!u) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(u);
}

template <class K, std::size_t... I>
PyObject* call_scalar(PyObject* const* args, std::index_sequence<I...>) {
  const double x[sizeof...(I)] = {PyFloat_AsDouble(args[I])...};
  if (PyErr_Occurred()) return nullptr;
  const long errors = PyLong_AsLong(args[sizeof...(I)]);
  if (errors == -1 && PyErr_Occurred()) return nullptr;
  if (errors != 0) return PyFloat_FromDouble(K::eval(x[I]..., nan_policy()));
  try {
    return PyFloat_FromDouble(K::eval(x[I]..., default_policy()));
  } catch (const std::domain_error& e) {
    PyErr_SetString(PyExc_ValueError, e.what());
    return nullptr;
  }
}

template <class K, std::size_t Nin>
PyObject* scalar_fastcall(PyObject*, PyObject* const* args, Py_ssize_t nargs) {
  if (nargs != static_cast<Py_ssize_t>(Nin + 1)) {
    PyErr_Format(PyExc_TypeError, "gecko._core.%s_scalar takes %d arguments (%zd given)", K::name,
                 static_cast<int>(Nin + 1), nargs);
    return nullptr;
  }
  return call_scalar<K>(args, std::make_index_sequence<Nin>());
}

template <class K, std::size_t Nin>
void add_scalar(py::module_& m, const char* name) {
  static PyMethodDef def = {name, reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&scalar_fastcall<K, Nin>)),
                            METH_FASTCALL, "scalar kernel (a, ..., errors): errors 0 raises ValueError, 1 gives NaN"};
  PyObject* f = PyCFunction_NewEx(&def, nullptr, nullptr);
  if (!f) throw py::error_already_set();
  m.attr(name) = py::reinterpret_steal<py::object>(f);
}

}  // namespace

void bind_elliptic_ufuncs(py::module_& m) {
  if (_import_array() < 0) throw py::error_already_set();
  if (_import_umath() < 0) throw py::error_already_set();
  py::module_ u = m.def_submodule("ufuncs", "numpy ufuncs of the elliptic kernels (NaN outside the domain)");
  u.attr("ellint_f") = make_ufunc<kernel_f, 2>("ellint_f(phi, m): F(phi|m), NaN outside the domain");
  u.attr("ellint_e") = make_ufunc<kernel_e, 2>("ellint_e(phi, m): E(phi|m), NaN outside the domain");
  u.attr("ellint_k") = make_ufunc<kernel_k, 1>("ellint_k(m): K(m), NaN for m > 1");
  u.attr("carlson_rf") = make_ufunc<kernel_rf, 3>("carlson_rf(x, y, z): R_F, NaN outside the domain");
  u.attr("carlson_rd") = make_ufunc<kernel_rd, 3>("carlson_rd(x, y, z): R_D, NaN outside the domain");
  u.attr("carlson_rj") = make_ufunc<kernel_rj, 4>("carlson_rj(x, y, z, p): R_J, NaN outside the domain");
  u.attr("carlson_rc") = make_ufunc<kernel_rc, 2>("carlson_rc(x, y): R_C, NaN outside the domain");

  // Scalar entry points f(a, ..., errors): one float per argument, errors = 0 raises ValueError
  // (the std::domain_error's message: argument, value, allowed range), 1 gives NaN. The Python
  // functions call these for plain scalars and to name the first bad element of an array. Plain
  // METH_FASTCALL functions: a pybind11 call costs several times the kernel.
  add_scalar<kernel_f, 2>(m, "ellint_f_scalar");
  add_scalar<kernel_e, 2>(m, "ellint_e_scalar");
  add_scalar<kernel_k, 1>(m, "ellint_k_scalar");
  add_scalar<kernel_rf, 3>(m, "carlson_rf_scalar");
  add_scalar<kernel_rd, 3>(m, "carlson_rd_scalar");
  add_scalar<kernel_rj, 4>(m, "carlson_rj_scalar");
  add_scalar<kernel_rc, 2>(m, "carlson_rc_scalar");

  // Thread count of the ufunc loops: 0 automatic, k > 0 exactly k; returns the previous setting.
  m.def("set_ufunc_threads", [](int k) {
    if (k < 0) throw std::domain_error("gecko.elliptic.set_num_threads: threads = " + std::to_string(k) +
                                       " is out of range: need threads >= 0 (0: automatic)");
    return ufunc_threads.exchange(k);
  }, py::arg("threads"));
}

}  // namespace bindings
}  // namespace gecko
