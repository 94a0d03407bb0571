// gecko/gecko.hpp — umbrella header: everything in the gecko library.
#pragma once

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic.hpp"
#include "gecko/beam.hpp"
#include "gecko/friction.hpp"
#include "gecko/seta.hpp"
#include "gecko/peel.hpp"
