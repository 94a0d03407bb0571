// gecko/peel.hpp — classical peel lines.
//
//   kendall_fn(Ft, EA, w), rivlin_fn(Ft, w)          paper eq 17 (docs/theory/two_level_seta.md)
//
// The seta's small-deformation theory (small_deformation, small_deformation_fn; paper eqs 7,
// 18-22) moved to gecko/seta/small_deformation.hpp; this header still includes it so that code
// written against gecko 0.1 keeps compiling (deprecated: include gecko/seta.hpp for it).
#pragma once

#include "gecko/peel/kendall.hpp"
#include "gecko/peel/rivlin.hpp"
#include "gecko/seta/small_deformation.hpp"  // deprecated here, see above
