// Tests of gecko/seta/critical_residual.hpp: the exact (dual-number) Jacobian of the critical-state
// residual, dF/d(Fn, beta, p, q) and dF/dmu, agrees with finite differences in EVERY Carlson form
// and plan (gecko/seta/elastica_segment.hpp): direct; libration ends in the turning-point forms
// (theta max and min) and the bottom forms (up and down), with and without an added period;
// rotation ends at the bottom and at the top; for the beam and the spatula, EA finite and
// infinite. tests/seta/critical_equations.cpp checks a few solved states; these are random
// states off the line, so that every form is met (the continuation's predictors land anywhere).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

#include "gecko/seta/detail/seta_system.hpp"
#include "seta/random_designs.hpp"

namespace {

using Policy = gecko::policies::default_policy;
using gecko::detail::segment_plan;
using gecko::detail::segment_rep;

constexpr int n_reps = 6;  // segment_rep values

struct coverage {
  int rep_s[2][n_reps] = {};   // [beam, spatula][rep]: plans checked with this start form
  int rep_e[2][n_reps] = {};
  int direct[2] = {}, period[2] = {};
  int checked = 0, skipped = 0;
  double worst = 0;
};

void count(const segment_plan& p, int seg, coverage& c) {
  if (p.direct) {
    ++c.direct[seg];
    return;
  }
  ++c.rep_s[seg][static_cast<int>(p.rep_s)];
  ++c.rep_e[seg][static_cast<int>(p.rep_e)];
  if (p.periods != 0) ++c.period[seg];
}

// Random states (z, mu) of random designs, each under its own plan. The finite differences are
// central, Richardson-extrapolated from h and h/2 (error O(h^4)); where h and h/2 disagree by more
// than 1e-4 (a form boundary or a near-singular R_F within h) the state is skipped, as finite
// differences say nothing there.
template <bool E1, bool E2>
coverage check_random_states(std::uint64_t seed, int draws) {
  using System = gecko::detail::seta_system<double, Policy, E1, E2>;
  using vec = typename System::vec;
  using mat = typename System::mat;
  coverage c;
  std::uint64_t st = seed;
  for (int k = 0; k < draws; ++k) {
    auto s = seta_test::sweep_box_design(st);
    s.EA1 = E1 ? 20 + 200 * seta_test::uniform01(st) : std::numeric_limits<double>::infinity();
    if (!E2) s.EA2 = std::numeric_limits<double>::infinity();
    const System sys(gecko::detail::make_seta_params(s));
    vec z;
    z[0] = -3 + 6 * seta_test::uniform01(st);
    z[1] = -1 + 3 * seta_test::uniform01(st);
    z[2] = -2 + 4 * seta_test::uniform01(st);
    z[3] = -2 + 4 * seta_test::uniform01(st);
    const double mu = (-1 + 2 * seta_test::uniform01(st)) * (E2 ? 1.4 * sys.ftmax : 2.0);
    const auto plan = sys.plan(z, mu);
    if (System::plan_state(plan) != gecko::detail::segment_state::ok) continue;
    vec F, dmu;
    mat J;
    double u14[2];
    if (!sys.eval(z, mu, plan, F, J, &dmu, u14)) continue;
    // Column j of [J dF/dmu], by finite differences in x = (z, mu).
    auto fd_column = [&](int j, vec& col) {
      const double x0 = j < 4 ? z[j] : mu;
      const double h = 1e-6 * std::max(1.0, std::fabs(x0));
      vec D[2];
      for (int r = 0; r < 2; ++r) {
        const double hh = h / (1 + r);
        vec zp = z, zm = z, Fp, Fm;
        double mp = mu, mm = mu;
        if (j < 4) {
          zp[j] += hh;
          zm[j] -= hh;
        } else {
          mp += hh;
          mm -= hh;
        }
        if (!sys.residual(zp, mp, plan, Fp) || !sys.residual(zm, mm, plan, Fm)) return false;
        D[r] = (Fp - Fm) / (2 * hh);
      }
      for (int i = 0; i < 4; ++i)
        if (std::fabs(D[0][i] - D[1][i]) > 1e-4 * (1 + std::fabs(D[1][i]))) return false;
      col = (4 * D[1] - D[0]) / 3;
      return true;
    };
    mat Jfd;
    vec dmu_fd;
    bool ok = true;
    for (int j = 0; j < 4 && ok; ++j) {
      vec col;
      ok = fd_column(j, col);
      if (ok) Jfd.col(j) = col;
    }
    if (ok) ok = fd_column(4, dmu_fd);
    if (!ok) {
      ++c.skipped;
      continue;
    }
    for (int i = 0; i < 4; ++i) {
      // Errors relative to the row's largest entry: the Newton step sees the row as a whole.
      const double row = 1 + std::max(J.row(i).cwiseAbs().maxCoeff(), std::fabs(dmu[i]));
      for (int j = 0; j < 5; ++j) {
        const double an = j < 4 ? J(i, j) : dmu[i];
        const double fd = j < 4 ? Jfd(i, j) : dmu_fd[i];
        const double e = std::fabs(an - fd) / row;
        if (e > c.worst) c.worst = e;
        INFO("E1 " << E1 << " E2 " << E2 << " draw " << k << " dF" << i + 1 << "/dx" << j << " analytic " << an
                   << " fd " << fd);
        if (e > 1e-6) CHECK(e <= 1e-6);
      }
    }
    count(plan.beam, 0, c);
    count(plan.spatula, 1, c);
    ++c.checked;
  }
  return c;
}

void require_every_form(const coverage& c, bool spatula_rotates) {
  INFO("checked " << c.checked << " skipped " << c.skipped << " worst " << c.worst);
  CHECK(c.skipped < c.checked / 10);
  for (int seg = 0; seg < 2; ++seg) {
    INFO("segment " << (seg == 0 ? "beam" : "spatula"));
    CHECK(c.direct[seg] >= 10);
    CHECK(c.period[seg] >= 10);
    for (int r = 0; r < n_reps; ++r) {
      const bool rotation = r >= static_cast<int>(segment_rep::rot_bottom);
      if (rotation && seg == 1 && !spatula_rotates) continue;
      INFO("form " << r);
      CHECK(c.rep_s[seg][r] + c.rep_e[seg][r] >= 10);
    }
  }
}

}  // namespace

TEST_CASE("critical residual: Jacobian matches finite differences in every form and plan",
          "[seta][residual][jacobian]") {
  const int draws = 8000;
  require_every_form(check_random_states<false, false>(11, draws), true);
  require_every_form(check_random_states<false, true>(12, draws), true);
  require_every_form(check_random_states<true, false>(13, draws), true);
  require_every_form(check_random_states<true, true>(14, draws), true);
}
