// gecko/elliptic.hpp — the elliptic-integral concern: Carlson symmetric forms and Legendre forms.
//
//   carlson_rf, carlson_rd, carlson_rj, carlson_rc     Carlson's R_F, R_D, R_J, R_C (DLMF 19.16)
//   ellint_f, ellint_e                                 incomplete F(phi|m), E(phi|m), parameter m
//   ellint_k, ellint_ek                                complete K(m), and E(m) with K(m) together
//   carlson_rf_gradient                                R_F with its three partial derivatives
//
// Every public function takes an optional policy (gecko/core/policy.hpp): domain errors throw
// std::domain_error (default) or return NaN (nan_policy); precision<Bits> trades accuracy for
// speed. NaN input always propagates quietly as NaN. Unchecked kernels for hot loops live in
// gecko::detail (carlson_rf_imp, carlson_rd_imp, carlson_rf_rd_imp, ...).
#pragma once

#include "gecko/elliptic/carlson_rc.hpp"
#include "gecko/elliptic/carlson_rd.hpp"
#include "gecko/elliptic/carlson_rf.hpp"
#include "gecko/elliptic/carlson_rf_gradient.hpp"
#include "gecko/elliptic/carlson_rf_rd.hpp"
#include "gecko/elliptic/carlson_rj.hpp"
#include "gecko/elliptic/ellint_e.hpp"
#include "gecko/elliptic/ellint_ek.hpp"
#include "gecko/elliptic/ellint_f.hpp"
#include "gecko/elliptic/ellint_k.hpp"
