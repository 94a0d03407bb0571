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
//
// SIMD: the float64 loops of F, E and R_F run the vector kernels of elliptic_simd.hpp at the level
// picked once at import (the best the CPU has, or GECKO_SIMD=scalar|sse|avx2|avx512|
// avx512-sqrt-unit, or set_simd_level); every element's result is independent of its neighbours
// there as well, so the bitwise thread independence holds at every level.
#include "bindings.hpp"

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>
#include <numpy/arrayscalars.h>
#include <numpy/ufuncobject.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>

#include "gecko/core/parallel.hpp"
#include "elliptic_simd.hpp"
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
  static constexpr simd::batch_fn simd::kernels::*simd_slot = &simd::kernels::ellint_f;
  template <class T, class P> static T eval(T p, T m, P pol) { return gecko::ellint_f(p, m, pol); }
};
struct kernel_e {
  static constexpr const char* name = "ellint_e";
  static constexpr simd::batch_fn simd::kernels::*simd_slot = &simd::kernels::ellint_e;
  template <class T, class P> static T eval(T p, T m, P pol) { return gecko::ellint_e(p, m, pol); }
};
struct kernel_k {
  static constexpr const char* name = "ellint_k";
  template <class T, class P> static T eval(T m, P pol) { return gecko::ellint_k(m, pol); }
};
struct kernel_rf {
  static constexpr const char* name = "carlson_rf";
  static constexpr simd::batch_fn simd::kernels::*simd_slot = &simd::kernels::carlson_rf;
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

// ---- SIMD level ------------------------------------------------------------------------------
constexpr int n_levels = 5;
constexpr const char* level_names[n_levels] = {"scalar", "sse", "avx2", "avx512", "avx512-sqrt-unit"};
const simd::kernels* level_table[n_levels] = {nullptr, nullptr, nullptr, nullptr, nullptr};
int best_level = simd::scalar;
std::atomic<int> active_level{simd::scalar};

void detect_levels() {
#if defined(GECKO_SIMD_X86)
  __builtin_cpu_init();
  level_table[simd::sse] = simd::kernels_sse();  // SSE2 is part of x86-64
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) level_table[simd::avx2] = simd::kernels_avx2();
  if (__builtin_cpu_supports("avx512f")) {
    level_table[simd::avx512] = simd::kernels_avx512();
    level_table[simd::avx512_sqrt_unit] = simd::kernels_avx512_sqrt_unit();
  }
#endif
  for (int l = simd::avx512; l > simd::scalar; --l)
    if (level_table[l]) {
      best_level = l;
      break;
    }
#if defined(GECKO_SIMD_X86)
  // The two AVX-512 schedules give the same bits; which is faster depends on the chip
  // (elliptic_simd_avx512.cpp): the FMA-unit roots help where AVX-512 is native (Intel), and cost
  // time on AMD's Zen 4, which splits each 512-bit operation in two.
  if (level_table[simd::avx512_sqrt_unit] && __builtin_cpu_is("amd")) best_level = simd::avx512_sqrt_unit;
#endif
}

// Level by name ("auto": the best); -1 for an unknown name.
int parse_level(const std::string& name) {
  if (name == "auto") return best_level;
  for (int l = 0; l < n_levels; ++l)
    if (name == level_names[l]) return l;
  return -1;
}

std::string available_levels() {
  std::string s;
  for (int l = 0; l < n_levels; ++l)
    if (l == simd::scalar || level_table[l]) s += (s.empty() ? "" : ", ") + std::string(level_names[l]);
  return s;
}

// The float64 batch kernel of K at the active level, or nullptr (scalar loop).
template <class K, class T, class = void>
struct simd_batch {
  static simd::batch_fn get() { return nullptr; }
};
template <class K>
struct simd_batch<K, double, std::void_t<decltype(K::simd_slot)>> {
  static simd::batch_fn get() {
    const simd::kernels* t = level_table[active_level.load(std::memory_order_relaxed)];
    return t ? t->*K::simd_slot : nullptr;
  }
};

