// Python bindings of gecko/beam and gecko/friction (see python/gecko/friction.py for the public
// wrappers): flat float64 arrays in, arrays out, the loops run without the GIL. Broadcasting,
// scalars, presets, law objects and the `errors=` keyword live in python/gecko/friction.py.
// A Python detachment law is evaluated there (vectorised, GIL held) and passed in as G(V).
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "bindings.hpp"
#include "result_types.hpp"
#include "vectorize.hpp"
#include "gecko/beam.hpp"
#include "gecko/friction.hpp"

namespace gecko {
namespace bindings {
namespace {

using policies::default_policy;
using policies::nan_policy;
using Mat2 = Eigen::Matrix2d;

void require_equal(py::ssize_t n, const darray& a, const char* what) {
  if (a.ndim() != 1 || a.size() != n)
    throw std::invalid_argument(std::string("gecko._core: ") + what +
                                " must be a flat array of the same length as the others");
}

Mat2 to_mat2(const darray& K, const char* name) {
  if (K.size() != 4)
    throw std::invalid_argument(std::string("gecko._core: ") + name + " must have 4 entries (2x2)");
  const double* k = K.data();
  Mat2 M;
  M << k[0], k[1], k[2], k[3];
  return M;
}

py::array_t<double> from_mat2(const Mat2& M) {
  py::array_t<double> out({2, 2});
  auto o = out.mutable_unchecked<2>();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) o(i, j) = M(i, j);
  return out;
}

// Runs body(begin, end) over [0, n) on the one pool without the GIL (vectorize.hpp), automatic
// thread count (several threads only for long arrays).
template <class Body>
void parallel_for(py::ssize_t n, Body body) {
  const auto count = static_cast<std::size_t>(n);
  for_each_block(count, threads_for(count, 0), [&](std::size_t lo, std::size_t hi) {
    body(static_cast<py::ssize_t>(lo), static_cast<py::ssize_t>(hi));
  });
}

// A shape backed by Python callables; the GIL is held throughout (castigliano does not release
// it). Without dzdx the slope is the complex step through z itself.
struct python_shape {
  py::function z;
  py::object dzdx;
  double operator()(double x) const { return z(x).cast<double>(); }
  double slope(double x) const {
    if (!dzdx.is_none()) return dzdx(x).cast<double>();
    const double eps = std::numeric_limits<double>::epsilon();
    const double floor = std::numeric_limits<double>::min() / eps;
    const double h = eps * x > floor ? eps * x : floor;
    static const char* message =
        "gecko.castigliano_compliance: dzdx = None needs z to accept complex x (complex-step "
        "slope, e.g. numpy functions); pass dzdx explicitly otherwise";
    py::object v;
    try {
      v = z(std::complex<double>(x, h));
    } catch (py::error_already_set& e) {
      if (e.matches(PyExc_TypeError)) throw std::invalid_argument(message);
      throw;
    }
    try {
      return v.cast<std::complex<double>>().imag() / h;
    } catch (const py::cast_error&) {
      throw std::invalid_argument(message);
    }
  }
};

// The run options that simulate_spatulae and simulate_compliant_seta share.
template <class Options>
void set_run_options(Options& o, std::size_t spatulae, double duration, double t_off,
                     bool exponential, std::size_t samples, std::uint64_t seed) {
  o.spatulae = spatulae;
  o.duration = duration;
  o.t_off = t_off;
  o.law = exponential ? resticking::exponential : resticking::fixed;
  o.samples = samples;
  o.seed = seed;
}

// ---- field tables: each result struct's Python dict keys, written once (result_types.hpp) ------
#define GECKO_F(m) GECKO_RESULT_FIELD(S, m)
#define GECKO_A(m) GECKO_ARRAY_FIELD(S, m)

template <class S = quadrature_report<double>>
auto quadrature_report_fields() {
  return std::make_tuple(GECKO_F(error_estimate), GECKO_F(levels), GECKO_F(evaluations), GECKO_F(converged));
}

template <class S = force_trace_result<double>>
auto force_trace_fields() {
  return std::make_tuple(GECKO_A(t), GECKO_A(d_par), GECKO_A(d_perp), GECKO_A(f_par), GECKO_A(f_perp));
}

// What the results of simulate_spatulae and simulate_compliant_seta share.
template <class S>
auto run_fields() {
  return std::make_tuple(GECKO_F(mean_par), GECKO_F(mean_perp), GECKO_F(std_par), GECKO_F(std_perp),
                         GECKO_F(stretch), GECKO_F(t_on), GECKO_F(detachments), GECKO_A(t), GECKO_A(F_par),
                         GECKO_A(F_perp));
}

template <class S = spatula_simulation_result<double>>
auto spatula_simulation_fields() {
  return std::tuple_cat(run_fields<S>(),
                        std::make_tuple(GECKO_F(mean_field_par), GECKO_F(mean_field_perp), GECKO_F(population_par),
                                        GECKO_F(population_perp), GECKO_F(bound_par), GECKO_F(bound_perp)));
}

template <class S = compliant_seta_result<double>>
auto compliant_seta_fields() {
  return std::tuple_cat(run_fields<S>(), std::make_tuple(GECKO_F(max_drop), GECKO_F(max_slip_size), GECKO_F(slips),
                                                         GECKO_F(collective_stiffness), GECKO_A(lag)));
}

// A fit of any law (steady_sliding_fit<double, Law>); the vectors stay lists, as they always were.
template <class S>
auto fit_fields() {
  return std::make_tuple(
      GECKO_F(names), GECKO_F(values), GECKO_F(standard_errors),
      field("covariance", [](const S& s) {
        const auto n = static_cast<py::ssize_t>(s.covariance.rows());
        py::array_t<double> cov({n, n});
        auto c = cov.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < n; ++i)
          for (py::ssize_t j = 0; j < n; ++j) c(i, j) = s.covariance(i, j);
        return cov;
      }),
      GECKO_F(rss), GECKO_F(chi2), GECKO_F(dof), GECKO_F(iterations),
      field("status", [](const S& s) { return std::string(to_string(s.status)); }), GECKO_F(reason),
      GECKO_F(condition), GECKO_F(undetermined), GECKO_F(profile_lower), GECKO_F(profile_upper),
      field("f_par1", [](const S& s) { return s.params.f_par1; }),
      field("f_perp1", [](const S& s) { return s.params.f_perp1; }),
      field("K", [](const S& s) { return from_mat2(s.params.K); }));
}

#undef GECKO_A
#undef GECKO_F

sliding_params<double> make_params(double N, const darray& K, double f_par1, double f_perp1) {
  sliding_params<double> p;
  p.N = N;
  p.K = to_mat2(K, "K");
  p.f_par1 = f_par1;
  p.f_perp1 = f_perp1;
  return p;
}

// law_kind: 0 viscoelastic (G0, V_star, n), 1 Eyring (G0, V_star).
template <class Policy, class Fn>
auto with_law(int kind, double G0, double V_star, double n, Fn fn) {
  if (kind == 0) return fn(viscoelastic_detachment<double, Policy>{G0, V_star, n});
  if (kind == 1) return fn(eyring_detachment<double, Policy>{G0, V_star});
  throw std::invalid_argument("gecko._core: law kind must be 0 (viscoelastic) or 1 (eyring)");
}

// Outputs (F_par, F_perp, stretch, t_on); with forces_only the last two are None and never
// allocated (a quarter of the run time for long arrays is the page faults of fresh outputs).
struct sliding_outputs {
  py::array_t<double> Fp, Fq, dd, ton;
  double *a, *b, *c = nullptr, *d = nullptr;
  sliding_outputs(py::ssize_t m, bool forces_only) : Fp(m), Fq(m) {
    a = Fp.mutable_data();
    b = Fq.mutable_data();
    if (!forces_only) {
      dd = py::array_t<double>(m);
      ton = py::array_t<double>(m);
      c = dd.mutable_data();
      d = ton.mutable_data();
    }
  }
  py::tuple result() const {
    if (!c) return py::make_tuple(Fp, Fq, py::none(), py::none());
    return py::make_tuple(Fp, Fq, dd, ton);
  }
};

template <class Policy>
py::tuple steady_sliding_law_imp(const darray& V, double N, const darray& K, double f_par1,
                                 double f_perp1, int kind, double G0, double V_star, double n,
                                 double t_off, bool forces_only) {
  const auto p = make_params(N, K, f_par1, f_perp1);
  const py::ssize_t m = V.size();
  sliding_outputs out(m, forces_only);
  double *a = out.a, *b = out.b, *c = out.c, *d = out.d;
  const double* v = V.data();
  with_law<Policy>(kind, G0, V_star, n, [&](auto law) {
    // Validate the parameters once with the GIL held (a bad law raises here, not in a thread).
    if (m > 0) {
      steady_sliding(p, law, v, 1, a, b, c, d, t_off, Policy());
    }
    parallel_for(m, [&](py::ssize_t lo, py::ssize_t hi) {
      steady_sliding(p, law, v + lo, std::size_t(hi - lo), a + lo, b + lo, c ? c + lo : nullptr,
                     d ? d + lo : nullptr, t_off, Policy());
    });
    return 0;
  });
  return out.result();
}

template <class Policy>
py::tuple steady_sliding_energy_imp(const darray& V, const darray& G, double N, const darray& K,
                                    double f_par1, double f_perp1, double t_off, bool forces_only) {
  const auto p = make_params(N, K, f_par1, f_perp1);
  const py::ssize_t m = V.size();
  require_equal(m, G, "G");
  sliding_outputs out(m, forces_only);
  double *a = out.a, *b = out.b, *c = out.c, *d = out.d;
  const double* v = V.data();
  const double* g = G.data();
  parallel_for(m, [&](py::ssize_t lo, py::ssize_t hi) {
    for (py::ssize_t i = lo; i < hi; ++i) {
      const auto r = steady_sliding_from_energy(p, v[i], g[i], t_off, Policy());
      a[i] = r.F_par;
      b[i] = r.F_perp;
      if (c) c[i] = r.stretch;
      if (d) d[i] = r.t_on;
    }
  });
  return out.result();
}

// out[i] = f(a[i], b[i], c[i], d[i]) through the shared element loop (vectorize.hpp), so that an
// out-of-range element is named by its index like every other elementwise call.
template <class F>
py::array_t<double> map4(const darray& a, const darray& b, const darray& c, const darray& d, F f) {
  return map_elements(f, 0, a, b, c, d);
}

}  // namespace

