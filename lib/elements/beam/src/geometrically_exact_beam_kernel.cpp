// The geometrically exact beam element kernel: energy, force and exact Hessian (docs/beam.md).
//
// The energy of a Gauss point depends on the element unknowns only through twelve numbers
//   z = (x′, a, Θ, Θ′),   x′ = Σ N_I′ x_I,  a = Δφ_0,  Θ = Σ N_I ψ_I,  Θ′ = Σ N_I′ ψ_I,
// with ψ_I = log(exp(−Δφ_0) R_0ᵀ R_I exp(Δφ_I)) the Crisfield–Jelenić relative rotations about the
// first control point (003 eq. 40). The kernel therefore works in three stages:
//   1. per Gauss point, the gradient and Hessian of W = ½ εᵀ C ε in z (eqs. B5–B8);
//   2. the linear map z ← y, y = (x_0 … x_p, a, ψ_1 … ψ_p), accumulated over Gauss points (B9);
//   3. the nonlinear map y ← Δ through ψ_I(Δφ_0, Δφ_I), first and second order (B10–B11).
#include <spar/elements/beam/beam_element.hpp>

#include "beam_interpolation.hpp"

#include <spar/error.hpp>
#include <spar/lie/lie.hpp>

#include <numbers>
#include <string>

namespace spar::core {

namespace {

using Matrix3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;
using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Vector12 = Eigen::Matrix<double, 12, 1>;
using Matrix6x12 = Eigen::Matrix<double, 6, 12>;

// z-blocks.
constexpr int z_x_prime = 0, z_a = 1, z_theta = 2, z_theta_prime = 3;

/// Kinematics of one Gauss point (003 eqs. 41–42).
struct PointKinematics {
  lie::TangentCoefficients<double> coefficients;  // of exp, T and T's derivatives at Θ
  lie::ExpAndTangent<double> exp_tangent;  // E = exp(Θ), T = T(Θ)
  Matrix3 rotation;                        // R = R_r E
  Vector3 v;                               // R_rᵀ x′
  Vector3 w;                               // Eᵀ v = Rᵀ x′
  Vector3 kappa;                           // T Θ′
  Matrix3 kappa_derivative;                // ∂(TΘ′)/∂Θ: only where the stiffness is computed
};

PointKinematics kinematics(const detail::RelativeRotations& rel,
                           const detail::InterpolatedFields& f) {
  PointKinematics k;
  k.coefficients = lie::tangent_coefficients(f.theta);
  k.exp_tangent = lie::exp_and_tangent(f.theta, k.coefficients);
  k.rotation = rel.reference * k.exp_tangent.rotation;
  k.v = rel.reference.transpose() * f.x_prime;
  k.w = k.exp_tangent.rotation.transpose() * k.v;
  k.kappa = k.exp_tangent.tangent * f.theta_prime;
  return k;
}

/// B = ∂ε/∂z (docs/beam.md eq. B5):
///   γ rows: [Rᵀ, Eᵀ hat(v), hat(w) T, 0],  κ rows: [0, 0, ∂(TΘ′)/∂Θ, T].
Matrix6x12 strain_operator(const PointKinematics& k) {
  const Matrix3& E = k.exp_tangent.rotation;
  const Matrix3& T = k.exp_tangent.tangent;
  Matrix6x12 B = Matrix6x12::Zero();
  B.block<3, 3>(0, 3 * z_x_prime) = k.rotation.transpose();
  B.block<3, 3>(0, 3 * z_a) = E.transpose() * lie::hat(k.v);
  B.block<3, 3>(0, 3 * z_theta) = lie::hat(k.w) * T;
  B.block<3, 3>(3, 3 * z_theta) = k.kappa_derivative;
  B.block<3, 3>(3, 3 * z_theta_prime) = T;
  return B;
}

/// C B and Bᵀ (C B), the material part of H_z (docs/beam.md eq. B8), from B's nonzero blocks
/// (eq. B5): B's γ rows have no Θ′ columns and its κ rows no x′ or a columns, so C B takes
/// 270 products instead of 432 and Bᵀ (C B) 540 instead of 864.
Matrix6x12 constitutive_times_strain_operator(const Eigen::Matrix<double, 6, 6>& C, const Matrix6x12& B) {
  Matrix6x12 CB;
  CB.leftCols<6>().noalias() = C.leftCols<3>().lazyProduct(B.topLeftCorner<3, 6>());
  CB.middleCols<3>(3 * z_theta).noalias() = C.lazyProduct(B.middleCols<3>(3 * z_theta));
  CB.rightCols<3>().noalias() = C.rightCols<3>().lazyProduct(B.bottomRightCorner<3, 3>());
  return CB;
}

/// H += Bᵀ (C B) from B's nonzero blocks (see constitutive_times_strain_operator).
void add_material_stiffness(const Matrix6x12& B, const Matrix6x12& CB, Matrix12& H) {
  H.topRows<6>().noalias() += B.topLeftCorner<3, 6>().transpose().lazyProduct(CB.topRows<3>());
  H.middleRows<3>(3 * z_theta).noalias() += B.middleCols<3>(3 * z_theta).transpose().lazyProduct(CB);
  H.bottomRows<3>().noalias() += B.bottomRightCorner<3, 3>().transpose().lazyProduct(CB.bottomRows<3>());
}

/// Bᵀσ for σ = (n, m), written out from B's blocks (eq. B5) without forming B — the force
/// alone needs no more:  [R n,  (E n) × v,  Tᵀ (n × w) + (∂(TΘ′)/∂Θ)ᵀ m,  Tᵀ m], with
/// `curvature_gradient` = (∂(TΘ′)/∂Θ)ᵀ m, the gradient of mᵀ T(Θ) Θ′.
Vector12 strain_operator_transpose_times(const PointKinematics& k, const Vector3& n, const Vector3& m,
                                          const Vector3& curvature_gradient) {
  const Matrix3& E = k.exp_tangent.rotation;
  const Matrix3& T = k.exp_tangent.tangent;
  const Vector3 En = E * n;
  Vector12 g;
  g.segment<3>(3 * z_x_prime) = k.rotation * n;
  g.segment<3>(3 * z_a) = En.cross(k.v);
  g.segment<3>(3 * z_theta) =
      T.transpose() * n.cross(k.w) + curvature_gradient;
  g.segment<3>(3 * z_theta_prime) = T.transpose() * m;
  return g;
}

/// The geometric part Σ σ_i ∂²ε_i/∂z² with σ = (n, m) (docs/beam.md eqs. B6–B7).
Matrix12 geometric_stiffness(const PointKinematics& k, const detail::InterpolatedFields& f,
                             const detail::RelativeRotations& rel, const Vector3& n,
                             const Vector3& m) {
  const Matrix3& E = k.exp_tangent.rotation;
  const Matrix3& T = k.exp_tangent.tangent;
  const Vector3 u = E * n;
  const Matrix3 hat_n_T = lie::hat(n) * T;
  Matrix12 G = Matrix12::Zero();
  // nᵀγ = (R_r exp(a) E n)ᵀ x′: mixed x′–a, x′–Θ, and a–a, a–Θ, Θ–Θ terms (B6).
  G.block<3, 3>(3 * z_x_prime, 3 * z_a) = -rel.reference * lie::hat(u);
  G.block<3, 3>(3 * z_x_prime, 3 * z_theta) = -k.rotation * hat_n_T;
  Matrix3 aa = 0.5 * (u * k.v.transpose() + k.v * u.transpose());
  aa.diagonal().array() -= u.dot(k.v);
  G.block<3, 3>(3 * z_a, 3 * z_a) = aa;
  G.block<3, 3>(3 * z_a, 3 * z_theta) = lie::hat(k.v) * E * hat_n_T;
  G.block<3, 3>(3 * z_theta, 3 * z_theta) =
      lie::tangent_transpose_derivative(f.theta, n.cross(k.w), k.coefficients) +
      T.transpose() * lie::hat(n) * lie::hat(k.w) * T +
      // mᵀκ = mᵀ T(Θ) Θ′ (B7).
      lie::tangent_hessian(f.theta, m, f.theta_prime, k.coefficients);
  G.block<3, 3>(3 * z_theta_prime, 3 * z_theta) = lie::tangent_transpose_derivative(f.theta, m, k.coefficients);
  // Mirror the upper blocks.
  G.block<3, 3>(3 * z_a, 3 * z_x_prime) = G.block<3, 3>(3 * z_x_prime, 3 * z_a).transpose();
  G.block<3, 3>(3 * z_theta, 3 * z_x_prime) =
      G.block<3, 3>(3 * z_x_prime, 3 * z_theta).transpose();
  G.block<3, 3>(3 * z_theta, 3 * z_a) = G.block<3, 3>(3 * z_a, 3 * z_theta).transpose();
  G.block<3, 3>(3 * z_theta, 3 * z_theta_prime) =
      G.block<3, 3>(3 * z_theta_prime, 3 * z_theta).transpose();
  return G;
}

// The linear map z ← y of one Gauss point (B9): x′ = Σ N_I′ x_I, a, Θ = Σ N_I ψ_I (I ≥ 1),
// Θ′ = Σ N_I′ ψ_I, with y-blocks x_I → I, a → k, ψ_I → k + I. H_y += Lᵀ H_z L is added block by
// block in H_y's upper block triangle, the columns of ψ_J first combined into
// H_z(·, Θ) N_J + H_z(·, Θ′) N_J′.

/// The rows of the k translations x_I: (Lᵀ H_z L)(x_I, ·) = N_I′ (H_z L)(x′, ·), from H_z's x′ rows.
template <class Matrix>
void add_translation_rows(const BeamGaussPoint& gp, int k, const Eigen::Matrix<double, 3, 12>& H_x, Matrix& H_y) {
  const Matrix3 H_xx = H_x.middleCols<3>(3 * z_x_prime), H_xa = H_x.middleCols<3>(3 * z_a);
  for (int I = 0; I < k; ++I) {
    const double dN_I = gp.shape_derivative[I];
    for (int J = I; J < k; ++J) H_y.template block<3, 3>(3 * I, 3 * J) += dN_I * gp.shape_derivative[J] * H_xx;
    H_y.template block<3, 3>(3 * I, 3 * k) += dN_I * H_xa;
    for (int J = 1; J < k; ++J)
      H_y.template block<3, 3>(3 * I, 3 * (k + J)) +=
          dN_I * (gp.shape[J] * H_x.middleCols<3>(3 * z_theta) + gp.shape_derivative[J] * H_x.middleCols<3>(3 * z_theta_prime));
  }
}

/// The rows of a and of the k − 1 relative rotations ψ_I.
template <class Matrix>
void add_rotation_rows(const BeamGaussPoint& gp, int k, const Matrix12& H_z, Matrix& H_y) {
  H_y.template block<3, 3>(3 * k, 3 * k) += H_z.block<3, 3>(3 * z_a, 3 * z_a);
  for (int J = 1; J < k; ++J) {
    const Eigen::Matrix<double, 12, 3> column = gp.shape[J] * H_z.middleCols<3>(3 * z_theta) +
                                                gp.shape_derivative[J] * H_z.middleCols<3>(3 * z_theta_prime);
    H_y.template block<3, 3>(3 * k, 3 * (k + J)) += column.middleRows<3>(3 * z_a);
    for (int I = 1; I <= J; ++I)
      H_y.template block<3, 3>(3 * (k + I), 3 * (k + J)) += gp.shape[I] * column.middleRows<3>(3 * z_theta) +
                                                   gp.shape_derivative[I] * column.middleRows<3>(3 * z_theta_prime);
  }
}

/// Σ_i λ_i ∂²ψ_i/∂b² for ψ(b) = log(exp(ψ) exp(b)) at b = 0 (docs/beam.md eq. B10):
///   ∂(T⁻ᵀλ)/∂ψ · T⁻¹ − ½ hat(T⁻ᵀ λ),
/// from T⁻¹ = T⁻¹(ψ) and D = ∂(T⁻ᵀλ)/∂ψ, which the caller has for other terms too.
Matrix3 relative_rotation_hessian(const Matrix3& T_inverse, const Matrix3& D, const Vector3& lambda) {
  return D * T_inverse - 0.5 * lie::hat(Vector3(T_inverse.transpose() * lambda));
}

/// evaluate_beam_element for elements of `Nodes` control points (Eigen::Dynamic: any number up to
/// max_beam_element_nodes). With the count fixed, the element's vectors and matrices are
/// fixed-size, and Eigen unrolls the 3-column block products of stage 3 and the loops over nodes.
template <int Nodes>
void evaluate_element(const GeometricallyExactBeam& beam, int e, const Configuration& q,
                      const detail::RelativeRotations& rel, BeamEvaluation what, BeamElementResult& result) {
  constexpr int dofs = Nodes == Eigen::Dynamic ? Eigen::Dynamic : frame_dofs * Nodes;
  constexpr int max_dofs = Nodes == Eigen::Dynamic ? max_beam_element_dofs : dofs;
  using Vector = Eigen::Matrix<double, dofs, 1, Eigen::ColMajor, max_dofs, 1>;
  using Matrix = Eigen::Matrix<double, dofs, dofs, Eigen::ColMajor, max_dofs, max_dofs>;
  const bool with_force = (what != BeamEvaluation::energy);
  const bool with_stiffness = with_force && (what != BeamEvaluation::force);
  const bool rotation_blocks = (what == BeamEvaluation::force_and_stiffness);
  const int k = Nodes == Eigen::Dynamic ? rel.node_count : Nodes;
  const int n = frame_dofs * k;  // = size of y = size of Δ

  // Stage 1 and 2: energy, gradient g_y and Hessian H_y in y (B5–B9).
  Vector g_y = Vector::Zero(n);
  Matrix H_y;
  if (with_stiffness) H_y.setZero(n, n);
  result.strain_energy = 0.0;
  for (const BeamGaussPoint& gp : beam.element(e).gauss_points) {
    const detail::InterpolatedFields f =
        detail::interpolate(beam, e, q, rel, gp.shape, gp.shape_derivative);
    PointKinematics kin = kinematics(rel, f);
    Eigen::Matrix<double, 6, 1> strain;
    strain << kin.w - gp.reference_translational_strain, kin.kappa - gp.reference_curvature;
    const Eigen::Matrix<double, 6, 6>& C = beam.constitutive()[gp.part];
    const Eigen::Matrix<double, 6, 1> stress = C * strain;  // (N, M), 003 eq. 17
    result.strain_energy += 0.5 * gp.weight * strain.dot(stress);
    if (!with_force) continue;

    // (∂κ/∂Θ)ᵀ m from the derivative where the stiffness needs it anyway, else directly.
    if (with_stiffness) kin.kappa_derivative = lie::tangent_derivative(f.theta, f.theta_prime, kin.coefficients);
    const Vector3 curvature_gradient =
        with_stiffness ? Vector3(kin.kappa_derivative.transpose() * stress.tail<3>())
                       : lie::tangent_gradient(f.theta, stress.tail<3>(), f.theta_prime, kin.coefficients);
    const Vector12 g_z =
        gp.weight * strain_operator_transpose_times(kin, stress.head<3>(), stress.tail<3>(), curvature_gradient);
    // g_y += Lᵀ g_z for the linear map z ← y of B9: x′ = Σ N_I′ x_I, a, Θ = Σ N_I ψ_I, Θ′ = Σ N_I′ ψ_I.
    for (int I = 0; I < k; ++I)
      g_y.template segment<3>(3 * I) += gp.shape_derivative[I] * g_z.segment<3>(3 * z_x_prime);
    g_y.template segment<3>(3 * k) += g_z.segment<3>(3 * z_a);
    for (int I = 1; I < k; ++I)
      g_y.template segment<3>(3 * (k + I)) += gp.shape[I] * g_z.segment<3>(3 * z_theta) +
                                              gp.shape_derivative[I] * g_z.segment<3>(3 * z_theta_prime);
    if (!with_stiffness) continue;
    // C B once, then Bᵀ (C B), both as coefficient-wise products of B's nonzero blocks: Eigen
    // would hand a 12 × 6 × 12 product to its blocked GEMM, whose packing costs more than the
    // product at this size.
    const Matrix6x12 B = strain_operator(kin);
    const Matrix6x12 CB = constitutive_times_strain_operator(C, B);
    if (!rotation_blocks) {
      // Only the x′ rows of H_z reach a translation row or column of K (B9 with the rotation
      // rows left out): H_z(x′, ·) = w (B_x′ᵀ C B + G(x′, ·)), G(x′, ·) from B6; B_x′ = [Rᵀ; 0].
      Eigen::Matrix<double, 3, 12> H_x;
      H_x.noalias() = gp.weight * B.topLeftCorner<3, 3>().transpose().lazyProduct(CB.topRows<3>());
      H_x.middleCols<3>(3 * z_a) -=
          gp.weight * rel.reference * lie::hat(Vector3(kin.exp_tangent.rotation * stress.head<3>()));
      H_x.middleCols<3>(3 * z_theta) -=
          gp.weight * kin.rotation * lie::hat(Vector3(stress.head<3>())) * kin.exp_tangent.tangent;
      add_translation_rows(gp, k, H_x, H_y);
      continue;
    }

    Matrix12 H_z = geometric_stiffness(kin, f, rel, stress.head<3>(), stress.tail<3>());
    add_material_stiffness(B, CB, H_z);
    H_z *= gp.weight;
    add_translation_rows(gp, k, H_z.middleRows<3>(3 * z_x_prime), H_y);
    add_rotation_rows(gp, k, H_z, H_y);
  }

  if (!with_force) {
    result.internal_force.resize(0);
    return;
  }
  // Stage 3: y ← Δ (B10–B11). Δ-blocks: translation of node I → 2I, rotation → 2I + 1.
  // ∂ψ_I/∂Δφ_I = T⁻¹(ψ_I), ∂ψ_I/∂Δφ_0 = −T⁻ᵀ(ψ_I), x and a map identically.
  std::array<Matrix3, max_beam_element_nodes> d_psi_d_own, d_psi_d_first;
  for (int I = 1; I < k; ++I) {
    d_psi_d_own[I] = lie::tangent_inverse(rel.psi[I]);
    d_psi_d_first[I] = -d_psi_d_own[I].transpose();
  }
  result.internal_force.resize(n);
  for (int I = 0; I < k; ++I) result.internal_force.segment<3>(6 * I) = g_y.template segment<3>(3 * I);
  result.internal_force.segment<3>(3) = g_y.template segment<3>(3 * k);
  for (int I = 1; I < k; ++I) {
    const auto g_psi = g_y.template segment<3>(3 * (k + I));
    result.internal_force.segment<3>(6 * I + 3) = d_psi_d_own[I].transpose() * g_psi;
    result.internal_force.segment<3>(3) += d_psi_d_first[I].transpose() * g_psi;
  }
  if (!with_stiffness) return;

  // H_y is filled in its upper block triangle; complete it.
  H_y.template triangularView<Eigen::StrictlyLower>() = H_y.transpose();
  // H_Δ = Jᵀ H_y J with J (Δ → y) block sparse: Δ-block 2I (translation of node I) ← y-block I;
  // 2I + 1 (rotation of node I ≥ 1) ← y-block k + I through T⁻¹(ψ_I); 1 (rotation of node 0)
  // ← y-block k and every y-block k + I through −T⁻ᵀ(ψ_I). First HJ = H_y J, then Jᵀ HJ.
  Matrix HJ(n, n);
  HJ.template middleCols<3>(3) = H_y.template middleCols<3>(3 * k);
  for (int I = 0; I < k; ++I) {
    HJ.template middleCols<3>(6 * I) = H_y.template middleCols<3>(3 * I);
    if (I == 0) continue;
    HJ.template middleCols<3>(3).noalias() +=
        H_y.template middleCols<3>(3 * (k + I)).lazyProduct(d_psi_d_first[I]);
    HJ.template middleCols<3>(6 * I + 3).noalias() =
        H_y.template middleCols<3>(3 * (k + I)).lazyProduct(d_psi_d_own[I]);
  }
  ElementMatrix& K = result.stiffness;
  K.resize(n, n);
  K.middleRows<3>(3) = HJ.template middleRows<3>(3 * k);
  for (int I = 0; I < k; ++I) {
    K.middleRows<3>(6 * I) = HJ.template middleRows<3>(3 * I);
    if (I == 0) continue;
    K.middleRows<3>(3).noalias() +=
        d_psi_d_first[I].transpose().lazyProduct(HJ.template middleRows<3>(3 * (k + I)));
    K.middleRows<3>(6 * I + 3).noalias() =
        d_psi_d_own[I].transpose().lazyProduct(HJ.template middleRows<3>(3 * (k + I)));
  }
  // Second-order terms of ψ_I(Δφ_0, Δφ_I) contracted with λ = ∂Π/∂ψ_I (B10): rotation–rotation
  // blocks only.
  if (!rotation_blocks) return;
  for (int I = 1; I < k; ++I) {
    const Vector3 lambda = g_y.template segment<3>(3 * (k + I));
    const Vector3& psi = rel.psi[I];
    const Matrix3 D = lie::tangent_inverse_transpose_derivative(psi, lambda);
    result.stiffness.block<3, 3>(6 * I + 3, 6 * I + 3) += relative_rotation_hessian(d_psi_d_own[I], D, lambda);
    // The aa term is the bb term at (−ψ, −λ) (B10), where T⁻¹(−ψ) = T⁻ᵀ(ψ).
    result.stiffness.block<3, 3>(3, 3) += relative_rotation_hessian(
        d_psi_d_own[I].transpose(), lie::tangent_inverse_transpose_derivative(Vector3(-psi), Vector3(-lambda)),
        Vector3(-lambda));
    const Matrix3 cross = -D * d_psi_d_own[I].transpose();
    result.stiffness.block<3, 3>(6 * I + 3, 3) += cross;
    result.stiffness.block<3, 3>(3, 6 * I + 3) += cross.transpose();
  }
}

}  // namespace

namespace detail {

RelativeRotations relative_rotations(const GeometricallyExactBeam& beam, int e,
                                     const Configuration& q) {
  RelativeRotations rel;
  rel.node_count = beam.degree() + 1;
  const int first = beam.node(beam.element(e).first_control_point);
  rel.reference = q.rotation[first];
  rel.psi[0].setZero();
  for (int I = 1; I < rel.node_count; ++I) {
    // R_rᵀR_I is a product of the model's rotations: log's input check (for user input) is skipped.
    rel.psi[I] = lie::rotation_vector_from_quaternion(
        lie::quaternion_from_rotation(Eigen::Matrix3d(rel.reference.transpose() * q.rotation[first + I])));
    // 1e-6 short of π: beyond it log(R_rᵀR_I) jumps to the opposite vector and the
    // interpolated rotation field tears.
    if (rel.psi[I].norm() > std::numbers::pi - 1e-6)
      throw Error("control points " + std::to_string(first) + " and " +
                      std::to_string(first + I) + " of element " + std::to_string(e) +
                      " are rotated by pi relative to each other",
                  "core::evaluate_beam_element",
                  "refine the beam mesh, or reduce the load or time step so rotations stay smooth");
  }
  return rel;
}

}  // namespace detail

BeamStrains beam_strains(const GeometricallyExactBeam& beam, int e, int g, const Configuration& q) {
  const BeamGaussPoint& gp = beam.element(e).gauss_points[g];
  const detail::RelativeRotations rel = detail::relative_rotations(beam, e, q);
  const detail::InterpolatedFields f =
      detail::interpolate(beam, e, q, rel, gp.shape, gp.shape_derivative);
  const PointKinematics k = kinematics(rel, f);
  return {k.w - gp.reference_translational_strain, k.kappa - gp.reference_curvature, k.rotation};
}

void evaluate_beam_element(const GeometricallyExactBeam& beam, int e, const Configuration& q,
                           BeamEvaluation what, BeamElementResult& result) {
  const detail::RelativeRotations rel = detail::relative_rotations(beam, e, q);
  switch (rel.node_count) {
    case 2: return evaluate_element<2>(beam, e, q, rel, what, result);
    case 3: return evaluate_element<3>(beam, e, q, rel, what, result);
    case 4: return evaluate_element<4>(beam, e, q, rel, what, result);
    default: return evaluate_element<Eigen::Dynamic>(beam, e, q, rel, what, result);
  }
}

void add_local_tangent_correction(const Eigen::Ref<const Eigen::VectorXd>& force,
                                  Eigen::Ref<Eigen::MatrixXd> tangent) {
  for (int I = 0; I < force.size() / frame_dofs; ++I)
    tangent.block<3, 3>(6 * I + 3, 6 * I + 3) +=
        0.5 * lie::hat(Eigen::Vector3d(force.segment<3>(6 * I + 3)));
}

}  // namespace spar::core
