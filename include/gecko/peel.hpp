// gecko/peel.hpp — classical peel lines and the small-deformation theory of the seta.
//
//   kendall_fn(Ft, EA, w), rivlin_fn(Ft, w)          paper eq 17 (docs/theory/two_level_seta.md)
//   small_deformation(seta), small_deformation_fn    paper eqs 7, 18-22
#pragma once

#include "gecko/peel/kendall.hpp"
#include "gecko/peel/rivlin.hpp"
#include "gecko/peel/small_deformation.hpp"
