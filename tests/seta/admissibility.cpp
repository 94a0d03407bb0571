// Tests of gecko/seta/admissibility.hpp: the lowest point of the deformed seta and its largest
// axial strain, against an independent dense evaluation (RK4 integration of the governing ODE,
// paper 001 eqs (1)-(2), in long double from the base, z tracked at every step), and the status 7
// ("inadmissible") in every solver.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "gecko/elliptic.hpp"
#include "gecko/seta/admissibility.hpp"
#include "gecko/seta/batch.hpp"
#include "gecko/seta/characteristics.hpp"
#include "gecko/seta/critical_line.hpp"
#include "random_designs.hpp"

namespace {

struct dense_result {
  long double min_z, where, max_strain, edge_theta;
  long double min_stretch = 1;  // the lowest 1 + T/EA over the samples (dense_reference_from_edge)
};

// The governing ODE (paper 001 eqs (1)-(2)) for theta, theta' and z along s, in long double, with
// one classical RK4 step.
struct dense_ode {
  struct Y { long double th, om, z; };
  long double Fn, Ft, c1, c2;
  dense_ode(const gecko::TwoLevelSeta<double>& s, const gecko::critical_state<double>& st)
      : Fn(st.Fn), Ft(st.Ft), c1(std::isinf(s.EA1) ? 0.0L : 1.0L / s.EA1),
        c2(std::isinf(s.EA2) ? 0.0L : 1.0L / s.EA2) {}
  long double axial(const Y& y) const { return Ft * std::sin(y.th) - Fn * std::cos(y.th); }
  long double strain(const Y& y, long double c) const { return std::fabs(c * axial(y)); }
  long double stretch(const Y& y, long double c) const { return 1 + c * axial(y); }
  Y rhs(const Y& y, long double EI, long double c) const {
    const long double T = axial(y);
    return Y{y.om, -(Fn * std::sin(y.th) + Ft * std::cos(y.th)) * (1 + c * T) / EI, -(1 + c * T) * std::cos(y.th)};
  }
  Y step(const Y& y, long double h, long double EI, long double c) const {
    const Y k1 = rhs(y, EI, c);
    const Y k2 = rhs({y.th + h / 2 * k1.th, y.om + h / 2 * k1.om, y.z + h / 2 * k1.z}, EI, c);
    const Y k3 = rhs({y.th + h / 2 * k2.th, y.om + h / 2 * k2.om, y.z + h / 2 * k2.z}, EI, c);
    const Y k4 = rhs({y.th + h * k3.th, y.om + h * k3.om, y.z + h * k3.z}, EI, c);
    return Y{y.th + h / 6 * (k1.th + 2 * k2.th + 2 * k3.th + k4.th),
             y.om + h / 6 * (k1.om + 2 * k2.om + 2 * k3.om + k4.om),
             y.z + h / 6 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z)};
  }
};

// The extreme value of the parabola through three equally spaced samples a, b, c (b the extreme
// sample): an interior extremum of a smooth function, where the sample alone is off by O(h^2).
long double parabola_extremum(long double a, long double b, long double c) {
  return b - (c - a) * (c - a) / (8 * (a - 2 * b + c));
}

// theta, theta', x, z along s from the base; z relative to the contact edge at the end.
dense_result dense_reference(const gecko::TwoLevelSeta<double>& s, const gecko::critical_state<double>& st,
                             int steps_per_unit = 20000) {
  const dense_ode ode(s, st);
  using Y = dense_ode::Y;
  const long double c1 = ode.c1, c2 = ode.c2;
  auto strain = [&](const Y& y, long double c) { return ode.strain(y, c); };
  std::vector<long double> zs, ss, es;
  Y y{s.alpha1, st.theta_rate_base, 0};
  zs.push_back(0);
  ss.push_back(0);
  es.push_back(strain(y, c1));
  auto run = [&](long double len, long double EI, long double c, long double s0) {
    const int n = std::max(400, static_cast<int>(steps_per_unit * len));
    const long double h = len / n;
    if (!es.empty()) es.back() = std::max(es.back(), strain(y, c));
    for (int i = 0; i < n; ++i) {
      y = ode.step(y, h, EI, c);
      zs.push_back(y.z);
      ss.push_back(s0 + h * (i + 1));
      es.push_back(strain(y, c));
    }
  };
  run(s.l1, s.EI1, c1, 0);
  const std::size_t joint = zs.size() - 1;
  y.th += s.alpha2;
  y.om *= s.EI1 / s.EI2;
  run(s.l2, s.EI2, c2, s.l1);
  // Extrema of the samples, refined by the parabola through the neighbours.
  auto refine = [&](const std::vector<long double>& v, std::size_t i, long double sign) {
    if (i == 0 || i + 1 >= v.size() || i == joint) return v[i];  // an end or the kink
    if (!(sign * (v[i - 1] - 2 * v[i] + v[i + 1]) < 0)) return v[i];
    return parabola_extremum(v[i - 1], v[i], v[i + 1]);
  };
  dense_result r{0, 0, 0, y.th};
  std::size_t imax = 0;
  for (std::size_t i = 0; i < es.size(); ++i)
    if (es[i] > es[imax]) imax = i;
  r.max_strain = refine(es, imax, 1);
  const long double z_edge = zs.back();
  r.min_z = 0;
  r.where = s.l1 + s.l2;
  std::size_t imin = zs.size() - 1;
  for (std::size_t i = 0; i < zs.size(); ++i)
    if (zs[i] - z_edge < r.min_z) {
      r.min_z = zs[i] - z_edge;
      r.where = ss[i];
      imin = i;
    }
  if (r.min_z < 0) r.min_z = refine(zs, imin, -1) - z_edge;
  return r;
}

