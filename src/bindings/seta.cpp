// Python bindings of gecko/seta and gecko/peel (see python/gecko/seta.py for the public wrappers).
// Designs travel as 9 doubles (EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w); arrays are flat
// float64; every C++ loop runs without the GIL (errors raised inside leave the released scope
// normally, so pybind11 re-acquires the GIL before turning std::domain_error into ValueError).
// Result structs are described once, by field tables (result_types.hpp): one result is a bound
// type (CriticalState, SetaCharacteristicsResult, SmallDeformation), many are numpy columns.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <pybind11/native_enum.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "gecko/core/parallel.hpp"
#include "gecko/peel.hpp"
#include "gecko/seta.hpp"
#include "result_types.hpp"
#include "vectorize.hpp"

namespace gecko {
namespace bindings {
namespace {

using policies::default_policy;
using policies::nan_policy;

TwoLevelSeta<double> design_from(const double* p) {
  TwoLevelSeta<double> s;
  for (const auto& f : seta_design_fields<double>()) s.*(f.member) = *p++;  // the fields' order
  return s;
}

TwoLevelSeta<double> design_from(const darray& params) {
  if (params.ndim() != 1 || params.size() != 9)
    throw std::invalid_argument("gecko._core: a seta design is 9 numbers (EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w)");
  return design_from(params.data());
}

critical_line_options<double> line_options(double ft_end, double tolerance,
                                           double strain_limit = std::numeric_limits<double>::infinity()) {
  critical_line_options<double> o;
  o.ft_end = ft_end;
  if (tolerance == tolerance) o.tolerance = tolerance;
  if (!(strain_limit > 0))  // NaN or <= 0
    throw std::invalid_argument("gecko: strain_limit must be > 0 (None or inf: no limit)");
  o.strain_limit = strain_limit;
  return o;
}

// ---- field tables: each result struct's Python names, written once -------------------------
#define GECKO_F(m) GECKO_RESULT_FIELD(S, m)

// What a critical state and a traced node of the line share.
template <class S>
auto shared_state_fields() {
  return std::make_tuple(GECKO_F(Fn), GECKO_F(theta_joint), GECKO_F(theta_rate_joint), GECKO_F(theta_rate_base),
                         GECKO_F(status), GECKO_F(turning_points_beam), GECKO_F(turning_points_spatula),
                         GECKO_F(min_z), GECKO_F(min_z_at), GECKO_F(max_axial_strain),
                         GECKO_F(min_stretch));
}

// Columns of states at requested Ft (the caller knows Ft).
template <class S = critical_state<double>>
auto state_column_fields() {
  return std::tuple_cat(shared_state_fields<S>(), std::make_tuple(GECKO_F(iterations)));
}

template <class S = critical_state<double>>
auto critical_state_fields() {
  return std::tuple_cat(std::make_tuple(GECKO_F(Ft)), state_column_fields<S>());
}

template <class S = critical_line_point<double>>
auto line_node_fields() {
  return std::tuple_cat(std::make_tuple(GECKO_F(Ft)), shared_state_fields<S>(), std::make_tuple(GECKO_F(branch)));
}

// What the characteristics of one seta and the batch's per-design characteristics share.
template <class S>
auto shared_characteristic_fields() {
  return std::make_tuple(
      GECKO_F(fn0), GECKO_F(slope_k), GECKO_F(min_fn), GECKO_F(ft_at_min_fn), GECKO_F(min_fn_interior),
      GECKO_F(max_pull_off), GECKO_F(ft_max), GECKO_F(ft_at_line_end), GECKO_F(fn_at_line_end),
      GECKO_F(sticky_at_rest), field("small_fn0", [](const S& s) { return s.small.fn0; }),
      field("small_slope_k", [](const S& s) { return s.small.slope_k; }),
      field("small_contact_length", [](const S& s) { return s.small.contact_length; }),
      field("small_non_sticky", [](const S& s) { return s.small.non_sticky; }), GECKO_F(admissible_to_end),
      GECKO_F(admissible_end_ft), GECKO_F(admissible_end_fn), GECKO_F(slope_at_zero), GECKO_F(paper_k),
      GECKO_F(max_pull_off_is_bound), GECKO_F(max_pull_off_bound));
}

template <class S = seta_characteristics<double>>
auto characteristics_fields() {
  return std::tuple_cat(shared_characteristic_fields<S>(), std::make_tuple(GECKO_F(min_status),
                        GECKO_F(slope_at_min_fn), GECKO_F(end), GECKO_F(folds)));
}

// The batch's columns; line_end is -1 below depth whole_line (set by the caller).
template <class S = design_characteristics<double>>
auto design_characteristics_fields() {
  return std::tuple_cat(std::make_tuple(GECKO_F(status)), shared_characteristic_fields<S>(),
                        std::make_tuple(field("line_end", [](const S& s) { return s.end; }), GECKO_F(folds)));
}

template <class S = small_deformation_line<double>>
auto small_deformation_fields() {
  return std::make_tuple(GECKO_F(fn0), GECKO_F(slope_k), GECKO_F(contact_length), GECKO_F(non_sticky));
}

#undef GECKO_F

void bind_result_types(py::module_& m) {
  bind_result<critical_state<double>>(m, "CriticalState",
                                      "One critical state (TwoLevelSeta.solve): forces, joint angle and rates, "
                                      "status (CriticalStatus), admissibility.",
                                      critical_state_fields());
  bind_result<seta_characteristics<double>>(m, "SetaCharacteristicsResult",
                                            "Characteristics of one seta as computed (gecko.SetaCharacteristics "
                                            "is built from it).",
                                            characteristics_fields());
  bind_result<small_deformation_line<double>>(m, "SmallDeformation",
                                              "The small-deformation theory's (Fn)0, k, contact length at rest "
                                              "and non-sticky criterion (paper 001 eqs 7, 18-22).",
                                              small_deformation_fields());
}

template <class S>
py::dict state_columns(const std::vector<S>& rows) {
  return columns(rows.data(), rows.size(), state_column_fields<S>());
}

void line_at(const TwoLevelSeta<double>& s, const double* Ft, std::size_t n, int errors,
             const critical_line_options<double>& o, std::vector<critical_state<double>>& out) {
  out.resize(n);
  if (errors == static_cast<int>(on_error::nan)) critical_line_at(s, Ft, n, out.data(), o, nan_policy());
  else critical_line_at(s, Ft, n, out.data(), o, default_policy());
}

}  // namespace

void bind_seta_contact(py::module_& m);  // the forward problem, at the end of this file

void bind_seta(py::module_& m) {
  bind_result_types(m);
  bind_seta_contact(m);
  m.def("seta_validate", [](const darray& params, double Ft) {
    const auto s = design_from(params);
    detail::check_seta<double, default_policy>(s, "gecko.TwoLevelSeta");
    if (Ft == Ft) detail::check_ft<double, default_policy>(Ft, ft_max(s), "gecko.TwoLevelSeta");
    return ft_max(s);
  }, py::arg("params"), py::arg("Ft") = std::nan(""));

  m.def("seta_critical_line_at", [](const darray& params, const darray& Ft, int errors, double tolerance,
                                    double strain_limit) {
    const auto s = design_from(params);
    const auto n = static_cast<std::size_t>(Ft.size());
    const double* f = Ft.data();
    const auto o = line_options(std::nan(""), tolerance, strain_limit);
    std::vector<critical_state<double>> out;
    {
      py::gil_scoped_release release;
      line_at(s, f, n, errors, o, out);
    }
    return state_columns(out);
  }, py::arg("params"), py::arg("Ft"), py::arg("errors") = 0, py::arg("tolerance") = std::nan(""),
     py::arg("strain_limit") = std::numeric_limits<double>::infinity());

  m.def("seta_critical_line", [](const darray& params, double ft_end, bool resolve_nodes, double strain_limit) {
    const auto s = design_from(params);
    critical_line_result<double> r;
    auto options = line_options(ft_end, std::nan(""), strain_limit);
    options.resolve_nodes = resolve_nodes;
    {
      py::gil_scoped_release release;
      r = critical_line(s, options);
    }
    py::dict d = columns(r.points.data(), r.points.size(), line_node_fields());
    d["folds"] = py::cast(r.folds);
    d["end"] = static_cast<int>(r.end);
    d["natural_Fn"] = r.natural.Fn;
    d["natural_status"] = static_cast<int>(r.natural.status);
    return d;
  }, py::arg("params"), py::arg("ft_end") = std::nan(""),
     py::arg("resolve_nodes") = true, py::arg("strain_limit") = std::numeric_limits<double>::infinity());

  m.def("seta_solve", [](const darray& params, double Ft, double Fn, double beta, double rate_joint,
                         double rate_base, double tolerance, int max_iterations, double strain_limit) {
    const auto s = design_from(params);
    critical_state<double> r;
    const auto lo = line_options(std::nan(""), tolerance, strain_limit);
    {
      py::gil_scoped_release release;
      solve_options<double> o;
      if (tolerance == tolerance) o.tolerance = tolerance;
      o.max_iterations = max_iterations;
      o.strain_limit = strain_limit;
      if (Fn == Fn) {
        r = solve_critical(s, Ft, critical_guess<double>{Fn, beta, rate_joint, rate_base}, o);
      } else {
        critical_line_at(s, &Ft, 1, &r, lo);
      }
    }
    return r;
  }, py::arg("params"), py::arg("Ft"), py::arg("Fn") = std::nan(""), py::arg("theta_joint") = std::nan(""),
     py::arg("theta_rate_joint") = std::nan(""), py::arg("theta_rate_base") = std::nan(""),
     py::arg("tolerance") = std::nan(""), py::arg("max_iterations") = 40,
     py::arg("strain_limit") = std::numeric_limits<double>::infinity());

  m.def("seta_characteristics", [](const darray& params, double ft_end, double strain_limit) {
    const auto s = design_from(params);
    seta_characteristics<double> c;
    const auto o = line_options(ft_end, std::nan(""), strain_limit);
    {
      py::gil_scoped_release release;
      c = characteristics(s, o);
    }
    return c;
  }, py::arg("params"), py::arg("ft_end") = std::nan(""),
     py::arg("strain_limit") = std::numeric_limits<double>::infinity());

  // Many designs x many Ft: designs is (n*9) flat, Ft (m); returns (n*m) columns, row-major by
  // design. Designs are spread over `threads` std::threads; each design's line is independent,
  // so the result does not depend on the thread count.
  m.def("seta_batch", [](const darray& designs, const darray& Ft, int errors, int threads, double tolerance,
                         double strain_limit) {
    if (designs.ndim() != 1 || designs.size() % 9 != 0)
      throw std::invalid_argument("gecko._core: designs must be a flat array of 9 numbers per design");
    const auto nd = static_cast<std::size_t>(designs.size() / 9);
    const auto m_ft = static_cast<std::size_t>(Ft.size());
    const double* p = designs.data();
    const double* f = Ft.data();
    std::vector<critical_state<double>> out(nd * m_ft);
    {
      py::gil_scoped_release release;
      std::vector<TwoLevelSeta<double>> ds(nd);
      for (std::size_t i = 0; i < nd; ++i) ds[i] = design_from(p + 9 * i);
      const auto o = line_options(std::nan(""), tolerance, strain_limit);
      const unsigned nt = threads > 0 ? static_cast<unsigned>(threads) : 1u;
      if (errors == static_cast<int>(on_error::nan)) critical_line_batch(ds.data(), nd, f, m_ft, out.data(), nt, o, nan_policy());
      else critical_line_batch(ds.data(), nd, f, m_ft, out.data(), nt, o, default_policy());
    }
    return state_columns(out);
  }, py::arg("designs"), py::arg("Ft"), py::arg("errors") = 0, py::arg("threads") = 1,
     py::arg("tolerance") = std::nan(""), py::arg("strain_limit") = std::numeric_limits<double>::infinity());

  // Characteristics of many designs (the design sweep, python/gecko/design_sweep.py): designs is
  // (n*9) flat; depth 0 / 1 / 2 is characteristics_depth closed_forms / natural_state / whole_line
  // (gecko/seta/characteristics_batch.hpp: what each depth solves, the statuses, NaN for what it
  // does not). line_end is -1 below depth 2. Never raises for a bad design (status 5).
  m.def("seta_characteristics_batch", [](const darray& designs, int depth, int threads) {
    if (designs.ndim() != 1 || designs.size() % 9 != 0)
      throw std::invalid_argument("gecko._core: designs must be a flat array of 9 numbers per design");
    if (depth < 0 || depth > 2)
      throw std::invalid_argument("gecko._core: depth must be 0 (closed forms), 1 (natural state) or 2 (line)");
    const auto how = static_cast<characteristics_depth>(depth);
    const auto nd = static_cast<std::size_t>(designs.size() / 9);
    const double* p = designs.data();
    std::vector<design_characteristics<double>> out(nd);
    {
      py::gil_scoped_release release;
      std::vector<TwoLevelSeta<double>> ds(nd);
      for (std::size_t i = 0; i < nd; ++i) ds[i] = design_from(p + 9 * i);
      characteristics_batch(ds.data(), nd, how, out.data(), threads > 0 ? static_cast<unsigned>(threads) : 1u);
    }
    py::dict d = columns(out.data(), nd, design_characteristics_fields());
    if (how != characteristics_depth::whole_line) {  // no line followed: no line end to report
      auto end = d["line_end"].cast<py::array_t<std::int32_t>>();
      std::fill(end.mutable_data(), end.mutable_data() + nd, std::int32_t(-1));
    }
    return d;
  }, py::arg("designs"), py::arg("depth") = 2, py::arg("threads") = 1);

  // dFn/d(design) and dtheta_joint/d(design) at the line's states: (n, 9) arrays, columns in the
  // design order (EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w).
  m.def("seta_sensitivities", [](const darray& params, const darray& Ft) {
    const auto s = design_from(params);
    const auto n = static_cast<std::size_t>(Ft.size());
    std::vector<double> ft(Ft.data(), Ft.data() + n);
    std::vector<critical_sensitivity<double>> r;
    {
      py::gil_scoped_release release;
      r = sensitivities(s, ft);
    }
    py::array_t<double> dfn({static_cast<py::ssize_t>(n), py::ssize_t(9)}), db({static_cast<py::ssize_t>(n), py::ssize_t(9)});
    py::array_t<std::int32_t> status(static_cast<py::ssize_t>(n));
    py::array_t<double> Fn(static_cast<py::ssize_t>(n));
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < 9; ++j) {
        dfn.mutable_data()[9 * i + j] = r[i].dFn[j];
        db.mutable_data()[9 * i + j] = r[i].dtheta_joint[j];
      }
      status.mutable_data()[i] = static_cast<std::int32_t>(r[i].state.status);
      Fn.mutable_data()[i] = r[i].state.Fn;
    }
    py::dict d;
    d["dFn"] = dfn;
    d["dtheta_joint"] = db;
    d["status"] = status;
    d["Fn"] = Fn;
    return d;
  }, py::arg("params"), py::arg("Ft"));

