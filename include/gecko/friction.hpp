// gecko/friction.hpp — frictional adhesion dynamics of paper 000 (docs/theory/frictional_adhesion.md): force traces,
// detachment laws, steady sliding, the spatula simulation (populations, a compliant seta) and the steady-sliding fit.
#pragma once

#include "gecko/friction/compliant_seta.hpp"
#include "gecko/friction/detachment.hpp"
#include "gecko/friction/fit.hpp"
#include "gecko/friction/force_trace.hpp"
#include "gecko/friction/path.hpp"
#include "gecko/friction/spatula_simulation.hpp"
#include "gecko/friction/steady_sliding.hpp"