// The same evaluation shot backwards from the contact edge (theta = pi/2, z = 0, EI2 theta'^2/2 =
// w - Ft^2/(2 EA2) from Griffith's condition, the sign that meets the state's theta at the joint):
// where a beam passes next to a saddle of its first integral, the shot from the base amplifies the
// rounding of theta1'(0) and this one, started from exact data, does not (the state's own Fn is
// used, so it checks the heights, not the root).
dense_result dense_reference_from_edge(const gecko::TwoLevelSeta<double>& s, const gecko::critical_state<double>& st,
                                       int steps_per_unit = 20000) {
  const dense_ode ode(s, st);
  using Y = dense_ode::Y;
  const long double c1 = ode.c1, c2 = ode.c2, Ft = st.Ft;
  auto strain = [&](const Y& y, long double c) { return ode.strain(y, c); };
  const long double pi_2 = std::acos(-1.0L) / 2;
  const long double rate = std::sqrt(2 * (s.w - c2 * Ft * Ft / 2) / s.EI2);
  dense_result best{0, 0, 0, 0};
  long double best_miss = std::numeric_limits<long double>::infinity();
  for (const long double sign : {1.0L, -1.0L}) {
    Y y{pi_2, sign * rate, 0};
    dense_result r{0, s.l1 + s.l2, strain(y, c2), 0, ode.stretch(y, c2)};
    auto run = [&](long double len, long double EI, long double c, long double s_end) {
      const int n = std::max(400, static_cast<int>(steps_per_unit * len));
      const long double h = -len / n;
      Y prev2 = y, prev = y;
      for (int i = 0; i < n; ++i) {
        prev2 = prev;
        prev = y;
        y = ode.step(y, h, EI, c);
        r.max_strain = std::max(r.max_strain, strain(y, c));
        r.min_stretch = std::min(r.min_stretch, ode.stretch(y, c));
        if (i >= 1) {  // an interior minimum of the stretch at the previous sample: refined the same way
          const long double a = ode.stretch(prev2, c), b = ode.stretch(prev, c), e = ode.stretch(y, c);
          if (b < a && b < e && a - 2 * b + e > 0) r.min_stretch = std::min(r.min_stretch, parabola_extremum(a, b, e));
        }
        if (y.z < r.min_z) {
          r.min_z = y.z;
          r.where = s_end + h * (i + 1);
        }
        // an interior minimum at the previous sample: refine by the parabola through its neighbours
        if (i >= 1 && prev.z < prev2.z && prev.z < y.z && prev2.z - 2 * prev.z + y.z > 0)
          r.min_z = std::min(r.min_z, parabola_extremum(prev2.z, prev.z, y.z));
      }
    };
    run(s.l2, s.EI2, c2, s.l1 + s.l2);
    const long double miss = std::fabs(y.th - static_cast<long double>(st.theta_joint));
    y.th -= s.alpha2;
    y.om *= s.EI2 / s.EI1;
    r.max_strain = std::max(r.max_strain, strain(y, c1));
    r.min_stretch = std::min(r.min_stretch, ode.stretch(y, c1));
    run(s.l1, s.EI1, c1, s.l1);
    if (miss < best_miss) {
      best_miss = miss;
      best = r;
    }
  }
  return best;
}

gecko::TwoLevelSeta<double> reference_with_alpha2(double alpha2) {
  gecko::TwoLevelSeta<double> s;
  s.alpha2 = alpha2;
  return s;
}

}  // namespace

TEST_CASE("the paper's reference design with alpha2 = 1.0 crosses the substrate near (Ft)max",
          "[seta][admissibility]") {
  const auto s = reference_with_alpha2(1.0);
  const auto st = gecko::critical_line_at(s, std::vector<double>{0.0, 5.0, 9.999});
  REQUIRE(st[0].status == gecko::critical_status::converged);
  CHECK(st[0].min_z == 0.0);
  CHECK(st[0].max_axial_strain >= 0.0);
  REQUIRE(st[2].status == gecko::critical_status::inadmissible);
  // Kept for drawing: the solved values are there.
  CHECK(std::isfinite(st[2].Fn));
  CHECK(std::isfinite(st[2].theta_joint));
  const auto ref = dense_reference(s, st[2]);
  INFO("min_z " << st[2].min_z << " reference " << static_cast<double>(ref.min_z) << " at "
                << st[2].min_z_at << " / " << static_cast<double>(ref.where));
  CHECK(st[2].min_z < -5e-4);
  CHECK(st[2].min_z > -5e-3);
  CHECK(std::fabs(st[2].min_z - static_cast<double>(ref.min_z)) < 1e-9);
  CHECK(std::fabs(st[2].min_z_at - static_cast<double>(ref.where)) < 1e-3);
  CHECK(std::fabs(st[2].max_axial_strain - static_cast<double>(ref.max_strain)) < 1e-9);
  // The same verdict from the one-state solver and the public check.
  gecko::critical_guess<double> g{st[2].Fn, st[2].theta_joint, st[2].theta_rate_joint, st[2].theta_rate_base};
  const auto one = gecko::solve_critical(s, 9.999, g);
  CHECK(one.status == gecko::critical_status::inadmissible);
  CHECK(std::fabs(one.min_z - st[2].min_z) < 1e-12);
  const auto chk = gecko::admissibility_check(s, st[2]);
  CHECK_FALSE(chk.admissible);
  CHECK(chk.crosses_substrate);
}