void bind_friction(py::module_& m) {
  // ---- beam ----------------------------------------------------------------------------
  m.def("castigliano_compliance",
        [](py::function z, py::object dzdx, double L, double EI, double EA, double tol,
           int max_levels) {
          quadrature_report<double> rep;
          quadrature_options<double> opt;
          opt.tol = tol;
          opt.max_levels = max_levels;
          opt.report = &rep;
          const Mat2 C = gecko::castigliano_compliance(python_shape{z, dzdx},
                                                       curved_beam<double>{L, EI, EA}, opt);
          return py::make_tuple(from_mat2(C), record(rep, quadrature_report_fields()));
        },
        py::arg("z"), py::arg("dzdx"), py::arg("L"), py::arg("EI"), py::arg("EA"),
        py::arg("tol") = 0.0, py::arg("max_levels") = 9);
  m.def("parabolic_beam_compliance", [](const darray& L, const darray& EI, int errors, bool rigid) {
    const py::ssize_t n = L.size();
    require_equal(n, EI, "EI");
    py::array_t<double> out({n, py::ssize_t(2), py::ssize_t(2)});
    double* o = out.mutable_data();
    const double *pl = L.data(), *pe = EI.data();
    {
      py::gil_scoped_release release;
      for (py::ssize_t i = 0; i < n; ++i) {
        Mat2 C;
        if (errors == int(on_error::nan))
          C = rigid ? parabolic_beam_rigidity(pl[i], pe[i], nan_policy())
                    : parabolic_beam_compliance(pl[i], pe[i], nan_policy());
        else
          C = rigid ? parabolic_beam_rigidity(pl[i], pe[i], default_policy())
                    : parabolic_beam_compliance(pl[i], pe[i], default_policy());
        o[4 * i] = C(0, 0); o[4 * i + 1] = C(0, 1); o[4 * i + 2] = C(1, 0); o[4 * i + 3] = C(1, 1);
      }
    }
    return out;
  }, py::arg("L"), py::arg("EI"), py::arg("errors") = 0, py::arg("rigidity") = false);
  m.def("rigidity", [](const darray& C, int errors) {
    // C: flat, 4 entries per matrix (row-major).
    if (C.size() % 4 != 0) throw std::invalid_argument("gecko._core: C must hold 2x2 matrices");
    const py::ssize_t n = C.size() / 4;
    py::array_t<double> out({n, py::ssize_t(2), py::ssize_t(2)});
    double* o = out.mutable_data();
    const double* c = C.data();
    {
      py::gil_scoped_release release;
      for (py::ssize_t i = 0; i < n; ++i) {
        Mat2 M;
        M << c[4 * i], c[4 * i + 1], c[4 * i + 2], c[4 * i + 3];
        const Mat2 K = errors == int(on_error::nan) ? gecko::rigidity(M, nan_policy())
                                                    : gecko::rigidity(M, default_policy());
        o[4 * i] = K(0, 0); o[4 * i + 1] = K(0, 1); o[4 * i + 2] = K(1, 0); o[4 * i + 3] = K(1, 1);
      }
    }
    return out;
  }, py::arg("C"), py::arg("errors") = 0);

  // ---- force traces --------------------------------------------------------------------
  m.def("force_trace", [](const darray& K, const darray& t, const darray& d_par,
                          const darray& d_perp, py::object times, int samples_per_segment) {
    displacement_path<double> path{std::vector<double>(t.data(), t.data() + t.size()),
                                   std::vector<double>(d_par.data(), d_par.data() + d_par.size()),
                                   std::vector<double>(d_perp.data(), d_perp.data() + d_perp.size())};
    const Mat2 KK = to_mat2(K, "K");
    force_trace_result<double> r;
    if (times.is_none()) {
      r = gecko::force_trace(KK, path, samples_per_segment);
    } else {
      darray tt = times.cast<darray>();
      r = gecko::force_trace(KK, path, std::vector<double>(tt.data(), tt.data() + tt.size()));
    }
    return record(r, force_trace_fields());
  }, py::arg("K"), py::arg("t"), py::arg("d_par"), py::arg("d_perp"), py::arg("times") = py::none(),
     py::arg("samples_per_segment") = 50);

  // ---- detachment ----------------------------------------------------------------------
  m.def("viscoelastic_detachment", [](const darray& V, const darray& G0, const darray& Vs,
                                      const darray& n, int errors) {
    if (errors == int(on_error::nan))
      return map4(V, G0, Vs, n, [](double a, double b, double c, double d) {
        return viscoelastic_detachment_energy(a, b, c, d, nan_policy()); });
    return map4(V, G0, Vs, n, [](double a, double b, double c, double d) {
      return viscoelastic_detachment_energy(a, b, c, d, default_policy()); });
  }, py::arg("V"), py::arg("G0"), py::arg("V_star"), py::arg("n"), py::arg("errors") = 0);
  m.def("eyring_detachment", [](const darray& V, const darray& G0, const darray& Vs, int errors) {
    if (errors == int(on_error::nan))
      return map4(V, G0, Vs, Vs, [](double a, double b, double c, double) {
        return eyring_detachment_energy(a, b, c, nan_policy()); });
    return map4(V, G0, Vs, Vs, [](double a, double b, double c, double) {
      return eyring_detachment_energy(a, b, c, default_policy()); });
  }, py::arg("V"), py::arg("G0"), py::arg("V_star"), py::arg("errors") = 0);
  m.def("detachment_stretch", [](const darray& K, const darray& f1, const darray& G, int errors) {
    if (errors == int(on_error::nan))
      return map4(K, f1, G, G, [](double a, double b, double c, double) {
        return gecko::detachment_stretch(a, b, c, nan_policy()); });
    return map4(K, f1, G, G, [](double a, double b, double c, double) {
      return gecko::detachment_stretch(a, b, c, default_policy()); });
  }, py::arg("K_par_par"), py::arg("f_par1"), py::arg("G"), py::arg("errors") = 0);
  m.def("resonant_frequency", [](const darray& D, const darray& L, const darray& E,
                                 const darray& rho, int errors) {
    if (errors == int(on_error::nan))
      return map4(D, L, E, rho, [](double a, double b, double c, double d) {
        return gecko::resonant_frequency(a, b, c, d, nan_policy()); });
    return map4(D, L, E, rho, [](double a, double b, double c, double d) {
      return gecko::resonant_frequency(a, b, c, d, default_policy()); });
  }, py::arg("D"), py::arg("L"), py::arg("E"), py::arg("rho"), py::arg("errors") = 0);

  // ---- steady sliding --------------------------------------------------------------------
  m.def("steady_sliding_law", [](const darray& V, double N, const darray& K, double f_par1,
                                 double f_perp1, int kind, double G0, double V_star, double n,
                                 double t_off, int errors, bool forces_only) {
    if (errors == int(on_error::nan))
      return steady_sliding_law_imp<nan_policy>(V, N, K, f_par1, f_perp1, kind, G0, V_star, n,
                                                t_off, forces_only);
    return steady_sliding_law_imp<default_policy>(V, N, K, f_par1, f_perp1, kind, G0, V_star, n,
                                                  t_off, forces_only);
  }, py::arg("V"), py::arg("N"), py::arg("K"), py::arg("f_par1"), py::arg("f_perp1"),
     py::arg("kind"), py::arg("G0"), py::arg("V_star"), py::arg("n"), py::arg("t_off") = 0.0,
     py::arg("errors") = 0, py::arg("forces_only") = false);
  m.def("steady_sliding_energy", [](const darray& V, const darray& G, double N, const darray& K,
                                    double f_par1, double f_perp1, double t_off, int errors,
                                    bool forces_only) {
    if (errors == int(on_error::nan))
      return steady_sliding_energy_imp<nan_policy>(V, G, N, K, f_par1, f_perp1, t_off, forces_only);
    return steady_sliding_energy_imp<default_policy>(V, G, N, K, f_par1, f_perp1, t_off, forces_only);
  }, py::arg("V"), py::arg("G"), py::arg("N"), py::arg("K"), py::arg("f_par1"), py::arg("f_perp1"),
     py::arg("t_off") = 0.0, py::arg("errors") = 0, py::arg("forces_only") = false);

  // ---- simulation --------------------------------------------------------------------------
  // Population factors: None (all 1) or a flat array with one entry per simulated spatula (the
  // C++ side checks sizes and values).
  auto factors = [](const py::object& length, const py::object& stiffness, const py::object& G0) {
    auto one = [](const py::object& a) {
      std::vector<double> v;
      if (a.is_none()) return v;
      const darray arr = a.cast<darray>();
      if (arr.ndim() != 1)
        throw std::invalid_argument("gecko._core: population factors must be flat arrays");
      v.assign(arr.data(), arr.data() + arr.size());
      return v;
    };
    spatula_population<double> pop;
    pop.length = one(length);
    pop.stiffness = one(stiffness);
    pop.G0 = one(G0);
    return pop;
  };
  m.def("simulate_spatulae", [factors](double N, const darray& K, double f_par1, double f_perp1,
                                       double V, double G, std::size_t spatulae, double duration,
                                       double t_off, bool exponential, std::size_t samples,
                                       std::uint64_t seed, py::object length, py::object stiffness,
                                       py::object G0) {
    const auto p = make_params(N, K, f_par1, f_perp1);
    spatula_simulation_options<double> o;
    set_run_options(o, spatulae, duration, t_off, exponential, samples, seed);
    const spatula_population<double> pop = factors(length, stiffness, G0);
    spatula_simulation_result<double> r;
    {
      py::gil_scoped_release release;
      auto law = [G](double) { return G; };
      r = pop.empty() ? gecko::simulate_spatulae(p, law, V, o)
                      : gecko::simulate_spatulae(p, law, V, o, pop);
    }
    return record(r, spatula_simulation_fields());
  }, py::arg("N"), py::arg("K"), py::arg("f_par1"), py::arg("f_perp1"), py::arg("V"), py::arg("G"),
     py::arg("spatulae"), py::arg("duration"), py::arg("t_off"), py::arg("exponential"),
     py::arg("samples"), py::arg("seed"), py::arg("length") = py::none(),
     py::arg("stiffness") = py::none(), py::arg("G0") = py::none());
  m.def("simulate_compliant_seta", [factors](double N, const darray& K, double f_par1,
                                             double f_perp1, double V, double G, double spring,
                                             std::size_t spatulae, double duration, double t_off,
                                             bool exponential, double transient,
                                             std::size_t samples, std::uint64_t seed,
                                             py::object length, py::object stiffness,
                                             py::object G0) {
    const auto p = make_params(N, K, f_par1, f_perp1);
    compliant_seta_options<double> o;
    set_run_options(o, spatulae, duration, t_off, exponential, samples, seed);
    o.spring = spring;
    o.transient = transient;
    const spatula_population<double> pop = factors(length, stiffness, G0);
    compliant_seta_result<double> r;
    {
      py::gil_scoped_release release;
      r = gecko::simulate_compliant_seta(p, [G](double) { return G; }, V, o, pop);
    }
    return record(r, compliant_seta_fields());
  }, py::arg("N"), py::arg("K"), py::arg("f_par1"), py::arg("f_perp1"), py::arg("V"), py::arg("G"),
     py::arg("spring"), py::arg("spatulae"), py::arg("duration"), py::arg("t_off"),
     py::arg("exponential"), py::arg("transient"), py::arg("samples"), py::arg("seed"),
     py::arg("length") = py::none(), py::arg("stiffness") = py::none(),
     py::arg("G0") = py::none());

  // ---- fit ---------------------------------------------------------------------------------
  // kind 0 viscoelastic, 1 Eyring (GIL released), 2 a Python law G(V, p) with named parameters
  // (GIL held: the law is called from the solver).
  m.def("fit_steady_sliding", [](const darray& V, const darray& F_par, const darray& F_perp,
                                 double N, const darray& K, double f_par1, double f_perp1,
                                 int kind, double G0, double V_star, double n, py::object fit_f_par1,
                                 bool fit_f_perp1, bool fit_coupling, int max_iterations,
                                 py::object sigma_par, py::object sigma_perp, bool absolute_sigma,
                                 bool profile, double profile_delta, double max_condition,
                                 py::object custom_G, std::vector<std::string> custom_names,
                                 std::vector<double> custom_values,
                                 std::vector<bool> custom_positive) {
    const py::ssize_t m = V.size();
    require_equal(m, F_par, "F_par");
    require_equal(m, F_perp, "F_perp");
    const auto p = make_params(N, K, f_par1, f_perp1);
    fit_options<double> opt;
    // None: automatic (fitted iff the guess law has G(0) = 0; see fit_options)
    if (!fit_f_par1.is_none()) opt.fit_f_par1 = fit_f_par1.cast<bool>();
    opt.fit_f_perp1 = fit_f_perp1;
    opt.fit_coupling = fit_coupling;
    opt.max_iterations = max_iterations;
    opt.absolute_sigma = absolute_sigma;
    opt.profile = profile;
    opt.profile_delta = profile_delta;
    opt.max_condition = max_condition;
    darray sp, sq;
    if (!sigma_par.is_none()) {
      sp = sigma_par.cast<darray>();
      require_equal(m, sp, "sigma_par");
      opt.sigma_par = sp.data();
    }
    if (!sigma_perp.is_none()) {
      sq = sigma_perp.cast<darray>();
      require_equal(m, sq, "sigma_perp");
      opt.sigma_perp = sq.data();
    }
    auto pack = [](const auto& r) { return record(r, fit_fields<std::decay_t<decltype(r)>>()); };
    if (kind == 2) {
      custom_detachment<double> law;
      law.names = custom_names;
      law.values = custom_values;
      law.positive = custom_positive;
      py::function G = custom_G.cast<py::function>();
      const std::size_t k = custom_names.size();
      law.G = [G, k](const double* v, std::size_t nv, const double* par, double* out) {
        py::array_t<double> vv(static_cast<py::ssize_t>(nv), v);
        py::array_t<double> pp(static_cast<py::ssize_t>(k), par);
        py::array_t<double> g = py::array_t<double>::ensure(G(vv, pp));
        if (!g || g.size() != static_cast<py::ssize_t>(nv))
          throw std::invalid_argument(
              "gecko.fit_steady_sliding: the law must return one G per velocity");
        const double* gd = g.data();
        for (std::size_t i = 0; i < nv; ++i) out[i] = gd[i];
      };
      const auto r = gecko::fit_steady_sliding(V.data(), F_par.data(), F_perp.data(),
                                               std::size_t(m), p, law, opt);
      return pack(r);
    }
    return with_law<default_policy>(kind, G0, V_star, n, [&](auto law) {
      decltype(gecko::fit_steady_sliding(V.data(), F_par.data(), F_perp.data(), std::size_t(m), p,
                                         law, opt)) r;
      {
        py::gil_scoped_release release;
        r = gecko::fit_steady_sliding(V.data(), F_par.data(), F_perp.data(), std::size_t(m), p,
                                      law, opt);
      }
      return pack(r);
    });
  }, py::arg("V"), py::arg("F_par"), py::arg("F_perp"), py::arg("N"), py::arg("K"),
     py::arg("f_par1"), py::arg("f_perp1"), py::arg("kind"), py::arg("G0"), py::arg("V_star"),
     py::arg("n"), py::arg("fit_f_par1") = py::none(), py::arg("fit_f_perp1") = true,
     py::arg("fit_coupling") = false, py::arg("max_iterations") = 200,
     py::arg("sigma_par") = py::none(), py::arg("sigma_perp") = py::none(),
     py::arg("absolute_sigma") = true, py::arg("profile") = false, py::arg("profile_delta") = 1.0,
     py::arg("max_condition") = 1e10, py::arg("custom_G") = py::none(),
     py::arg("custom_names") = std::vector<std::string>(),
     py::arg("custom_values") = std::vector<double>(),
     py::arg("custom_positive") = std::vector<bool>());
}

}  // namespace bindings
}  // namespace gecko
