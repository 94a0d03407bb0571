// gecko/seta/characteristics_batch.hpp — the characteristic quantities of many designs, each
// solved only as deep as the caller needs (the design sweep, python/gecko/design_sweep.py).
//
// docs/theory/two_level_seta.md, "Critical line of adhesion" (the characteristic quantities) and
// "Small-deformation approximations" (paper eqs 7, 18-22). Each depth adds to the one before:
//   closed_forms    (Ft)max = sqrt(2 EA2 w) and the small-deformation (Fn)0, k, contact length
//                   and non-sticky criterion: no solver at all;
//   natural_state   + the natural state at Ft = 0 and the exact slope there: (Fn)0, k, sticky at
//                   rest (gecko::characteristics with ft_end = 0: no line is traced);
//   whole_line      + the line followed from Ft = 0 to its end: max pull-off and its Ft, Fn and Ft
//                   at the line's end, why it ended, its folds.
// Every value is gecko::characteristics' own for the design (gecko/seta/characteristics.hpp),
// bitwise; (Fn)0 and k come from the same natural state at natural_state and whole_line depth,
// so they agree bitwise between the two. A quantity the depth does not compute is NaN (false,
// no folds), never a value from a cheaper route. Like characteristics', the minimum's values
// (min_fn, its Ft, max pull-off) are NaN where it could not be certified (minimum_status).
//
// A sweep of a million random designs must not stop at the first bad one, so nothing here
// throws for a bad design (nan_policy throughout); its status says what happened instead:
//   invalid_input      the design is outside its admissible range (gecko/seta/two_level_seta.hpp):
//                      every value NaN;
//   not_converged      the natural state at Ft = 0 was not found;
//   unsupported_state  the natural state left the model's forms (axial load comparable to EA).
// In the last two the closed forms are still reported; (Fn)0 and every value of the line are NaN.
//
// Designs are dealt round-robin to threads (gecko/core/parallel.hpp) with no shared mutable
// state: the result is bitwise identical for any thread count.
#pragma once

#include <cstddef>
#include <limits>

#include "gecko/core/parallel.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/small_deformation.hpp"
#include "gecko/seta/characteristics.hpp"
#include "gecko/seta/solve_critical.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

// How much of a design characteristics_batch solves (the values are the Python binding's
// `depth` argument).
enum class characteristics_depth : int {
  closed_forms = 0,   // (Ft)max and the small-deformation theory only
  natural_state = 1,  // + (Fn)0, k and stickiness from the natural state at Ft = 0
  whole_line = 2      // + the line followed to its end: max pull-off, the line's end, folds
};

// One design's characteristic quantities, to the depth asked for (see the header comment for
// which depth fills which field; the others keep these defaults).
template <class T>
struct design_characteristics {
  critical_status status = critical_status::invalid_input;
  // natural_state and whole_line
  T fn0 = std::numeric_limits<T>::quiet_NaN();
  T slope_k = std::numeric_limits<T>::quiet_NaN();  // = slope_at_zero (deprecated name)
  T slope_at_zero = std::numeric_limits<T>::quiet_NaN();
  bool sticky_at_rest = false;
  // whole_line: the paper's k (seta_characteristics::paper_k) and the bound of a max pull-off at
  // the end of the followed range (max_pull_off NaN then, see seta_characteristics)
  T paper_k = std::numeric_limits<T>::quiet_NaN();
  bool max_pull_off_is_bound = false;
  T max_pull_off_bound = std::numeric_limits<T>::quiet_NaN();
  // whole_line, when the natural state was found
  T min_fn = std::numeric_limits<T>::quiet_NaN();
  T ft_at_min_fn = std::numeric_limits<T>::quiet_NaN();
  bool min_fn_interior = false;
  T max_pull_off = std::numeric_limits<T>::quiet_NaN();
  T ft_at_line_end = std::numeric_limits<T>::quiet_NaN();
  T fn_at_line_end = std::numeric_limits<T>::quiet_NaN();
  int folds = 0;
  // whole_line: where the admissible part of the line ends (gecko/seta/characteristics.hpp)
  bool admissible_to_end = false;
  T admissible_end_ft = std::numeric_limits<T>::quiet_NaN();
  T admissible_end_fn = std::numeric_limits<T>::quiet_NaN();
  // whole_line, whatever the status (no_natural_state when no line was followed)
  line_end end = line_end::no_natural_state;
  // every depth, for an admissible design
  T ft_max = std::numeric_limits<T>::quiet_NaN();
  small_deformation_line<T> small = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN(),
                                     std::numeric_limits<T>::quiet_NaN(), false};
};