TEST_CASE("reference design: admissible up to near (Ft)max; strain reaches 20 % there", "[seta][admissibility]") {
  gecko::TwoLevelSeta<double> s;
  const double fm = gecko::ft_max(s);
  const auto st = gecko::critical_line_at(s, std::vector<double>{0.0, 2.0, 7.0, 9.9, fm});
  for (const auto& x : st) {
    const auto ref = dense_reference(s, x, 4000);
    CHECK(std::fabs(x.max_axial_strain - static_cast<double>(ref.max_strain)) < 1e-9);
    CHECK(std::fabs(x.min_z - static_cast<double>(ref.min_z)) < 1e-9);
    if (x.Ft == fm) continue;
    REQUIRE(x.status == gecko::critical_status::converged);
    CHECK(x.min_z == 0.0);
  }
  // At (Ft)max the contact edge is a turning point (theta2'(a) = 0) and theta2 > pi/2 just before
  // it (EI2 theta2'' = -Fn (1 + Ft/EA2) > 0 there for Fn < 0): the spatula approaches the edge
  // from below, with the joint lowest, ~4.4e-5 l1 under the substrate.
  CHECK(st.back().status == gecko::critical_status::inadmissible);
  CHECK(st.back().min_z < -4e-5);
  CHECK(st.back().min_z_at == Approx(s.l1).epsilon(1e-12));
  CHECK(st.back().max_axial_strain == Approx(0.2).epsilon(1e-12));
  // A strain limit turns the states above it into status 7, values kept.
  gecko::critical_line_options<double> opt;
  opt.strain_limit = 0.15;
  const auto lim = gecko::critical_line_at(s, std::vector<double>{2.0, 9.9}, opt);
  CHECK(lim[0].status == gecko::critical_status::converged);
  CHECK(lim[1].status == gecko::critical_status::inadmissible);
  CHECK(lim[1].Fn == Approx(st[3].Fn).epsilon(1e-12));
}

TEST_CASE("random critical states: min z against a dense ODE evaluation", "[seta][admissibility][random]") {
  std::uint64_t seed = 0x5eed0013ULL;
  int crossing = 0, checked = 0, slow_path = 0;
  for (int i = 0; i < 60; ++i) {
    auto s = seta_test::sweep_box_design(seed);
    std::vector<double> ft;
    const double fm = gecko::ft_max(s);
    for (int k = 0; k < 5; ++k) ft.push_back(fm * (0.2 * k + 0.19));
    const auto st = gecko::critical_line_at(s, ft);
    for (const auto& x : st) {
      if (x.status != gecko::critical_status::converged && x.status != gecko::critical_status::inadmissible) continue;
      REQUIRE(x.min_z == x.min_z);  // the check was made
      const auto ref = dense_reference(s, x, 4000);
      INFO("design " << i << " Ft " << x.Ft << " min_z " << x.min_z << " ref " << static_cast<double>(ref.min_z)
                     << " edge " << static_cast<double>(ref.edge_theta));
      CHECK(std::fabs(x.min_z - static_cast<double>(ref.min_z)) < 1e-9);
      CHECK(std::fabs(x.max_axial_strain - static_cast<double>(ref.max_strain)) < 1e-9);
      CHECK((x.status == gecko::critical_status::inadmissible) == (ref.min_z < -1e-9));
      const auto chk = gecko::admissibility_check(s, x);
      if (!chk.exact_fast_path) ++slow_path;
      crossing += x.status == gecko::critical_status::inadmissible;
      ++checked;
    }
  }
  INFO("checked " << checked << " crossing " << crossing << " slow path " << slow_path);
  CHECK(checked > 200);
  CHECK(crossing > 0);
}

