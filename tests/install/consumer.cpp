// A downstream simulation code: include the umbrella header, call a kernel, check the answer.
#include <gecko/gecko.hpp>

#include <cmath>
#include <cstdio>

int main() {
  // K(1/2) = 1.8540746773013719... (complete integral of the first kind, parameter m = 1/2)
  const double k = gecko::ellint_k(0.5);
  std::printf("gecko::ellint_k(0.5) = %.17g\n", k);
  return std::abs(k - 1.8540746773013719) < 1e-15 ? 0 : 1;
}