  m.def("seta_shape", [](const darray& params, double Ft, int steps) {
    const auto s = design_from(params);
    if (steps < 1) throw std::invalid_argument("gecko: steps must be >= 1 (points per segment)");
    seta_shape<double> sh;
    critical_state<double> st;
    {
      py::gil_scoped_release release;
      st = solve_critical(s, Ft);
      sh = shape(s, st, steps);
    }
    py::dict d;
    d["s"] = py::array_t<double>(static_cast<py::ssize_t>(sh.s.size()), sh.s.data());
    d["x"] = py::array_t<double>(static_cast<py::ssize_t>(sh.x.size()), sh.x.data());
    d["z"] = py::array_t<double>(static_cast<py::ssize_t>(sh.z.size()), sh.z.data());
    d["theta"] = py::array_t<double>(static_cast<py::ssize_t>(sh.theta.size()), sh.theta.data());
    d["closing_error"] = sh.closing_error;
    d["max_closing_error"] = sh.max_closing_error;
    d["error_estimate"] = sh.error_estimate;
    d["shape_status"] = sh.status;
    d["status"] = static_cast<int>(st.status);
    d["Fn"] = st.Fn;
    d["min_z"] = st.min_z;
    d["max_axial_strain"] = st.max_axial_strain;
    d["min_stretch"] = st.min_stretch;
    return d;
  }, py::arg("params"), py::arg("Ft"), py::arg("steps") = 200);