TEST_CASE("libration pieces in chi: length and height against the closed forms in F and E",
          "[seta][admissibility][chi]") {
  // An inextensible libration (f4 = 1) in the pendulum's variable chi, sin(omega/2) = k sin(chi):
  //   s = sqrt(EI/N) F(chi|k^2), and with cos(theta) = 2 k Delta sin(chi) cos(phi) + (2 Delta^2 - 1)
  //   sin(phi), z = -sqrt(EI/N) (-2 k cos(chi) cos(phi) + (2 E(chi|k^2) - F(chi|k^2)) sin(phi))
  // (DLMF 19.2.4, 19.2.5): the quadrature of gecko/seta/admissibility.hpp against Legendre's
  // integrals (tested against mpmath in tests/elliptic) over random windows and pieces, from deep
  // librations to next to the separatrix (up = 0.9999, k' = 0.007), on pieces within a half-period
  // and on paths through turning angles.
  using namespace gecko::detail;
  std::uint64_t seed = 0xc41f0013ULL;
  const double pi_2 = 1.5707963267948966;
  double worst = 0;
  int pieces = 0;
  for (int i = 0; i < 400; ++i) {
    const double EI = 0.1 + 9.9 * seta_test::uniform01(seed), N = 0.1 + 9.9 * seta_test::uniform01(seed);
    const double up = i % 4 == 3 ? 1 - std::pow(10.0, -1 - 3 * seta_test::uniform01(seed))
                                 : -0.99 + 1.98 * seta_test::uniform01(seed);
    const double phi = -3 + 6 * seta_test::uniform01(seed);
    const auto g = make_height_segment(EI, 0.0, N * up, N, phi, std::sin(phi), std::cos(phi));
    const auto f = make_libration_frame(g);
    const double m = (1 + up) / 2, k = std::sqrt(m);
    double xa = -pi_2 + pi_2 * 2 * seta_test::uniform01(seed), xb = -pi_2 + pi_2 * 2 * seta_test::uniform01(seed);
    if (i % 5 == 0) xa = -pi_2, xb = pi_2;  // a whole half-period, turning angle to turning angle
    // through one to three turning angles: chi runs on past +-pi/2 (height_walk joins the pieces),
    // where F and E continue quasi-periodically
    if (i % 7 == 3) xb = xa + (i % 2 ? 1 : -1) * pi_2 * (1.2 + 4 * seta_test::uniform01(seed));
    const double tol = 1e-13;
    double ds = 0, dz = 0;
    int budget = 1000;
    REQUIRE(height_adaptive_chi(g, f, xa, xb, tol, 0, budget, ds, dz));
    const double scale = std::sqrt(EI / N);
    auto len = [&](double x) { return gecko::ellint_f(x, m); };
    auto height = [&](double x) {
      return -scale * (-2 * k * std::cos(x) * std::cos(phi) + (2 * gecko::ellint_e(x, m) - len(x)) * std::sin(phi));
    };
    const double ref_ds = scale * std::fabs(len(xb) - len(xa));
    const double ref_dz = xb >= xa ? height(xb) - height(xa) : height(xa) - height(xb);
    const double bound = 1e-12 * (1 + ref_ds);
    INFO("i " << i << " up " << up << " chi " << xa << " .. " << xb << " ds " << ds << " ref " << ref_ds << " dz "
              << dz << " ref " << ref_dz);
    CHECK(std::fabs(ds - ref_ds) <= bound);
    CHECK(std::fabs(dz - ref_dz) <= bound);
    worst = std::max(worst, std::max(std::fabs(ds - ref_ds), std::fabs(dz - ref_dz)) / (1 + ref_ds));
    // chi of theta: omega = 2 asin(k sin(chi)) from the window's centre phi - pi/2
    if (std::fabs(xa) < 1.5) {
      const double theta = phi - pi_2 + 2 * std::asin(k * std::sin(xa));
      CHECK(std::fabs(libration_chi(g, theta, theta) - xa) <= 1e-12);
    }
    ++pieces;
  }
  INFO("pieces " << pieces << " worst relative miss " << worst);
  CHECK(pieces == 400);
}

TEST_CASE("inextensible beams with turning points kept inside by their first integral: as the general path",
          "[seta][admissibility][beam_bars]") {
  // admissibility_imp takes an inextensible beam with turning points (and a spatula without) as
  // monotone in z when its first integral bars theta = +-pi/2 on its path
  // (beam_first_integral_bars_level); the general path finds the range from the turning angles
  // (atan2, asin) instead. Both must give the same verdict, lowest point and strain, on random
  // designs (EA1 infinite, and EA1 = 200, where the test is never taken) and on the alpha2 = 1
  // reference line, whose upper part is such states.
  std::uint64_t seed = 0xbea0013ULL;
  int states = 0, barred = 0;
  auto compare = [&](const gecko::TwoLevelSeta<double>& s, const std::vector<double>& ft) {
    const auto d = gecko::detail::make_seta_params(s);
    for (const auto& x : gecko::critical_line_at(s, ft)) {
      if (!(x.Fn == x.Fn)) continue;
      const gecko::seta_pose<double> p{x.Fn, x.Ft, x.theta_joint, x.theta_rate_base, x.theta_rate_joint,
                                       x.turning_points_beam, x.turning_points_spatula,
                                       std::numeric_limits<double>::quiet_NaN()};
      const auto f = gecko::detail::make_pose_frame(d, p);
      const bool taken = p.turning_points_beam > 0 && p.turning_points_spatula == 0 && !(d.c1 > 0) &&
                         gecko::detail::beam_first_integral_bars_level(d, p, f, std::sqrt(p.Fn * p.Fn + p.Ft * p.Ft));
      const auto a = gecko::detail::admissibility_imp(d, p, std::numeric_limits<double>::infinity());
      const auto g = gecko::detail::admissibility_general(d, p, f, std::numeric_limits<double>::infinity());
      INFO("Ft " << x.Ft << " taken " << taken << " min_z " << a.min_z << " general " << g.min_z);
      CHECK(a.admissible == g.admissible);
      CHECK((a.min_z == g.min_z || (a.min_z != a.min_z && g.min_z != g.min_z)));
      if (g.max_axial_strain == g.max_axial_strain) CHECK(std::fabs(a.max_axial_strain - g.max_axial_strain) <= 1e-15);
      if (taken) CHECK(a.exact_fast_path);
      ++states;
      barred += taken;
    }
  };
  for (int i = 0; i < 120; ++i) {
    auto s = seta_test::sweep_box_design(seed);
    if (i % 2) s.EA1 = 200;
    std::vector<double> ft;
    const double fm = gecko::ft_max(s);
    for (int k = 0; k < 8; ++k) ft.push_back(fm * (-0.5 + 0.2 * k));
    compare(s, ft);
  }
  const int random_barred = barred;
  std::vector<double> line(200);
  for (std::size_t i = 0; i < line.size(); ++i) line[i] = 9.9 * static_cast<double>(i) / 199.0;
  compare(reference_with_alpha2(1.0), line);
  INFO("states " << states << " taken " << barred << " (random designs " << random_barred << ")");
  CHECK(random_barred > 50);
  CHECK(barred - random_barred > 100);
}

