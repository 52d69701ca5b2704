#pragma once
/// \file
/// Merging of two ALE-RANCF elements AH and HB into one element AB (paper 000 §4.2; docs/rancf.md
/// eqs. R25–R29). Nodes A and B keep their coordinates (000 eq. (29)), l_AB = x_B − x_A
/// (eq. (30)), and the weights w = (k0, k1, k2, 1) are chosen so that the merged curve passes
/// through the deleted node at ū_H = (x_H − x_A)/l_AB (eqs. (31)–(32)). Multiplying eq. (34) by
/// K(ū_H) makes it linear in k (the paper's "linear equations"):
///   k0 [v³ (r_A − r_H) + l u v² r_x^A] + k1 [3 u v² (r_A − r_H)] + k2 [3 u² v (r_B − r_H)]
///     = −u³ (r_B − r_H) + l u² v r_x^B,          u = ū_H, v = 1 − u,                  (R26)
/// i.e. A k = c; with k = x + 1 (eq. (35)), A x = c − A 1 (eq. (36)), solved in the minimum-norm
/// least-squares sense (eq. (37), a complete orthogonal decomposition: 2 equations for 3 unknowns
/// in 2D, 3 in 3D, rank-deficient for collinear nodes); k = 1 (the ALE-ANCF element) when any
/// k_i ≤ 0 (eq. (38)).
///
/// Bound (ours; 000 bounds nothing but k ≤ 0): the minimum-norm solution is unbounded when H lies
/// almost on the chord of the merged element (k = 9.3 seen in suspended_beam), and a weight far
/// from 1 makes the parameterization's speed vary strongly along the element, which the axial
/// strain pays for. With a finite `max_weight` the solution is shrunk towards the ALE-ANCF weights,
/// k = 1 + t x with the largest t ∈ [0, 1] that keeps every k_i in [1/max_weight, max_weight]; the
/// merged curve then misses H by more (reported in `miss`).
///
/// A merge removes the coordinates of H and cannot keep the fields: what the rates become is a
/// choice (docs/rancf.md, "Merging"): here nodes A and B keep their rates and the velocity field
/// of the merged element follows from them (the paper's truncation).

#include <Eigen/Core>

#include <limits>

namespace spar::core {

struct RancfMergeWeights {
  Eigen::Vector4d weights;    ///< (k0, k1, k2, 1)
  bool fallback = false;      ///< some k_i ≤ 0: unit weights (000 eq. (38))
  bool bounded = false;       ///< shrunk towards 1 to keep the weights within the bound
  double miss = 0.0;          ///< |r̄(ū_H) − r_H| of the merged element (0 when eq. (32) holds)
};

/// The weights of the element merged from AH and HB. `e_ab` = [r_A, r_x^A, r_B, r_x^B] (the
/// merged element's nodal coordinates), r_h the deleted node, x_A < x_H < x_B; max_weight ≥ 1
/// (infinite: 000 as written). Throws spar::Error otherwise.
template <int Dim>
RancfMergeWeights merge_rancf_weights(const Eigen::Matrix<double, 4 * Dim, 1>& e_ab,
                                      const Eigen::Matrix<double, Dim, 1>& r_h, double x_a,
                                      double x_h, double x_b,
                                      double max_weight = std::numeric_limits<double>::infinity());

extern template RancfMergeWeights merge_rancf_weights<2>(const Eigen::Matrix<double, 8, 1>&,
                                                         const Eigen::Matrix<double, 2, 1>&,
                                                         double, double, double, double);
extern template RancfMergeWeights merge_rancf_weights<3>(const Eigen::Matrix<double, 12, 1>&,
                                                         const Eigen::Matrix<double, 3, 1>&,
                                                         double, double, double, double);

}  // namespace spar::core
