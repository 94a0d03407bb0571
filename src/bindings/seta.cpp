// Python bindings of gecko/seta and gecko/peel (see python/gecko/seta.py for the public wrappers).
// Designs travel as 9 doubles (EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w); arrays are flat
// float64; every C++ loop runs without the GIL (errors raised inside leave the released scope
// normally, so pybind11 re-acquires the GIL before turning std::domain_error into ValueError).
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

// Columns of critical states.
struct state_columns {
  py::array_t<double> Fn, theta_joint, rate_joint, rate_base, min_z, min_z_at, max_strain;
  py::array_t<std::int32_t> status, iterations, tp_beam, tp_spatula;
  explicit state_columns(py::ssize_t n)
      : Fn(n), theta_joint(n), rate_joint(n), rate_base(n), min_z(n), min_z_at(n), max_strain(n), status(n),
        iterations(n), tp_beam(n), tp_spatula(n) {}
  struct raw {
    double *Fn, *theta_joint, *rate_joint, *rate_base, *min_z, *min_z_at, *max_strain;
    std::int32_t *status, *iterations, *tp_beam, *tp_spatula;
    void put(std::size_t i, const critical_state<double>& s) const {
      min_z[i] = s.min_z;
      min_z_at[i] = s.min_z_at;
      max_strain[i] = s.max_axial_strain;
      Fn[i] = s.Fn;
      theta_joint[i] = s.theta_joint;
      rate_joint[i] = s.theta_rate_joint;
      rate_base[i] = s.theta_rate_base;
      status[i] = static_cast<std::int32_t>(s.status);
      iterations[i] = s.iterations;
      tp_beam[i] = s.turning_points_beam;
      tp_spatula[i] = s.turning_points_spatula;
    }
  };
  raw pointers() {
    return {Fn.mutable_data(), theta_joint.mutable_data(), rate_joint.mutable_data(), rate_base.mutable_data(),
            min_z.mutable_data(), min_z_at.mutable_data(), max_strain.mutable_data(), status.mutable_data(), iterations.mutable_data(), tp_beam.mutable_data(), tp_spatula.mutable_data()};
  }
  py::dict as_dict() const {
    py::dict d;
    d["Fn"] = Fn;
    d["theta_joint"] = theta_joint;
    d["theta_rate_joint"] = rate_joint;
    d["theta_rate_base"] = rate_base;
    d["status"] = status;
    d["iterations"] = iterations;
    d["turning_points_beam"] = tp_beam;
    d["turning_points_spatula"] = tp_spatula;
    d["min_z"] = min_z;
    d["min_z_at"] = min_z_at;
    d["max_axial_strain"] = max_strain;
    return d;
  }
};

void line_at(const TwoLevelSeta<double>& s, const double* Ft, std::size_t n, int errors,
             const critical_line_options<double>& o, std::vector<critical_state<double>>& out) {
  out.resize(n);
  if (errors == static_cast<int>(on_error::nan)) critical_line_at(s, Ft, n, out.data(), o, nan_policy());
  else critical_line_at(s, Ft, n, out.data(), o, default_policy());
}

}  // namespace

void bind_seta_contact(py::module_& m);  // the forward problem, at the end of this file