TEST_CASE("spatulas with one turning point kept inside by their first integral: as the general path",
          "[seta][admissibility][spatula_bars]") {
  // admissibility_imp takes a spatula with one turning point and beta <= pi/2 as monotone in z
  // when its first integral bars theta = -pi/2 on its way down (spatula_first_integral_bars_level);
  // the general path finds the range from the turning angle (atan2, asin) instead. Both must give
  // the same verdict, lowest point and strain (T's range from T+ and T' at the turning angle) on
  // random designs (EA2 finite, EA2 infinite in every third) and on the alpha2 = 1 reference line.
  std::uint64_t seed = 0x5ba7013ULL;
  int states = 0, taken_count = 0, turning = 0;
  auto compare = [&](const gecko::TwoLevelSeta<double>& s, const std::vector<double>& ft) {
    const auto d = gecko::detail::make_seta_params(s);
    for (const auto& x : gecko::critical_line_at(s, ft)) {
      if (!(x.Fn == x.Fn) || x.turning_points_spatula == 0) continue;
      const gecko::seta_pose<double> p{x.Fn, x.Ft, x.theta_joint, x.theta_rate_base, x.theta_rate_joint,
                                       x.turning_points_beam, x.turning_points_spatula,
                                       std::numeric_limits<double>::quiet_NaN()};
      const auto f = gecko::detail::make_pose_frame(d, p);
      double lo = 0, hi = 0;
      const bool taken = gecko::detail::spatula_first_integral_bars_level(
          d, p, f, std::sqrt(p.Fn * p.Fn + p.Ft * p.Ft), std::sin(p.theta_joint), std::cos(p.theta_joint), lo, hi);
      const auto a = gecko::detail::admissibility_imp(d, p, std::numeric_limits<double>::infinity());
      const auto g = gecko::detail::admissibility_general(d, p, f, std::numeric_limits<double>::infinity());
      INFO("Ft " << x.Ft << " taken " << taken << " min_z " << a.min_z << " general " << g.min_z << " strain "
                 << a.max_axial_strain << " general " << g.max_axial_strain);
      CHECK(a.admissible == g.admissible);
      CHECK((a.min_z == g.min_z || (a.min_z != a.min_z && g.min_z != g.min_z)));
      if (g.max_axial_strain == g.max_axial_strain)
        CHECK(std::fabs(a.max_axial_strain - g.max_axial_strain) <= 1e-15 * (1 + g.max_axial_strain));
      // where the test is taken, the general path must find theta inside [-pi/2, pi/2] as well
      if (taken) CHECK(g.exact_fast_path);
      ++states;
      taken_count += taken;
    }
  };
  for (int i = 0; i < 120; ++i) {
    auto s = seta_test::sweep_box_design(seed);
    if (i % 3 == 0) s.EA2 = std::numeric_limits<double>::infinity();
    std::vector<double> ft;
    const double fm = std::isinf(s.EA2) ? 3 * std::sqrt(s.EI1 * s.w) / s.l1 : gecko::ft_max(s);
    for (int k = 0; k < 8; ++k) ft.push_back(fm * (-0.5 + 0.2 * k));
    compare(s, ft);
  }
  const int random_taken = taken_count;
  turning = states;
  std::vector<double> line(200);
  for (std::size_t i = 0; i < line.size(); ++i) line[i] = 9.9 * static_cast<double>(i) / 199.0;
  compare(reference_with_alpha2(1.0), line);
  INFO("spatula-turning states " << states << " (random designs " << turning << "), taken " << taken_count
                                 << " (random designs " << random_taken << ")");
  CHECK(random_taken > 20);
  CHECK(taken_count - random_taken > 30);
}

TEST_CASE("injected states: a joint pushed below the substrate is caught", "[seta][admissibility]") {
  gecko::TwoLevelSeta<double> s;
  const auto st = gecko::critical_line_at(s, std::vector<double>{5.0})[0];
  REQUIRE(st.status == gecko::critical_status::converged);
  // Not a solution any more, but a pose: the spatula made to leave the joint past pi/2 with the
  // rates of a state that curls back to the edge; the quadrature must find the dip.
  gecko::seta_pose<double> p{st.Fn, st.Ft, st.theta_joint, st.theta_rate_base, st.theta_rate_joint,
                             st.turning_points_beam, st.turning_points_spatula,
                             std::numeric_limits<double>::quiet_NaN()};
  const auto ok = gecko::admissibility_check(s, p);
  CHECK(ok.admissible);
  CHECK(ok.exact_fast_path);
  const auto lim = gecko::admissibility_check(s, p, 1e-6);
  CHECK_FALSE(lim.admissible);
  CHECK(lim.strain_exceeded);
  CHECK_FALSE(lim.crosses_substrate);
}

