// Tests of gecko/seta/batch.hpp: the batch equals the serial calls bitwise, for 1 and 2 threads;
// bad designs are reported per design under nan_policy and raised under the default policy.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "gecko/seta/batch.hpp"

TEST_CASE("batch = serial bitwise; thread count does not matter", "[seta][batch]") {
  std::vector<gecko::TwoLevelSeta<double>> d(5);
  d[1].EI1 = 3.0; d[1].EA2 = 80.0;
  d[2].EI1 = 1.63413; d[2].EI2 = 1.15448; d[2].l2 = 0.382758; d[2].alpha1 = 0.694806; d[2].alpha2 = 0.288542;
  d[2].EA1 = 985.906; d[2].EA2 = 461.675;
  d[3].EA2 = std::numeric_limits<double>::infinity();
  d[4].alpha2 = 0.1; d[4].l2 = 0.3;
  const std::vector<double> Ft = {0.0, 0.7, 3.0, 6.0, -1.0, 9.5};
  std::vector<gecko::critical_state<double>> one(d.size() * Ft.size()), two(one.size());
  gecko::critical_line_batch(d.data(), d.size(), Ft.data(), Ft.size(), one.data(), 1);
  gecko::critical_line_batch(d.data(), d.size(), Ft.data(), Ft.size(), two.data(), 2);
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto serial = gecko::critical_line_at(d[i], Ft);
    for (std::size_t j = 0; j < Ft.size(); ++j) {
      const auto& a = one[i * Ft.size() + j];
      const auto& b = two[i * Ft.size() + j];
      CHECK(std::memcmp(&a.Fn, &serial[j].Fn, sizeof(double)) == 0);
      CHECK(std::memcmp(&a.theta_joint, &serial[j].theta_joint, sizeof(double)) == 0);
      CHECK(std::memcmp(&a.Fn, &b.Fn, sizeof(double)) == 0);
      CHECK(a.status == b.status);
      CHECK(a.status == serial[j].status);
    }
  }
  // A bad design: its row is invalid under nan_policy, the others untouched; raised otherwise.
  auto bad = d;
  bad[1].EI1 = -1;
  std::vector<gecko::critical_state<double>> out(one.size());
  gecko::critical_line_batch(bad.data(), bad.size(), Ft.data(), Ft.size(), out.data(), 2,
                             gecko::critical_line_options<double>(), gecko::policies::nan_policy());
  for (std::size_t j = 0; j < Ft.size(); ++j) {
    CHECK(out[Ft.size() + j].status == gecko::critical_status::invalid_input);
    CHECK(std::memcmp(&out[j].Fn, &one[j].Fn, sizeof(double)) == 0);
  }
  CHECK_THROWS_WITH(gecko::critical_line_batch(bad.data(), bad.size(), Ft.data(), Ft.size(), out.data(), 2),
                    Catch::Contains("EI1"));
}
