// gecko/seta.hpp — the two-level seta of directional adhesion (docs/theory/two_level_seta.md) and the single
// fiber of He et al. 2013.
//
//   TwoLevelSeta<T>, ft_max                      the design (defaults: the paper's reference scene)
//   elastica_segment(_length)                    one segment's length in Carlson form (EA = inf
//                                                special-cased at compile time; turning points)
//   solve_critical(seta, Ft[, guess, options])   one critical state (Newton, exact Jacobian)
//   critical_line(seta, options)                 the line from Ft = 0 through folds to (Ft)max
//                                                (every node re-solved, with a status)
//   critical_line_at(seta, Ft...)                the line at given Ft values
//   critical_line_batch(designs, Ft, threads)    many designs x many Ft, multithreaded
//   characteristics(seta)                        (Fn)0, k, max pull-off, (Ft)max, stickiness
//   small_deformation(seta), small_deformation_fn  the linear theory, paper eqs 7, 18-22
//   characteristics_batch(designs, n, depth, out, threads)  many designs, each solved only to `depth`
//   critical_equations(seta, Ft, ...)            residual and exact Jacobian at a state
//   sensitivities(seta, Ft)                      dFn/d(design) by implicit differentiation
//   shape(seta, state)                           deformed shape x(s), z(s) of a solved state
//   contact_state(seta, Fn, Ft)                  the forward problem: contact length at a load
//   contact_equilibria(seta, Fn, Ft)             ... every equilibrium there
//   SingleFiber<T>                               the single-level fiber (Fig 4)
#pragma once

#include "gecko/seta/batch.hpp"
#include "gecko/seta/characteristics.hpp"
#include "gecko/seta/characteristics_batch.hpp"
#include "gecko/seta/contact_state.hpp"
#include "gecko/seta/critical_line.hpp"
#include "gecko/seta/elastica_segment.hpp"
#include "gecko/seta/solve_critical.hpp"
#include "gecko/seta/two_level_seta.hpp"
#include "gecko/seta/critical_equations.hpp"
#include "gecko/seta/sensitivities.hpp"
#include "gecko/seta/shape.hpp"
#include "gecko/seta/single_fiber.hpp"
#include "gecko/seta/small_deformation.hpp"
