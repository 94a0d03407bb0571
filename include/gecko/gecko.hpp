// gecko/gecko.hpp — umbrella header: everything in the gecko library.
#pragma once

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic.hpp"