TEST_CASE("traced line, batch and characteristics see status 7", "[seta][admissibility]") {
  const auto s = reference_with_alpha2(1.0);
  const auto line = gecko::critical_line(s);
  int bad = 0;
  for (const auto& p : line.points) bad += p.status == gecko::critical_status::inadmissible;
  CHECK(bad > 0);
  CHECK(line.points.front().status == gecko::critical_status::converged);
  std::vector<gecko::TwoLevelSeta<double>> designs{s, gecko::TwoLevelSeta<double>()};
  std::vector<double> ft{5.0, 9.999};
  std::vector<gecko::critical_state<double>> out(4);
  gecko::critical_line_batch(designs.data(), 2, ft.data(), 2, out.data(), 2);
  CHECK(out[1].status == gecko::critical_status::inadmissible);
  CHECK(out[3].status == gecko::critical_status::converged);
}

TEST_CASE("states the check once left unmade: large strains and turning angles next to the saddle",
          "[seta][admissibility][stress]") {
  // Poses of stress-campaign states (validation/data/stress_10000_states.npz) that the check used
  // to report as not made (min_z = NaN, hence status 7): an axial strain |T|/EA above 1 (in tension
  // the stretch stays positive and z monotone; in compression past EA the stretch changes sign, a
  // further place where z can turn), and beams whose turning angle lies next to the saddle, where
  // the first integral's constant formed from the rates misses the beam's length and the turning
  // angle is solved from the length instead (design 362: tests/seta/natural_state_paths.cpp).
  // Each is compared with the dense RK4 evaluation shot back from the contact edge (the shot from
  // the base is itself off by 1.5e-6 for design 2399: it starts from the rounded theta1'(0) next to
  // the saddle).
  struct row {
    double EI1, EI2, EA1, EA2, l2, alpha1, alpha2, Ft, Fn, beta, q, p;
    int n1, n2;
  };
  const double inf = std::numeric_limits<double>::infinity();
  const row rows[] = {
      // design 362 of tests/seta/natural_state_paths.cpp, Ft = 0: tension only, T/EA1 from 0.47 to
      // 4.5 along the beam, theta within [0, 1.47] (z monotone; the check once gave up on it)
      {0.4862557085350056, 95.663642985073622, 12.962666584858646, inf, 0.0069261819223409527, 1.196205214292706,
       0.10533172401692666, 0.0, -58.9615654520907, 1.5698096461694737, -25.129321251984077, 0.14032219349991246,
       1, 0},
      // design 3652, Ft = -245.0: the beam compressed past EA1 (T/EA1 down to -2.1)
      {6.287875735944052, 37.756762661901234, 135.67837629266003, 43311.155846643385, 0.0019093487414188505,
       0.35256248530775103, 0.49187001283689347, -245.04002096991007, 156.22037911777855, 1.5705454138503523,
       -4.21824322283027, 0.13533947898580065, 1, 0},
      // design 2544, Ft = -67.7: T/EA1 from -10 to 12 along the beam
      {6.6890551964584164, 3043.5835995244006, 6.4573193355359324, 15198.501823696923, 0.26376481872055646,
       1.5102958552049621, 0.044112254729731862, -67.687670081180642, -39.156400266773993, 1.5650123287293796,
       -9.2710531179693678, 0.020227997357758598, 1, 0},
      // design 2399, Ft = 168.7: the beam's turning angle next to the saddle; crosses the substrate
      {0.45894274111851319, 6.4702666688366754, 610932.30933813995, 17558.035910304141, 0.49272257396615937,
       0.54031202076762463, 0.90280292361840964, 168.6535448032229, -13.06911925669127, 1.6876464541389811,
       17.616121475230035, -0.94502677006489544, 1, 1},
      // design 9691, Ft = 171.6: the same, EA1 infinite; stays above the substrate
      {0.73110455058294721, 0.26480678810721225, inf, 21637.900088647006, 0.98349444610512771, 0.40931157950422181,
       0.64978862562187845, 171.59026458895036, -10.436963516720736, 1.9157893527730165, 16.03944946986687,
       -10.306224238848227, 1, 1},
  };
  for (const auto& r : rows) {
    gecko::TwoLevelSeta<double> s;
    s.EI1 = r.EI1; s.EI2 = r.EI2; s.EA1 = r.EA1; s.EA2 = r.EA2;
    s.l1 = 1.0; s.l2 = r.l2; s.alpha1 = r.alpha1; s.alpha2 = r.alpha2; s.w = 1.0;
    gecko::critical_state<double> st;
    st.Ft = r.Ft; st.Fn = r.Fn; st.theta_joint = r.beta; st.theta_rate_base = r.q; st.theta_rate_joint = r.p;
    st.turning_points_beam = r.n1; st.turning_points_spatula = r.n2;
    st.status = gecko::critical_status::converged;
    const auto chk = gecko::admissibility_check(s, st);
    const auto ref = dense_reference_from_edge(s, st);
    INFO("Ft " << r.Ft << " min_z " << chk.min_z << " ref " << static_cast<double>(ref.min_z) << " strain "
               << chk.max_axial_strain);
    REQUIRE(chk.min_z == chk.min_z);  // the check is made
    CHECK(std::fabs(chk.min_z - static_cast<double>(ref.min_z)) < 1e-9);
    CHECK(std::fabs(chk.max_axial_strain - static_cast<double>(ref.max_strain)) < 1e-9);
    CHECK(chk.crosses_substrate == (ref.min_z < -1e-9));
    // The lowest stretch: a beam compressed past EA1 (3652, 2544) is turned inside out there, a
    // state no rod takes, inadmissible whatever its heights.
    CHECK(std::fabs(chk.min_stretch - static_cast<double>(ref.min_stretch)) < 1e-9);
    CHECK(chk.inverted == (ref.min_stretch <= 0));
    if (chk.inverted) CHECK_FALSE(chk.admissible);
  }
}

