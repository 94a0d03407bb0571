// gecko/beam.hpp — curved-beam compliance and rigidity by Castigliano (docs/theory/frictional_adhesion.md).
#pragma once

#include "gecko/beam/castigliano.hpp"
#include "gecko/beam/parabolic.hpp"
#include "gecko/beam/rigidity.hpp"
#include "gecko/beam/shape.hpp"
#include "gecko/beam/tanh_sinh.hpp"