void bind_seta(py::module_& m) {
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
    state_columns cols(static_cast<py::ssize_t>(n));
    auto raw = cols.pointers();
    const double* f = Ft.data();
    const auto o = line_options(std::nan(""), tolerance, strain_limit);
    {
      py::gil_scoped_release release;
      std::vector<critical_state<double>> out;
      line_at(s, f, n, errors, o, out);
      for (std::size_t i = 0; i < n; ++i) raw.put(i, out[i]);
    }
    return cols.as_dict();
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
    const auto n = static_cast<py::ssize_t>(r.points.size());
    py::array_t<double> Ft(n), Fn(n), beta(n), rj(n), rb(n), mz(n), mza(n), mst(n);
    py::array_t<std::int32_t> tpb(n), tps(n), branch(n), status(n);
    for (py::ssize_t i = 0; i < n; ++i) {
      const auto& p = r.points[static_cast<std::size_t>(i)];
      status.mutable_data()[i] = static_cast<std::int32_t>(p.status);
      Ft.mutable_data()[i] = p.Ft;
      Fn.mutable_data()[i] = p.Fn;
      beta.mutable_data()[i] = p.theta_joint;
      rj.mutable_data()[i] = p.theta_rate_joint;
      rb.mutable_data()[i] = p.theta_rate_base;
      tpb.mutable_data()[i] = p.turning_points_beam;
      tps.mutable_data()[i] = p.turning_points_spatula;
      branch.mutable_data()[i] = p.branch;
      mz.mutable_data()[i] = p.min_z;
      mza.mutable_data()[i] = p.min_z_at;
      mst.mutable_data()[i] = p.max_axial_strain;
    }
    py::dict d;
    d["Ft"] = Ft;
    d["Fn"] = Fn;
    d["theta_joint"] = beta;
    d["theta_rate_joint"] = rj;
    d["theta_rate_base"] = rb;
    d["turning_points_beam"] = tpb;
    d["turning_points_spatula"] = tps;
    d["branch"] = branch;
    d["status"] = status;
    d["min_z"] = mz;
    d["min_z_at"] = mza;
    d["max_axial_strain"] = mst;
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
    py::dict d;
    d["Ft"] = r.Ft;
    d["Fn"] = r.Fn;
    d["theta_joint"] = r.theta_joint;
    d["status"] = static_cast<int>(r.status);
    d["iterations"] = r.iterations;
    d["theta_rate_joint"] = r.theta_rate_joint;
    d["theta_rate_base"] = r.theta_rate_base;
    d["turning_points_beam"] = r.turning_points_beam;
    d["turning_points_spatula"] = r.turning_points_spatula;
    d["min_z"] = r.min_z;
    d["min_z_at"] = r.min_z_at;
    d["max_axial_strain"] = r.max_axial_strain;
    return d;
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
    py::dict d;
    d["fn0"] = c.fn0;
    d["slope_k"] = c.slope_k;
    d["min_fn"] = c.min_fn;
    d["ft_at_min_fn"] = c.ft_at_min_fn;
    d["min_fn_interior"] = c.min_fn_interior;
    d["min_status"] = static_cast<int>(c.min_status);
    d["slope_at_min_fn"] = c.slope_at_min_fn;
    d["max_pull_off"] = c.max_pull_off;
    d["ft_max"] = c.ft_max;
    d["ft_at_line_end"] = c.ft_at_line_end;
    d["fn_at_line_end"] = c.fn_at_line_end;
    d["sticky_at_rest"] = c.sticky_at_rest;
    d["end"] = static_cast<int>(c.end);
    d["folds"] = py::cast(c.folds);
    d["small_fn0"] = c.small.fn0;
    d["small_slope_k"] = c.small.slope_k;
    d["small_contact_length"] = c.small.contact_length;
    d["small_non_sticky"] = c.small.non_sticky;
    d["admissible_to_end"] = c.admissible_to_end;
    d["admissible_end_ft"] = c.admissible_end_ft;
    d["admissible_end_fn"] = c.admissible_end_fn;
    d["slope_at_zero"] = c.slope_at_zero;
    d["paper_k"] = c.paper_k;
    d["max_pull_off_is_bound"] = c.max_pull_off_is_bound;
    d["max_pull_off_bound"] = c.max_pull_off_bound;
    return d;
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
    state_columns cols(static_cast<py::ssize_t>(nd * m_ft));
    auto raw = cols.pointers();
    const double* p = designs.data();
    const double* f = Ft.data();
    {
      py::gil_scoped_release release;
      std::vector<TwoLevelSeta<double>> ds(nd);
      for (std::size_t i = 0; i < nd; ++i) ds[i] = design_from(p + 9 * i);
      std::vector<critical_state<double>> out(nd * m_ft);
      const auto o = line_options(std::nan(""), tolerance, strain_limit);
      const unsigned nt = threads > 0 ? static_cast<unsigned>(threads) : 1u;
      if (errors == static_cast<int>(on_error::nan)) critical_line_batch(ds.data(), nd, f, m_ft, out.data(), nt, o, nan_policy());
      else critical_line_batch(ds.data(), nd, f, m_ft, out.data(), nt, o, default_policy());
      for (std::size_t i = 0; i < out.size(); ++i) raw.put(i, out[i]);
    }
    return cols.as_dict();
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
    const auto n = static_cast<py::ssize_t>(nd);
    py::array_t<double> fn0(n), slope_k(n), min_fn(n), ft_at_min_fn(n), max_pull_off(n), ftmax(n),
        ft_end_(n), fn_end(n), small_fn0(n), small_k(n), small_lc(n), adm_ft(n), adm_fn(n), k0(n), pk(n),
        pbound(n);
    py::array_t<std::int8_t> sticky(n), small_ns(n), interior(n), adm_all(n), is_bound(n);
    double* p_adm_ft = adm_ft.mutable_data();
    double* p_adm_fn = adm_fn.mutable_data();
    std::int8_t* p_adm_all = adm_all.mutable_data();
    double* p_k0 = k0.mutable_data();
    double* p_pk = pk.mutable_data();
    double* p_pbound = pbound.mutable_data();
    std::int8_t* p_is_bound = is_bound.mutable_data();
    py::array_t<std::int32_t> status(n), end(n), folds(n);
    struct raw_t {
      double *fn0, *k, *min_fn, *ft_min, *pull, *ftmax, *ft_end, *fn_end, *sfn0, *sk, *slc;
      std::int8_t *sticky, *sns, *interior;
      std::int32_t *status, *end, *folds;
    } r{fn0.mutable_data(), slope_k.mutable_data(), min_fn.mutable_data(), ft_at_min_fn.mutable_data(),
        max_pull_off.mutable_data(), ftmax.mutable_data(), ft_end_.mutable_data(), fn_end.mutable_data(),
        small_fn0.mutable_data(), small_k.mutable_data(), small_lc.mutable_data(), sticky.mutable_data(),
        small_ns.mutable_data(), interior.mutable_data(), status.mutable_data(), end.mutable_data(),
        folds.mutable_data()};
    const double* p = designs.data();
    {
      py::gil_scoped_release release;
      std::vector<TwoLevelSeta<double>> ds(nd);
      for (std::size_t i = 0; i < nd; ++i) ds[i] = design_from(p + 9 * i);
      std::vector<design_characteristics<double>> out(nd);
      characteristics_batch(ds.data(), nd, how, out.data(), threads > 0 ? static_cast<unsigned>(threads) : 1u);
      for (std::size_t i = 0; i < nd; ++i) {
        const auto& c = out[i];
        r.fn0[i] = c.fn0;
        r.k[i] = c.slope_k;
        r.min_fn[i] = c.min_fn;
        r.ft_min[i] = c.ft_at_min_fn;
        r.pull[i] = c.max_pull_off;
        r.ftmax[i] = c.ft_max;
        r.ft_end[i] = c.ft_at_line_end;
        r.fn_end[i] = c.fn_at_line_end;
        r.sfn0[i] = c.small.fn0;
        r.sk[i] = c.small.slope_k;
        r.slc[i] = c.small.contact_length;
        r.sticky[i] = static_cast<std::int8_t>(c.sticky_at_rest);
        r.sns[i] = static_cast<std::int8_t>(c.small.non_sticky);
        r.interior[i] = static_cast<std::int8_t>(c.min_fn_interior);
        r.status[i] = static_cast<std::int32_t>(c.status);
        r.end[i] = how == characteristics_depth::whole_line ? static_cast<std::int32_t>(c.end) : -1;
        r.folds[i] = c.folds;
        p_adm_ft[i] = c.admissible_end_ft;
        p_adm_fn[i] = c.admissible_end_fn;
        p_adm_all[i] = static_cast<std::int8_t>(c.admissible_to_end);
        p_k0[i] = c.slope_at_zero;
        p_pk[i] = c.paper_k;
        p_pbound[i] = c.max_pull_off_bound;
        p_is_bound[i] = static_cast<std::int8_t>(c.max_pull_off_is_bound);
      }
    }
    py::dict d;
    d["status"] = status;
    d["fn0"] = fn0;
    d["slope_k"] = slope_k;
    d["sticky_at_rest"] = sticky;
    d["min_fn"] = min_fn;
    d["ft_at_min_fn"] = ft_at_min_fn;
    d["min_fn_interior"] = interior;
    d["max_pull_off"] = max_pull_off;
    d["ft_max"] = ftmax;
    d["ft_at_line_end"] = ft_end_;
    d["fn_at_line_end"] = fn_end;
    d["line_end"] = end;
    d["folds"] = folds;
    d["small_fn0"] = small_fn0;
    d["small_slope_k"] = small_k;
    d["small_contact_length"] = small_lc;
    d["small_non_sticky"] = small_ns;
    d["admissible_end_ft"] = adm_ft;
    d["admissible_end_fn"] = adm_fn;
    d["admissible_to_end"] = adm_all;
    d["slope_at_zero"] = k0;
    d["paper_k"] = pk;
    d["max_pull_off_bound"] = pbound;
    d["max_pull_off_is_bound"] = is_bound;
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
    state_columns cols(static_cast<py::ssize_t>(n));
    auto raw = cols.pointers();
    const double* ft = Ft.data();
    {
      py::gil_scoped_release release;
      std::vector<critical_state<double>> out(n);
      const auto o = line_options(std::nan(""), tolerance);
      if (errors == static_cast<int>(on_error::nan)) critical_line_at(f, ft, n, out.data(), o, nan_policy());
      else critical_line_at(f, ft, n, out.data(), o, default_policy());
      for (std::size_t i = 0; i < n; ++i) raw.put(i, out[i]);
    }
    return cols.as_dict();
  }, py::arg("params"), py::arg("Ft"), py::arg("errors") = 0, py::arg("tolerance") = std::nan(""));

  m.def("seta_small_deformation", [](const darray& params) {
    const auto c = small_deformation(design_from(params));
    py::dict d;
    d["fn0"] = c.fn0;
    d["slope_k"] = c.slope_k;
    d["contact_length"] = c.contact_length;
    d["non_sticky"] = c.non_sticky;
    return d;
  }, py::arg("params"));

  m.def("kendall_fn", [](const darray& Ft, const darray& EA, const darray& w, int errors) {
    const py::ssize_t n = Ft.size();
    if (EA.size() != n || w.size() != n) throw std::invalid_argument("gecko._core: array arguments must have equal length");
    py::array_t<double> out(n);
    double* o = out.mutable_data();
    const double *a = Ft.data(), *b = EA.data(), *c = w.data();
    {
      py::gil_scoped_release release;
      for (py::ssize_t i = 0; i < n; ++i)
        o[i] = errors == static_cast<int>(on_error::nan) ? kendall_fn(a[i], b[i], c[i], nan_policy())
                                                         : kendall_fn(a[i], b[i], c[i], default_policy());
    }
    return out;
  }, py::arg("Ft"), py::arg("EA"), py::arg("w"), py::arg("errors") = 0);

  m.def("rivlin_fn", [](const darray& Ft, const darray& w, int errors) {
    const py::ssize_t n = Ft.size();
    if (w.size() != n) throw std::invalid_argument("gecko._core: array arguments must have equal length");
    py::array_t<double> out(n);
    double* o = out.mutable_data();
    const double *a = Ft.data(), *c = w.data();
    {
      py::gil_scoped_release release;
      for (py::ssize_t i = 0; i < n; ++i)
        o[i] = errors == static_cast<int>(on_error::nan) ? rivlin_fn(a[i], c[i], nan_policy())
                                                         : rivlin_fn(a[i], c[i], default_policy());
    }
    return out;
  }, py::arg("Ft"), py::arg("w"), py::arg("errors") = 0);
}

// ---- the forward problem (gecko/seta/contact_state.hpp) ---------------------------------------
namespace {

struct contact_columns {
  py::array_t<double> a, contact_length, theta_joint, rate_joint, rate_base, strain, err, min_z;
  py::array_t<std::int32_t> tp, tp_beam, tp_spatula, equilibria, status;
  explicit contact_columns(py::ssize_t n)
      : a(n), contact_length(n), theta_joint(n), rate_joint(n), rate_base(n), strain(n), err(n), min_z(n), tp(n),
        tp_beam(n), tp_spatula(n), equilibria(n), status(n) {}
  void put(std::size_t i, const contact_result<double>& r) {
    a.mutable_data()[i] = r.a;
    contact_length.mutable_data()[i] = r.contact_length;
    theta_joint.mutable_data()[i] = r.theta_joint;
    rate_joint.mutable_data()[i] = r.theta_rate_joint;
    rate_base.mutable_data()[i] = r.theta_rate_base;
    strain.mutable_data()[i] = r.max_axial_strain;
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
