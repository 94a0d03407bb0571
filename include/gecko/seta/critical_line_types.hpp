// gecko/seta/critical_line_types.hpp — options and results of the critical line of adhesion
// (gecko/seta/critical_line.hpp): what a caller sets and what it reads back.
#pragma once

#include <limits>
#include <vector>

#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/solve_critical.hpp"

namespace gecko {

template <class T>
struct critical_line_options {
  // End of the followed range. NaN: (Ft)max for finite EA2, else 3 sqrt(EI1 w)/l1 (an arbitrary
  // but stated scale: the inextensible line has no (Ft)max). Negative: follow towards negative Ft.
  T ft_end = std::numeric_limits<T>::quiet_NaN();
  // Tolerance of the states at requested Ft values: a state is accepted when the scaled
  // correction (|dFn|/max(1,|Fn|), |dbeta|, rates relative) of its last chord step is below it
  // and a quarter of the step before (gecko/seta/detail/line_output.hpp); where the chord steps
  // do not settle it, of its last Newton step, or the Newton-Kantorovich bound omega/2 |dz|^2 of
  // the error after Newton's first step (omega estimated by the continuation;
  // gecko/seta/detail/newton.hpp).
  T tolerance = T(1e-12);
  T line_tolerance = T(1e-10);  // corrector tolerance of the traced nodes
  int max_points = 100000;
  // critical_line(): re-solve every traced node to `tolerance` before returning it (a node is a
  // predictor-corrector point accepted at line_tolerance, and near form boundaries, where the
  // Jacobian is ill-conditioned, that step test let errors of ~1e-8 through). Costs about one
  // Jacobian evaluation per node; false returns the raw nodes with status not_converged (all but
  // the natural state).
  bool resolve_nodes = true;
  // States whose largest axial strain |T|/EA exceeds this are inadmissible (status 7, see
  // gecko/seta/admissibility.hpp); the default is no limit (the paper's reference design reaches
  // 20 % strain at (Ft)max).
  T strain_limit = std::numeric_limits<T>::infinity();
};

template <class T>
struct critical_line_point {
  T Ft, Fn, theta_joint, theta_rate_joint, theta_rate_base;
  int turning_points_beam, turning_points_spatula;
  int branch;  // folds passed since Ft = 0
  // converged: re-solved to critical_line_options::tolerance (or the natural state, or the
  // landed end of the line). not_converged: the node could not be re-solved; its values are the
  // continuation's, accurate to about line_tolerance only, and kept so the line can be drawn.
  // inadmissible: a re-solved node where the seta crosses the substrate, a segment is compressed
  // to zero length (min_stretch <= 0) or the strain limit is exceeded; its values are kept so the
  // line can be drawn.
  critical_status status;
  // Admissibility of converged and inadmissible nodes (see critical_state); NaN otherwise.
  T min_z = std::numeric_limits<T>::quiet_NaN();
  T min_z_at = std::numeric_limits<T>::quiet_NaN();
  T max_axial_strain = std::numeric_limits<T>::quiet_NaN();
  T min_stretch = std::numeric_limits<T>::quiet_NaN();
};

template <class T>
struct critical_line_result {
  std::vector<critical_line_point<T>> points;  // the traced nodes, in order along the line
  std::vector<T> folds;                        // Ft at each fold (dFt/ds = 0)
  line_end end = line_end::reached_ft_end;
  critical_state<T> natural;                   // the natural state at Ft = 0
};

}  // namespace gecko
