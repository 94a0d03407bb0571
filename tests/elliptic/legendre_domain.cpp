// Tests for gecko/elliptic/legendre_domain.hpp: the m > 1 domain test at and around the edge.
#include <gecko/elliptic/legendre_domain.hpp>

#include <cmath>

#include <catch2/catch.hpp>

TEST_CASE("legendre_domain: m > 1 edge") {
  using gecko::detail::in_domain_m_above_one;
  for (double m : {1.0 + 1e-12, 1.5, 2.0, 100.0, 1e12}) {
    const double edge = std::asin(1 / std::sqrt(m));
    CHECK(in_domain_m_above_one(0.0, m));
    CHECK(in_domain_m_above_one(edge, m));
    CHECK(in_domain_m_above_one(-edge, m));
    CHECK(in_domain_m_above_one(std::nextafter(edge, 0.0), m));
    CHECK_FALSE(in_domain_m_above_one(edge * (1 + 1e-9), m));
    CHECK_FALSE(in_domain_m_above_one(3.0, m));
  }
  CHECK_FALSE(in_domain_m_above_one(2.0, 1.0 + 1e-15));  // |phi| > pi/2 never, for m > 1
}
