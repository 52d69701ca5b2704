#pragma once
/// \file
/// Segmentation of an ALE-RANCF (or fixed-length RANCF) element at u_H (paper 000 §4.1;
/// docs/rancf.md eqs. R20–R24): the element's rational cubic Bézier is split by the de Casteljau
/// algorithm in homogeneous coordinates (000 eq. (21), iga::split) and each half converted back to
/// RANCF nodal coordinates (000 eqs. (5), (27)) with the lengths of eq. (28). The new node H has
/// [r_H, r_x^H] and x_H = x_A + u_H (x_B − x_A); nodes A and B keep their coordinates (eq. (27)).
///
/// As an operator on the state: the new coordinates are a function Φ of the old (e, x_A, x_B) at
/// fixed u_H, and because both halves reproduce the old curve with its material parameterization
/// for every state (000 eqs. (23), (25)), the position field r(x, t) and — with rates mapped by
/// the Jacobian J = ∂Φ/∂q — the velocity field are unchanged; accelerations map as
/// J q̈ + J̇ q̇ (the convective part is non-zero when the length changes, l̇ ≠ 0).

#include <Eigen/Core>

namespace spar::core {

template <int Dim>
struct RancfSplit {
  static constexpr int old_size = 4 * Dim + 2;  ///< [e, x_A, x_B]
  static constexpr int node_size = 2 * Dim + 1;  ///< [r_H, r_x^H, x_H]
  Eigen::Vector4d left_weights;   ///< element AH (000 eq. (21): w̄0 … w̄3)
  Eigen::Vector4d right_weights;  ///< element HB (w̄3 … w̄6)
  /// [r_H, r_x^H, x_H].
  Eigen::Matrix<double, node_size, 1> node;
  /// ∂[r_H, r_x^H, x_H]/∂[e, x_A, x_B] at fixed u_H: new rates = J · old rates.
  Eigen::Matrix<double, node_size, old_size> jacobian;
  /// J̇ q̇ for the old rates q̇ given to split_rancf_element: the new node's accelerations are
  /// J q̈ + this.
  Eigen::Matrix<double, node_size, 1> convective_acceleration;
  /// The rates of [r_H, r_x^H, x_H] when H is held at its material point after the split (x_H a
  /// fixed coordinate, as when one half becomes a fixed-length element, 000 §5): the material
  /// velocity and slope rate at x_H, ẋ_H = 0 (docs/rancf.md eq. R30). Exact at H; between the
  /// nodes the new elements interpolate the old material velocity field, which they cannot
  /// represent exactly while ẋ_A or ẋ_B ≠ 0 (it has the denominator W², theirs W).
  Eigen::Matrix<double, node_size, old_size> material_jacobian;
};

/// Splits the element with nodal coordinates e = [r_A, r_x^A, r_B, r_x^B], material coordinates
/// x_A < x_B (for a fixed-length element: 0 and its length, with zero rates) and weights w at
/// 0 < u_H < 1; `rates` are the old [ė, ẋ_A, ẋ_B] (for the convective acceleration). Throws
/// spar::Error for u_H outside (0, 1), x_B ≤ x_A or invalid weights.
template <int Dim>
RancfSplit<Dim> split_rancf_element(const Eigen::Matrix<double, 4 * Dim, 1>& e, double x_a,
                                    double x_b, const Eigen::Vector4d& weights, double u_h,
                                    const Eigen::Matrix<double, 4 * Dim + 2, 1>& rates);

extern template RancfSplit<2> split_rancf_element<2>(const Eigen::Matrix<double, 8, 1>&, double,
                                                     double, const Eigen::Vector4d&, double,
                                                     const Eigen::Matrix<double, 10, 1>&);
extern template RancfSplit<3> split_rancf_element<3>(const Eigen::Matrix<double, 12, 1>&, double,
                                                     double, const Eigen::Vector4d&, double,
                                                     const Eigen::Matrix<double, 14, 1>&);

}  // namespace spar::core