TEST_CASE("a beam on its separatrix within rounding: the verdict does not depend on the state's last bits",
          "[seta][admissibility][stress]") {
  // Long-double states of the 10,000-design re-run (validation/data/stress_10000_states.npz,
  // designs 9557, 4119 and 8290 at their negative Ft; solved by the long-double retry of
  // critical_line_at): beams with one turning point that dwell next to the saddle for 120 to 183
  // time constants. The first-integral constant formed from the joint's rate puts the beam at the
  // separatrix to rounding, so a change of the state in its last bits moves it to either side
  // (up < 1 or up >= 1). The check once left the turning angle out of theta's range on the side
  // up >= 1, took the beam as monotone and reported min_z = 0 at the edge, against -0.22 to
  // -0.69 (below the substrate) on the other side. Each state is perturbed here by up to 4e-15 of
  // beta and of theta2'(l1): every perturbation must give one verdict.
  if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) {
    WARN("long double is double here: the long-double states of this test do not exist");
    return;
  }
  using L = long double;
  struct row {
    double EI1, EI2, EA1, EA2, l2, alpha1, alpha2;
    L Ft, Fn, beta, q, p;
  };
  const double inf = std::numeric_limits<double>::infinity();
  const row rows[] = {
      {0.2412184085920297, 125.13013896020112, inf, 62086593.209604636, 0.02289759296680623, 1.0989619026158497,
       0.21433222610927091, -7338.56879554999977699L, 3337.45841202226803213L, 1.56165574569000583326L,
       -365.537382834247997543L, 0.701199444879295996169L},
      {0.31540948110247186, 234.22578815932894, 28763366.986380022, 5738961.2881276226, 0.019504871968821769,
       1.2585122531136197, 0.25482849989877449, -3139.96364330000005793L, 3336.52962668578624483L,
       1.56741304754790141275L, -233.452988081784647306L, 0.312068661839904366449L},
      {0.21035036654855974, 100.69794842318009, inf, 42181747.578574598, 0.040174043388671608, 0.43788427594259616,
       1.0781361600930444, -5079.89004526999997324L, 1237.32817078257321819L, 1.5562956809336288426L,
       -284.334319633422813678L, 0.599565448510389826728L},
  };
  for (const auto& r : rows) {
    gecko::TwoLevelSeta<L> s{r.EI1, r.EI2, r.EA1, r.EA2, 1.0L, r.l2, r.alpha1, r.alpha2, 1.0L};
    L lowest = std::numeric_limits<L>::infinity(), highest = -lowest;
    for (int k = -4; k <= 4; ++k) {
      for (int which = 0; which < 2; ++which) {
        gecko::seta_pose<L> pose{r.Fn, r.Ft, r.beta, r.q, r.p, 1, 0, std::numeric_limits<L>::quiet_NaN()};
        (which == 0 ? pose.theta_joint : pose.theta_rate_joint) *= 1 + k * 1e-15L;
        const auto chk = gecko::admissibility_check(s, pose);
        INFO("Ft " << static_cast<double>(r.Ft) << " perturbation " << k << "e-15 of "
                   << (which == 0 ? "beta" : "theta2'(l1)") << ": min_z " << static_cast<double>(chk.min_z));
        REQUIRE(chk.min_z == chk.min_z);
        CHECK(chk.crosses_substrate);
        lowest = std::min(lowest, chk.min_z);
        highest = std::max(highest, chk.min_z);
      }
    }
    INFO("Ft " << static_cast<double>(r.Ft) << ": min_z from " << static_cast<double>(lowest) << " to "
               << static_cast<double>(highest));
    CHECK(highest - lowest < 1e-9L);
  }
}