  // Single fiber: params = (EI, EA, l, alpha, w).
  m.def("fiber_critical_line_at", [](const darray& params, const darray& Ft, int errors, double tolerance) {
    if (params.ndim() != 1 || params.size() != 5)
      throw std::invalid_argument("gecko._core: a single fiber is 5 numbers (EI, EA, l, alpha, w)");
    const double* q = params.data();
    SingleFiber<double> f;
    f.EI = q[0]; f.EA = q[1]; f.l = q[2]; f.alpha = q[3]; f.w = q[4];
    const auto n = static_cast<std::size_t>(Ft.size());
    const double* ft = Ft.data();
    std::vector<critical_state<double>> out(n);
    {
      py::gil_scoped_release release;
      const auto o = line_options(std::nan(""), tolerance);
      if (errors == static_cast<int>(on_error::nan)) critical_line_at(f, ft, n, out.data(), o, nan_policy());
      else critical_line_at(f, ft, n, out.data(), o, default_policy());
    }
    return state_columns(out);
  }, py::arg("params"), py::arg("Ft"), py::arg("errors") = 0, py::arg("tolerance") = std::nan(""));

  m.def("seta_small_deformation", [](const darray& params) {
    return small_deformation(design_from(params));
  }, py::arg("params"));

  // Through the shared element loop (vectorize.hpp): an out-of-range element is named by its index.
  m.def("kendall_fn", [](const darray& Ft, const darray& EA, const darray& w, int errors) {
    if (errors == static_cast<int>(on_error::nan))
      return map_elements([](double a, double b, double c) { return kendall_fn(a, b, c, nan_policy()); }, 0, Ft, EA, w);
    return map_elements([](double a, double b, double c) { return kendall_fn(a, b, c, default_policy()); }, 0, Ft, EA, w);
  }, py::arg("Ft"), py::arg("EA"), py::arg("w"), py::arg("errors") = 0);