template <class K, std::size_t... I>
double lane_eval(const double* a, std::index_sequence<I...>) {
  return K::eval(a[I]..., nan_policy());
}
template <class K, std::size_t Nin>
double lane(const double* a) {
  return lane_eval<K>(a, std::make_index_sequence<Nin>());
}

// The SIMD kernel over [begin, end): contiguous operands straight, strided ones through buffers.
template <std::size_t Nin>
void run_simd_range(simd::batch_fn fn, simd::lane_fn fallback, char** args, const npy_intp* steps,
                    npy_intp begin, npy_intp end) {
  bool contiguous = true;
  for (std::size_t k = 0; k <= Nin; ++k) contiguous = contiguous && steps[k] == static_cast<npy_intp>(sizeof(double));
  if (contiguous) {
    const double* in[Nin];
    for (std::size_t k = 0; k < Nin; ++k) in[k] = reinterpret_cast<const double*>(args[k]) + begin;
    fn(in, reinterpret_cast<double*>(args[Nin]) + begin, static_cast<std::size_t>(end - begin), fallback);
    return;
  }
  constexpr npy_intp chunk = 256;
  double buf[Nin][chunk];
  double res[chunk];
  const double* in[Nin];
  for (std::size_t k = 0; k < Nin; ++k) in[k] = buf[k];
  for (npy_intp i = begin; i < end; i += chunk) {
    const npy_intp n = end - i < chunk ? end - i : chunk;
    for (std::size_t k = 0; k < Nin; ++k)
      for (npy_intp j = 0; j < n; ++j) buf[k][j] = *reinterpret_cast<const double*>(args[k] + (i + j) * steps[k]);
    fn(in, res, static_cast<std::size_t>(n), fallback);
    for (npy_intp j = 0; j < n; ++j) *reinterpret_cast<double*>(args[Nin] + (i + j) * steps[Nin]) = res[j];
  }
}

