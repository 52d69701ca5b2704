// An outside driver: includes the umbrella header, uses the library, exits 0 when it works.
#include <spar/spar.hpp>

#include <cstdio>

int main() {
  const Eigen::Vector3d theta(0.3, -0.2, 0.1);
  const Eigen::Vector3d back = spar::lie::log(spar::lie::exp(theta));
  const double error = (back - theta).norm();
  std::printf("outside driver: |log(exp(theta)) - theta| = %.3e\n", error);
  return error < 1e-14 ? 0 : 1;
}