  m.def("rivlin_fn", [](const darray& Ft, const darray& w, int errors) {
    if (errors == static_cast<int>(on_error::nan))
      return map_elements([](double a, double c) { return rivlin_fn(a, c, nan_policy()); }, 0, Ft, w);
    return map_elements([](double a, double c) { return rivlin_fn(a, c, default_policy()); }, 0, Ft, w);
  }, py::arg("Ft"), py::arg("w"), py::arg("errors") = 0);
}

// ---- the forward problem (gecko/seta/contact_state.hpp) ---------------------------------------
namespace {

struct contact_columns {
  py::array_t<double> a, contact_length, theta_joint, rate_joint, rate_base, strain, stretch, err, min_z;
  py::array_t<std::int32_t> tp, tp_beam, tp_spatula, equilibria, status;
  explicit contact_columns(py::ssize_t n)
      : a(n), contact_length(n), theta_joint(n), rate_joint(n), rate_base(n), strain(n), stretch(n), err(n), min_z(n), tp(n),
        tp_beam(n), tp_spatula(n), equilibria(n), status(n) {}
  void put(std::size_t i, const contact_result<double>& r) {
    a.mutable_data()[i] = r.a;
    contact_length.mutable_data()[i] = r.contact_length;
    theta_joint.mutable_data()[i] = r.theta_joint;
    rate_joint.mutable_data()[i] = r.theta_rate_joint;
    rate_base.mutable_data()[i] = r.theta_rate_base;
    strain.mutable_data()[i] = r.max_axial_strain;
    stretch.mutable_data()[i] = r.min_stretch;
    err.mutable_data()[i] = r.energy_release_rate;
    min_z.mutable_data()[i] = r.min_z;
    tp.mutable_data()[i] = r.turning_points;
    tp_beam.mutable_data()[i] = r.turning_points_beam;
    tp_spatula.mutable_data()[i] = r.turning_points_spatula;
    equilibria.mutable_data()[i] = r.equilibria;
    status.mutable_data()[i] = static_cast<std::int32_t>(r.status);
  }
  py::dict as_dict() const {
    py::dict d;
    d["a"] = a;
    d["contact_length"] = contact_length;
    d["theta_joint"] = theta_joint;
    d["theta_rate_joint"] = rate_joint;
    d["theta_rate_base"] = rate_base;
    d["turning_points"] = tp;
    d["turning_points_beam"] = tp_beam;
    d["turning_points_spatula"] = tp_spatula;
    d["max_axial_strain"] = strain;
    d["min_stretch"] = stretch;
    d["energy_release_rate"] = err;
    d["min_z"] = min_z;
    d["equilibria"] = equilibria;
    d["status"] = status;
    return d;
  }
};

template <class Policy>
py::dict contact_at(const TwoLevelSeta<double>& s, const darray& Fn, const darray& Ft, int scan_points,
                    int threads, bool all, double strain_limit) {
  if (Fn.ndim() != 1 || Ft.ndim() != 1 || Fn.size() != Ft.size())
    throw std::invalid_argument("gecko._core: Fn and Ft must be flat arrays of equal length");
  const auto n = static_cast<std::size_t>(Fn.size());
  contact_options<double> opt;
  if (scan_points > 0) opt.scan_points = scan_points;
  if (strain_limit == strain_limit) opt.strain_limit = strain_limit;
  const contact_solver<double, Policy> solve(s, opt);
  const double *fn = Fn.data(), *ft = Ft.data();
  const unsigned nt = threads_for(n, threads);
  if (!all) {
    std::vector<contact_result<double>> out(n);
    for_each_element(n, nt, [&](std::size_t i) { out[i] = solve(fn[i], ft[i]); });
    contact_columns cols(static_cast<py::ssize_t>(n));
    for (std::size_t i = 0; i < n; ++i) cols.put(i, out[i]);
    return cols.as_dict();
  }
  // Every equilibrium: rows (element, state), the summary status per element.
  std::vector<typename contact_solver<double, Policy>::all_result> out(n);
  for_each_element(n, nt, [&](std::size_t i) { out[i] = solve.equilibria(fn[i], ft[i]); });
  std::size_t rows = 0;
  for (const auto& r : out) rows += r.states.size();
  contact_columns cols(static_cast<py::ssize_t>(rows));
  py::array_t<std::int64_t> element(static_cast<py::ssize_t>(rows));
  py::array_t<std::int32_t> summary(static_cast<py::ssize_t>(n));
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    summary.mutable_data()[i] = static_cast<std::int32_t>(out[i].status);
    for (const auto& st : out[i].states) {
      element.mutable_data()[k] = static_cast<std::int64_t>(i);
      cols.put(k++, st);
    }
  }
  py::dict d = cols.as_dict();
  d["element"] = element;
  d["summary_status"] = summary;
  return d;
}

}  // namespace