template <class K, class T, std::size_t Nin>
void loop(char** args, const npy_intp* dims, const npy_intp* steps, void*) {
  const npy_intp n = dims[0];
  const auto seq = std::make_index_sequence<Nin>();
  const simd::batch_fn vec = simd_batch<K, T>::get();  // one level for the whole call
  const auto range = [&](npy_intp b, npy_intp e) {
    if (vec)
      run_simd_range<Nin>(vec, &lane<K, Nin>, args, steps, b, e);
    else
      run_range<K, T>(args, steps, b, e, seq);
  };
  const unsigned nt = threads_for(static_cast<std::size_t>(n), ufunc_threads.load(std::memory_order_relaxed));
  if (nt <= 1) {
    range(0, n);
    return;
  }
  try {
    gecko::detail::parallel_for_blocks(static_cast<std::size_t>(n), nt, [&](std::size_t b, std::size_t e) {
      range(static_cast<npy_intp>(b), static_cast<npy_intp>(e));
    });
  } catch (...) {
    // Only a failure to start a thread can get here (the kernels do not throw under nan_policy):
    // every block is recomputed serially, with identical results.
    range(0, n);
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

// ellint_ek(m) -> (E, K): one input, two outputs from one duplication (gecko/elliptic/ellint_ek.hpp),
// on the pool like the other loops.
template <class T>
void ek_range(char** args, const npy_intp* steps, npy_intp begin, npy_intp end) {
  for (npy_intp i = begin; i < end; ++i) {
    const auto r = gecko::ellint_ek(*reinterpret_cast<const T*>(args[0] + i * steps[0]), nan_policy());
    *reinterpret_cast<T*>(args[1] + i * steps[1]) = r.E;
    *reinterpret_cast<T*>(args[2] + i * steps[2]) = r.K;
  }
}

template <class T>
void ek_loop(char** args, const npy_intp* dims, const npy_intp* steps, void*) {
  const npy_intp n = dims[0];
  const unsigned nt = threads_for(static_cast<std::size_t>(n), ufunc_threads.load(std::memory_order_relaxed));
  try {
    gecko::detail::parallel_for_blocks(static_cast<std::size_t>(n), nt, [&](std::size_t b, std::size_t e) {
      ek_range<T>(args, steps, static_cast<npy_intp>(b), static_cast<npy_intp>(e));
    });
  } catch (...) {
    ek_range<T>(args, steps, 0, n);  // a thread failed to start: serially, identical results
  }
}

PyUFuncGenericFunction ek_funcs[2] = {&ek_loop<float>, &ek_loop<double>};
void* ek_data[2] = {nullptr, nullptr};
char ek_types[6] = {NPY_FLOAT, NPY_FLOAT, NPY_FLOAT, NPY_DOUBLE, NPY_DOUBLE, NPY_DOUBLE};

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

// The public functions' first stop for anything but two plain floats: Python float, int and
// numpy float64 scalars give a Python float (as the scalar entry above); when any argument is a
// 0-d float64 array and the others such scalars, a numpy float64 (what the ufunc returns for
// 0-d input) without the ufunc machinery, whose call plus the NaN scan of errors="raise" cost
// several times scipy.special's 0-d call. Anything else: NotImplemented (the caller takes the
// ufunc route).
template <class K, std::size_t... I>
PyObject* call_fast(PyObject* const* args, std::index_sequence<I...>) {
  constexpr std::size_t nin = sizeof...(I);
  double x[nin];
  bool zero_d = false;
  for (std::size_t k = 0; k < nin; ++k) {
    PyObject* o = args[k];
    if (PyFloat_CheckExact(o) || PyLong_CheckExact(o) || Py_TYPE(o) == &PyDoubleArrType_Type) {
      x[k] = PyFloat_AsDouble(o);
      if (x[k] == -1.0 && PyErr_Occurred()) return nullptr;
    } else if (PyArray_CheckExact(o) && PyArray_NDIM(reinterpret_cast<PyArrayObject*>(o)) == 0 &&
               PyArray_TYPE(reinterpret_cast<PyArrayObject*>(o)) == NPY_DOUBLE &&
               PyArray_ISBEHAVED_RO(reinterpret_cast<PyArrayObject*>(o))) {
      x[k] = *static_cast<const double*>(PyArray_DATA(reinterpret_cast<PyArrayObject*>(o)));
      zero_d = true;
    } else {
      Py_RETURN_NOTIMPLEMENTED;
    }
  }
  const long errors = PyLong_AsLong(args[nin]);
  if (errors == -1 && PyErr_Occurred()) return nullptr;
  double r;
  if (errors != 0) {
    r = K::eval(x[I]..., nan_policy());
  } else {
    try {
      r = K::eval(x[I]..., default_policy());
    } catch (const std::domain_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
      return nullptr;
    }
  }
  if (!zero_d) return PyFloat_FromDouble(r);
  PyObject* out = PyArrayScalar_New(Double);
  if (out) PyArrayScalar_ASSIGN(out, Double, r);
  return out;
}

// METH_FASTCALL entry <name>_scalar (Fast = false) or <name>_fast (Fast = true).
template <class K, std::size_t Nin, bool Fast>
PyObject* fastcall(PyObject*, PyObject* const* args, Py_ssize_t nargs) {
  if (nargs != static_cast<Py_ssize_t>(Nin + 1)) {
    PyErr_Format(PyExc_TypeError, "gecko._core.%s%s takes %d arguments (%zd given)", K::name,
                 Fast ? "_fast" : "_scalar", static_cast<int>(Nin + 1), nargs);
    return nullptr;
  }
  if constexpr (Fast) return call_fast<K>(args, std::make_index_sequence<Nin>());
  return call_scalar<K>(args, std::make_index_sequence<Nin>());
}

template <class K, std::size_t Nin, bool Fast>
void add_fastcall(py::module_& m, const char* doc) {
  static const std::string name = std::string(K::name) + (Fast ? "_fast" : "_scalar");
  static PyMethodDef def = {name.c_str(), reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&fastcall<K, Nin, Fast>)),
                            METH_FASTCALL, doc};
  PyObject* f = PyCFunction_NewEx(&def, nullptr, nullptr);
  if (!f) throw py::error_already_set();
  m.attr(name.c_str()) = py::reinterpret_steal<py::object>(f);
}

