#include <spar/elements/cable/rancf_segmentation.hpp>

#include <spar/error.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <cmath>
#include <string>

namespace spar::core {

template <int Dim>
RancfSplit<Dim> split_rancf_element(const Eigen::Matrix<double, 4 * Dim, 1>& e, double x_a,
                                    double x_b, const Eigen::Vector4d& weights, double u_h,
                                    const Eigen::Matrix<double, 4 * Dim + 2, 1>& rates) {
  constexpr const char* where = "core::split_rancf_element";
  using Vec = Eigen::Matrix<double, Dim, 1>;
  const double l = x_b - x_a;
  if (!(l > 0.0) || !std::isfinite(l))
    throw Error("x_B − x_A = " + std::to_string(l) + " is not a positive length", where,
                "split an element with x_A < x_B");
  // 000 eqs. (6), (21), (5)/(27): Bézier form, de Casteljau split in homogeneous coordinates,
  // back to nodal coordinates of the halves with lengths u_H l and (1 − u_H) l (eq. (28)).
  const iga::RationalBezier<Dim> curve = iga::bezier_from_rancf<Dim>({e, weights, l});
  const iga::BezierSplit<Dim> halves = iga::split(curve, u_h);  // validates u_H and the weights
  const iga::RancfElement<Dim> left = iga::rancf_from_bezier(halves.left, u_h * l);
  RancfSplit<Dim> s;
  s.left_weights = halves.left.weights;
  s.right_weights = halves.right.weights;
  s.node << left.e.template segment<2 * Dim>(2 * Dim), x_a + u_h * l;

  // J = ∂Φ/∂q (docs/rancf.md eq. R22): r_H = R(u_H; e, l), r_x^H = t = R_u/l,
  // x_H = (1 − u_H) x_A + u_H x_B, with σ_k of eq. R3 and ∂/∂x_A = −∂/∂l, ∂/∂x_B = ∂/∂l.
  const Eigen::Matrix<double, 4, 4> sh = iga::rancf_shape_function_derivatives(u_h, weights);
  const auto block = [&](int k) { return e.template segment<Dim>(k * Dim); };
  const auto rate = [&](int k) { return rates.template segment<Dim>(k * Dim); };
  const Vec R_l = sh(1, 0) * block(1) + sh(3, 0) * block(3);
  const Vec endpoint_part = (sh(0, 1) * block(0) + sh(2, 1) * block(2)) / l;  // (s1' r_A + s3' r_B)/l
  const Vec t_l = -endpoint_part / l;                                        // ∂t/∂l
  const Eigen::Matrix<double, Dim, Dim> I = Eigen::Matrix<double, Dim, Dim>::Identity();
  s.jacobian.setZero();
  for (int k = 0; k < 4; ++k) {
    const bool slope = k % 2 == 1;
    s.jacobian.template block<Dim, Dim>(0, k * Dim) = (slope ? l * sh(k, 0) : sh(k, 0)) * I;
    s.jacobian.template block<Dim, Dim>(Dim, k * Dim) = (slope ? sh(k, 1) : sh(k, 1) / l) * I;
  }
  s.jacobian.template block<Dim, 1>(0, 4 * Dim) = -R_l;
  s.jacobian.template block<Dim, 1>(0, 4 * Dim + 1) = R_l;
  s.jacobian.template block<Dim, 1>(Dim, 4 * Dim) = -t_l;
  s.jacobian.template block<Dim, 1>(Dim, 4 * Dim + 1) = t_l;
  s.jacobian(2 * Dim, 4 * Dim) = 1.0 - u_h;
  s.jacobian(2 * Dim, 4 * Dim + 1) = u_h;

  // Eq. R30: at the fixed material point x_H, u̇ = −ẋ_g/l with ẋ_g = J_x q̇, so
  // ṙ = J_r q̇ − r_x ẋ_g and ṙ_x = J_t q̇ − (R_uu/l²) ẋ_g.
  Vec R_uu = Vec::Zero();
  for (int k = 0; k < 4; ++k) R_uu += (k % 2 == 1 ? l * sh(k, 2) : sh(k, 2)) * block(k);
  const Vec r_x = s.node.template segment<Dim>(Dim);
  s.material_jacobian = s.jacobian;
  s.material_jacobian.template topRows<Dim>() -= r_x * s.jacobian.row(2 * Dim);
  s.material_jacobian.template middleRows<Dim>(Dim) -= (R_uu / (l * l)) * s.jacobian.row(2 * Dim);
  s.material_jacobian.row(2 * Dim).setZero();

  // J̇ q̇: r_H is bilinear in (e, l), so d²r_H/dt² − J q̈ = 2 R_l(ė) l̇; r_x^H = (s1' r_A + s3' r_B)/l
  // + (ŝ2' r_x^A + ŝ4' r_x^B) gives 2 ∂²t/∂e∂l[ė] l̇ + ∂²t/∂l² l̇² with
  // ∂²t/∂e∂l[ė] = −(s1' ṙ_A + s3' ṙ_B)/l², ∂²t/∂l² = 2 (s1' r_A + s3' r_B)/l³; x_H is linear.
  const double l_dot = rates(4 * Dim + 1) - rates(4 * Dim);
  s.convective_acceleration.setZero();
  s.convective_acceleration.template head<Dim>() =
      2.0 * l_dot * (sh(1, 0) * rate(1) + sh(3, 0) * rate(3));
  s.convective_acceleration.template segment<Dim>(Dim) =
      -2.0 * l_dot * (sh(0, 1) * rate(0) + sh(2, 1) * rate(2)) / (l * l) +
      2.0 * l_dot * l_dot * endpoint_part / (l * l);
  return s;
}

template RancfSplit<2> split_rancf_element<2>(const Eigen::Matrix<double, 8, 1>&, double, double,
                                              const Eigen::Vector4d&, double,
                                              const Eigen::Matrix<double, 10, 1>&);
template RancfSplit<3> split_rancf_element<3>(const Eigen::Matrix<double, 12, 1>&, double, double,
                                              const Eigen::Vector4d&, double,
                                              const Eigen::Matrix<double, 14, 1>&);

}  // namespace spar::core
