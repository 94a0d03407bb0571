// gecko/peel/small_deformation.hpp — DEPRECATED forwarding header, kept so that code written
// against gecko 0.1 still compiles. The small-deformation formulas are the two-level seta's
// (paper eqs 7 and 18-22) and now live in gecko/seta/small_deformation.hpp; include that (or
// gecko/seta.hpp) instead. This header will be removed in a later release.
#pragma once

#include "gecko/seta/small_deformation.hpp"
