#include <spar/elements/cable/rancf_merging.hpp>

#include <spar/error.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <Eigen/QR>

#include <algorithm>
#include <string>

namespace spar::core {

template <int Dim>
RancfMergeWeights merge_rancf_weights(const Eigen::Matrix<double, 4 * Dim, 1>& e_ab,
                                      const Eigen::Matrix<double, Dim, 1>& r_h, double x_a,
                                      double x_h, double x_b, double max_weight) {
  if (!(max_weight >= 1.0))
    throw Error("weight bound " + std::to_string(max_weight) + " is below 1", "core::merge_rancf_weights",
                "give a bound ≥ 1 (infinity: 000's unbounded least squares)");
  if (!(x_a < x_h && x_h < x_b))
    throw Error("material coordinates x_A = " + std::to_string(x_a) + ", x_H = " + std::to_string(x_h) +
                    ", x_B = " + std::to_string(x_b) + " are not increasing",
                "core::merge_rancf_weights", "merge two adjacent elements AH and HB");
  using Vec = Eigen::Matrix<double, Dim, 1>;
  const double l = x_b - x_a, u = (x_h - x_a) / l, v = 1.0 - u;  // 000 eqs. (30), (31)
  const Vec r_a = e_ab.template segment<Dim>(0), rx_a = e_ab.template segment<Dim>(Dim);
  const Vec r_b = e_ab.template segment<Dim>(2 * Dim), rx_b = e_ab.template segment<Dim>(3 * Dim);
  // Eq. (R26): A k = c.
  Eigen::Matrix<double, Dim, 3> A;
  A.col(0) = v * v * v * (r_a - r_h) + l * u * v * v * rx_a;
  A.col(1) = 3 * u * v * v * (r_a - r_h);
  A.col(2) = 3 * u * u * v * (r_b - r_h);
  const Vec c = -u * u * u * (r_b - r_h) + l * u * u * v * rx_b;
  // Eqs. (35)–(37): minimum-norm least squares for x = k − 1.
  const Eigen::Vector3d x =
      Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, Dim, 3>>(A).solve(c - A * Eigen::Vector3d::Ones());
  RancfMergeWeights result;
  Eigen::Vector3d k = x + Eigen::Vector3d::Ones();
  result.fallback = !(k.minCoeff() > 0.0);  // eq. (38)
  // The bound: k = 1 + t x, the largest t ≤ 1 with 1/max_weight ≤ k_i ≤ max_weight.
  if (!result.fallback && (k.maxCoeff() > max_weight || k.minCoeff() < 1.0 / max_weight)) {
    double t = 1.0;
    for (int i = 0; i < 3; ++i)
      t = std::min(t, x(i) > 0.0 ? (max_weight - 1.0) / x(i) : (1.0 / max_weight - 1.0) / x(i));
    k = Eigen::Vector3d::Ones() + t * x;
    result.bounded = true;
  }
  result.weights << (result.fallback ? Eigen::Vector3d::Ones() : k), 1.0;
  const Eigen::Vector4d s = iga::rancf_shape_functions(u, result.weights, l);
  const Vec r_merged = s(0) * r_a + s(1) * rx_a + s(2) * r_b + s(3) * rx_b;
  result.miss = (r_merged - r_h).norm();
  return result;
}

template RancfMergeWeights merge_rancf_weights<2>(const Eigen::Matrix<double, 8, 1>&,
                                                  const Eigen::Matrix<double, 2, 1>&, double, double,
                                                  double, double);
template RancfMergeWeights merge_rancf_weights<3>(const Eigen::Matrix<double, 12, 1>&,
                                                  const Eigen::Matrix<double, 3, 1>&, double, double,
                                                  double, double);

}  // namespace spar::core