TEST_CASE("beams on their separatrix within rounding that cross the substrate: min_z against the arbitrary-precision shot",
          "[seta][admissibility][stress]") {
  // States of the 10,000-design re-run (validation/data/stress_10000_states.npz, designs 9769,
  // 6580 and 261 at their negative Ft; 44 to 56 saddle time constants of beam) that came back with
  // status 0 and min_z = 0 before the check took the saddle as the turning angle of a beam whose
  // first integral, formed from the rates, puts it past its separatrix in rounding. The reference is
  // the lowest height of the arbitrary-precision bracketing shot (python3 -m
  // validation.admissibility_mp validation/rerun_saddleangle.npz --states 9769:0 6580:0 261:0;
  // validation/results/admissibility_mp_saddle_angle.json), with the shot's turning points gecko's.
  struct row {
    double EI1, EI2, EA1, EA2, l2, alpha1, alpha2, Ft, min_z;
  };
  // Design 6580 at Ft = -726.36 was a third: its beam's stretch passes zero on the way there, so the
  // line now ends before it (status 3, "a followed line whose beam is compressed to zero length").
  const row rows[] = {
      {0.4427787486194838, 160.2623296450165, 1566678.1705902521, 13044.352108849595, 0.02248864069289234,
       1.49617569899873, 0.018790215510938044, -128.5524701284602, -0.8577339290675122},
      {1.7583361218925642, 234.20786545000487, 3661438.1821068637, 24649236.215905342, 0.0484030099512882,
       0.15480997477229064, 0.1823488908348738, -4114.740444567308, -0.5749009793701064},
  };
  for (const auto& r : rows) {
    const gecko::TwoLevelSeta<double> s{r.EI1, r.EI2, r.EA1, r.EA2, 1.0, r.l2, r.alpha1, r.alpha2, 1.0};
    const auto st = gecko::critical_line_at(s, std::vector<double>{r.Ft})[0];
    INFO("Ft " << r.Ft << " status " << static_cast<int>(st.status) << " min_z " << st.min_z << " reference "
               << r.min_z);
    REQUIRE(st.status == gecko::critical_status::inadmissible);
    CHECK(st.turning_points_beam == 1);
    CHECK(std::fabs(st.min_z - r.min_z) < 1e-9 * (1.0 + r.l2));
  }
}

TEST_CASE("a followed line whose beam is compressed to zero length leaves the model there",
          "[seta][admissibility][stress]") {
  // Design 6580 of the 10,000-design re-run (validation/data/stress_10000_states.npz): followed
  // towards its negative Ft, the beam's compression grows until T reaches -EA1 near Ft = -530.8,
  // where the linear law's stretch 1 + T/EA1 passes zero. The line ends at its first node past
  // that (line_end::unsupported_state), that node is kept and judged inadmissible, and the
  // campaign's Ft = -726.36 beyond it is status 3 (it was status 7, a state whose beam had a
  // negative length). The stretch of the two last nodes is checked against the dense ODE
  // evaluation shot from the contact edge.
  const gecko::TwoLevelSeta<double> s{9.234011903410433, 8632.183289992317, 1898.1613549209487, 335194.8826055024,
                                      1.0, 0.08155494130194677, 1.474315464438074, 0.028604678886875907, 1.0};
  gecko::critical_line_options<double> o;
  o.ft_end = -726.3553702242612;
  const auto line = gecko::critical_line(s, o);
  REQUIRE(line.points.size() >= 2);
  CHECK(line.end == gecko::line_end::unsupported_state);
  const auto& last = line.points.back();
  const auto& before = line.points[line.points.size() - 2];
  INFO("last node Ft " << last.Ft << " min_stretch " << last.min_stretch << ", before it " << before.min_stretch);
  CHECK(last.min_stretch <= 0);
  CHECK(before.min_stretch > 0);
  CHECK(last.status == gecko::critical_status::inadmissible);
  CHECK(last.Ft < -500.0);
  CHECK(last.Ft > -560.0);
  for (const auto* p : {&before, &last}) {
    gecko::critical_state<double> st;
    st.Ft = p->Ft; st.Fn = p->Fn; st.theta_joint = p->theta_joint;
    st.theta_rate_base = p->theta_rate_base; st.theta_rate_joint = p->theta_rate_joint;
    st.turning_points_beam = p->turning_points_beam; st.turning_points_spatula = p->turning_points_spatula;
    st.status = gecko::critical_status::converged;
    const auto ref = dense_reference_from_edge(s, st);
    CHECK(std::fabs(p->min_stretch - static_cast<double>(ref.min_stretch)) < 1e-9);
    const auto chk = gecko::admissibility_check(s, st);
    CHECK(chk.inverted == (p == &last));
  }
  const auto at = gecko::critical_line_at(s, std::vector<double>{-726.3553702242612, -300.0});
  CHECK(at[0].status == gecko::critical_status::unsupported_state);
  CHECK(at[1].status == gecko::critical_status::converged);
  CHECK(at[1].min_stretch > 0);
  CHECK(at[1].min_stretch < 1);  // the beam is compressed there
}

TEST_CASE("a line that ran along the edge of the forms with its beam past zero length: status 3, not given up",
          "[seta][admissibility][stress]") {
  // Design 1351 of the 10,000-design re-run: its line towards Ft = -4325.98 passed a beam stretch of
  // zero and then crept along the edge of the forms (f4's root at u = -1, the beam compressed to a
  // stretch of -3.8 at its joint) until its step collapsed: the target was status 6, given up
  // (validation/README.md, "Lines that run along the edge of the forms"). The line now ends where
  // the stretch first reaches zero, and the target beyond is outside the model.
  const gecko::TwoLevelSeta<double> s{0.12447762359910051, 0.0005877794453459785, 3.574302925688437, 39737401.3417575,
                                      1.0, 0.002637651785474554, 0.9963094041055244, 0.11285065550888966, 1.0};
  const auto at = gecko::critical_line_at(s, std::vector<double>{-4325.9810090173605, 0.0});
  CHECK(at[0].status == gecko::critical_status::unsupported_state);
  gecko::critical_line_options<double> o;
  o.ft_end = -4325.9810090173605;
  const auto line = gecko::critical_line(s, o);
  CHECK(line.end == gecko::line_end::unsupported_state);
  REQUIRE(line.points.size() >= 2);
  CHECK(line.points.back().min_stretch <= 0);
  CHECK(line.points[line.points.size() - 2].min_stretch > 0);
}