void bind_seta_contact(py::module_& m) {
  // The statuses of gecko/seta/contact_state.hpp as a Python IntEnum (equal to the integers in the
  // result arrays); the upper-case names are the package's public ones.
  py::native_enum<contact_status>(m, "ContactStatus", "enum.IntEnum",
                                  "Status of a contact state (gecko/seta/contact_state.hpp); the numbers "
                                  "shared with the critical line's statuses mean the same.")
      .value("CONVERGED", contact_status::converged,
             "one equilibrium, its contact edge on the spatula (l1 < a <= l1 + l2)")
      .value("NOT_CONVERGED", contact_status::not_converged,
             "a root could not be refined, or the scan could not decide")
      .value("NO_CONTACT", contact_status::no_contact, "below the critical line: no side contact at this load")
      .value("UNSUPPORTED_STATE", contact_status::unsupported_state,
             "outside the model's forms (axial load comparable to EA; l2 longer than one period of the "
             "spatula's orbit)")
      .value("BEYOND_JOINT", contact_status::beyond_joint,
             "the contact edge would pass the joint onto the beam (outside the model)")
      .value("INVALID_INPUT", contact_status::invalid_input, "bad input under errors='nan'")
      .value("SEVERAL_EQUILIBRIA", contact_status::several_equilibria,
             "more than one admissible equilibrium (count in `equilibria`; all of them with all_equilibria=True)")
      .value("INADMISSIBLE", contact_status::inadmissible,
             "equilibria exist but none is admissible: the seta crosses the substrate before the edge, or "
             "exceeds strain_limit (values kept for drawing)")
      .finalize();
  m.def("seta_contact_state", [](const darray& params, const darray& Fn, const darray& Ft, int errors,
                                 bool all, int scan_points, int threads, double strain_limit) {
    const auto s = design_from(params);
    if (errors == static_cast<int>(on_error::nan))
      return contact_at<nan_policy>(s, Fn, Ft, scan_points, threads, all, strain_limit);
    return contact_at<default_policy>(s, Fn, Ft, scan_points, threads, all, strain_limit);
  }, py::arg("params"), py::arg("Fn"), py::arg("Ft"), py::arg("errors") = 0, py::arg("all") = false,
     py::arg("scan_points") = 0, py::arg("threads") = 0, py::arg("strain_limit") = std::nan(""));
}

}  // namespace bindings
}  // namespace gecko