template <class K, std::size_t Nin>
void add_scalar(py::module_& m, const char*) {
  add_fastcall<K, Nin, false>(m, "scalar kernel (a, ..., errors): errors 0 raises ValueError, 1 gives NaN");
  add_fastcall<K, Nin, true>(m, "(a, ..., errors): scalars and 0-d float64 arrays through the scalar kernel, "
                                "else NotImplemented");
}

}  // namespace

void bind_elliptic_ufuncs(py::module_& m) {
  if (_import_array() < 0) throw py::error_already_set();
  if (_import_umath() < 0) throw py::error_already_set();
  py::module_ u = m.def_submodule("ufuncs", "numpy ufuncs of the elliptic kernels (NaN outside the domain)");
  u.attr("ellint_f") = make_ufunc<kernel_f, 2>("ellint_f(phi, m): F(phi|m), NaN outside the domain");
  u.attr("ellint_e") = make_ufunc<kernel_e, 2>("ellint_e(phi, m): E(phi|m), NaN outside the domain");
  u.attr("ellint_k") = make_ufunc<kernel_k, 1>("ellint_k(m): K(m), NaN for m > 1");
  {
    PyObject* ek = PyUFunc_FromFuncAndData(ek_funcs, ek_data, ek_types, 2, 1, 2, PyUFunc_None, "ellint_ek",
                                           "ellint_ek(m) -> (E(m), K(m)) from one duplication, NaN for m > 1", 0);
    if (!ek) throw py::error_already_set();
    u.attr("ellint_ek") = py::reinterpret_steal<py::object>(ek);
  }
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

  // SIMD level of the float64 F, E and R_F loops: the best available, or GECKO_SIMD's.
  detect_levels();
  active_level.store(best_level);
  if (const char* env = std::getenv("GECKO_SIMD")) {
    const int l = parse_level(env);
    if (l < 0 || !(l == simd::scalar || level_table[l])) {
      const std::string msg = "GECKO_SIMD=" + std::string(env) + " is not available here (available: " +
                              available_levels() + ", auto); using " + level_names[best_level];
      if (PyErr_WarnEx(PyExc_RuntimeWarning, msg.c_str(), 1) < 0) throw py::error_already_set();
    } else {
      active_level.store(l);
    }
  }
  m.def("set_simd_level", [](const std::string& name) {
    const int l = parse_level(name);
    if (l < 0 || !(l == simd::scalar || level_table[l]))
      throw std::domain_error("gecko.elliptic.set_simd_level: level = '" + name +
                              "' is not available on this machine: need one of " + available_levels() + ", auto");
    return std::string(level_names[active_level.exchange(l)]);
  }, py::arg("level"));
  m.def("simd_level", [] { return std::string(level_names[active_level.load()]); });
  m.def("simd_levels", [] {
    py::list out;
    for (int l = 0; l < n_levels; ++l)
      if (l == simd::scalar || level_table[l]) out.append(level_names[l]);
    return out;
  });

  // Thread count of the ufunc loops: 0 automatic, k > 0 exactly k; returns the previous setting.
  m.def("set_ufunc_threads", [](int k) {
    if (k < 0) throw std::domain_error("gecko.elliptic.set_num_threads: threads = " + std::to_string(k) +
                                       " is out of range: need threads >= 0 (0: automatic)");
    return ufunc_threads.exchange(k);
  }, py::arg("threads"));
}

}  // namespace bindings
}  // namespace gecko