namespace detail {

template <class T>
inline design_characteristics<T> characteristics_to_depth_imp(const TwoLevelSeta<T>& s,
                                                              characteristics_depth depth) {
  using policies::nan_policy;
  design_characteristics<T> r;
  if (!check_seta<T, nan_policy>(s, "gecko::characteristics_batch")) return r;
  r.status = critical_status::converged;
  if (depth == characteristics_depth::closed_forms) {
    r.ft_max = ft_max(s);
    r.small = small_deformation(s, nan_policy());
    return r;
  }
  critical_line_options<T> options;
  // ft_end = 0 stops the trace at the natural state; NaN is the default end ((Ft)max).
  options.ft_end = depth == characteristics_depth::natural_state ? T(0) : std::numeric_limits<T>::quiet_NaN();
  const seta_characteristics<T> c = characteristics(s, options, nan_policy());
  // A line that leaves the model's forms after its natural state was found is not a failed
  // design: its end says so, and its minimum is that of the followed part (line_incomplete).
  if (c.end == line_end::no_natural_state)
    r.status = critical_status::not_converged;
  else if (c.end == line_end::unsupported_state && !(c.fn0 == c.fn0))
    r.status = critical_status::unsupported_state;
  r.ft_max = c.ft_max;
  r.small = c.small;
  r.fn0 = c.fn0;
  r.slope_k = c.slope_k;
  r.slope_at_zero = c.slope_at_zero;
  const bool found = r.status == critical_status::converged;
  r.sticky_at_rest = found && c.sticky_at_rest;
  if (depth != characteristics_depth::whole_line) return r;
  r.end = c.end;
  if (!found) return r;
  r.min_fn = c.min_fn;
  r.ft_at_min_fn = c.ft_at_min_fn;
  r.min_fn_interior = c.min_fn_interior;
  r.max_pull_off = c.max_pull_off;
  r.ft_at_line_end = c.ft_at_line_end;
  r.fn_at_line_end = c.fn_at_line_end;
  r.folds = static_cast<int>(c.folds.size());
  r.admissible_to_end = c.admissible_to_end;
  r.admissible_end_ft = c.admissible_end_ft;
  r.admissible_end_fn = c.admissible_end_fn;
  r.paper_k = c.paper_k;
  r.max_pull_off_is_bound = c.max_pull_off_is_bound;
  r.max_pull_off_bound = c.max_pull_off_bound;
  return r;
}

}  // namespace detail

// One design, to the given depth.
template <class T>
inline design_characteristics<T> characteristics_to_depth(const TwoLevelSeta<T>& seta, characteristics_depth depth) {
  return detail::characteristics_to_depth_imp(seta, depth);
}

// designs[0..count) to the given depth, into out[0..count), on `threads` threads.
template <class T>
inline void characteristics_batch(const TwoLevelSeta<T>* designs, std::size_t count, characteristics_depth depth,
                                  design_characteristics<T>* out, unsigned threads = 1) {
  detail::parallel_for_strided(count, threads, [&](std::size_t i) {
    out[i] = detail::characteristics_to_depth_imp(designs[i], depth);
  });
}

}  // namespace gecko
