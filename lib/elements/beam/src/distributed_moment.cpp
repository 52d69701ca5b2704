// Distributed moments on beam elements (docs/beam.md B14).
#include <spar/elements/beam/distributed_moment.hpp>

#include "beam_interpolation.hpp"

#include <spar/lie/lie.hpp>

#include <array>

namespace spar::core {

void distributed_moment_contribution(const GeometricallyExactBeam& beam, int e,
                                     const Configuration& q,
                                     const Eigen::Vector3d& moment_per_length, MomentFrame frame,
                                     Eigen::VectorXd& force, Eigen::MatrixXd* tangent) {
  const detail::RelativeRotations rel = detail::relative_rotations(beam, e, q);
  const int k = rel.node_count;
  // Variables y = (a, ψ_1 … ψ_p): block 0 is a, block I is ψ_I.
  Eigen::VectorXd f_y = Eigen::VectorXd::Zero(3 * k);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(3 * k, 3 * k);  // ∂f_y/∂y along q ⊕ Δ
  // A dead moment has fixed material components in R_r's frame: μ = R_rᵀ m (then m = Eᵀμ).
  const Eigen::Vector3d mu = rel.reference.transpose() * moment_per_length;
  for (const BeamGaussPoint& gp : beam.element(e).gauss_points) {
    if (gp.part != 0) continue;  // the full rule (two points for p = 1)
    Eigen::Vector3d theta = Eigen::Vector3d::Zero();
    for (int I = 1; I < k; ++I) theta += gp.shape[I] * rel.psi[I];
    const lie::ExpAndTangent<double> et = lie::exp_and_tangent(theta);
    const Eigen::Matrix3d& E = et.rotation;
    const Eigen::Matrix3d& T = et.tangent;
    const double w = gp.weight;
    if (frame == MomentFrame::material) {
      const Eigen::Vector3d& m = moment_per_length;
      // f_a = E m, f_ψI = N_I Tᵀ m; ∂(E m)/∂Θ = −E hat(m) T, ∂(Tᵀm)/∂Θ (eq. C6).
      f_y.head<3>() += w * E * m;
      const Eigen::Matrix3d dfa = -E * lie::hat(m) * T;
      const Eigen::Matrix3d dfpsi = lie::tangent_transpose_derivative(theta, m);
      for (int I = 1; I < k; ++I) {
        f_y.segment<3>(3 * I) += w * gp.shape[I] * T.transpose() * m;
        for (int J = 1; J < k; ++J) {
          if (I == 1) G.block<3, 3>(0, 3 * J) += w * gp.shape[J] * dfa;
          G.block<3, 3>(3 * I, 3 * J) += w * gp.shape[I] * gp.shape[J] * dfpsi;
        }
      }
    } else {
      // m = Eᵀμ: f_a = μ, f_ψI = N_I T μ (E T = Tᵀ); μ = exp(−a) R_rᵀ m_inertial turns with a.
      f_y.head<3>() += w * mu;
      G.block<3, 3>(0, 0) += w * lie::hat(mu);
      const Eigen::Matrix3d dfpsi = lie::tangent_derivative(theta, mu);
      const Eigen::Matrix3d dfpsi_da = T * lie::hat(mu);
      for (int I = 1; I < k; ++I) {
        f_y.segment<3>(3 * I) += w * gp.shape[I] * T * mu;
        G.block<3, 3>(3 * I, 0) += w * gp.shape[I] * dfpsi_da;
        for (int J = 1; J < k; ++J) G.block<3, 3>(3 * I, 3 * J) += w * gp.shape[I] * gp.shape[J] * dfpsi;
      }
    }
  }

  // y ← Δ: a ← Δφ_0; ψ_I ← T⁻¹(ψ_I) Δφ_I − T⁻ᵀ(ψ_I) Δφ_0 (B10). J[I] maps the rotations of the
  // element's nodes (3k) to y.
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(3 * k, 3 * k);
  J.block<3, 3>(0, 0).setIdentity();
  std::array<Eigen::Matrix3d, max_beam_element_nodes> T_inverse;
  for (int I = 1; I < k; ++I) {
    T_inverse[I] = lie::tangent_inverse(rel.psi[I]);
    J.block<3, 3>(3 * I, 3 * I) = T_inverse[I];
    J.block<3, 3>(3 * I, 0) = -T_inverse[I].transpose();
  }
  const Eigen::VectorXd f_rot = J.transpose() * f_y;
  force = Eigen::VectorXd::Zero(frame_dofs * k);
  for (int I = 0; I < k; ++I) force.segment<3>(6 * I + 3) = f_rot.segment<3>(3 * I);
  if (!tangent) return;
  // ∂(Jᵀ f_y)/∂Δ = Jᵀ G J + (the derivative of Jᵀ at fixed f_y through ψ).
  Eigen::MatrixXd K_rot = J.transpose() * G * J;
  for (int I = 1; I < k; ++I) {
    const Eigen::Vector3d f_psi = f_y.segment<3>(3 * I);
    const Eigen::Matrix3d d_own = lie::tangent_inverse_transpose_derivative(rel.psi[I], f_psi);
    const Eigen::Matrix3d d_first = -lie::tangent_inverse_derivative(rel.psi[I], f_psi);
    // ∂ψ_I/∂Δφ_I = T⁻¹, ∂ψ_I/∂Δφ_0 = −T⁻ᵀ.
    K_rot.block<3, 3>(3 * I, 3 * I) += d_own * T_inverse[I];
    K_rot.block<3, 3>(3 * I, 0) -= d_own * T_inverse[I].transpose();
    K_rot.block<3, 3>(0, 3 * I) += d_first * T_inverse[I];
    K_rot.block<3, 3>(0, 0) -= d_first * T_inverse[I].transpose();
  }
  tangent->setZero(frame_dofs * k, frame_dofs * k);
  for (int I = 0; I < k; ++I)
    for (int L = 0; L < k; ++L)
      tangent->block<3, 3>(6 * I + 3, 6 * L + 3) = K_rot.block<3, 3>(3 * I, 3 * L);
}

}  // namespace spar::core
