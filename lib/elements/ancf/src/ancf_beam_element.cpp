#include <spar/elements/ancf/ancf_beam_element.hpp>

#include "ancf_variables.hpp"

#include <spar/error.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <span>
#include <utility>

namespace spar::core {

using detail::transverse_shear;
using detail::variable_column;
using detail::variable_phi;

// Section kernel --------------------------------------------------------------------------------

namespace {

using Matrix3 = Eigen::Matrix3d;

/// Subtracts c J, J = ∫ (E_xx − Ē_xx)² dA, from W̄ and its derivatives (eq. A21). With
/// x = (a, b, c), E_xx = Σ_ij φ_i φ_j ε_ij, ε_ij = ½ x_i · x_j − ½ δ_i0 δ_j0:
///   J = Σ_ij ε_ij σ_ij,  σ_ij = Σ_kl M_ijkl ε_kl − M_ij00 Ē_xx,  Ē_xx = Σ_ij M_ij00 ε_ij / A,
///   ∂J/∂x_k = 2 Σ_j σ_kj x_j,  ∂²J/∂x_k∂x_l = 2 σ_kl I + 2 Σ_jq (M_kjlq − M_kj00 M_lq00/A) x_j x_qᵀ.
double subtract_poisson_correction(const double (&M)[3][3][3][3], double c, const Eigen::Matrix<double, 15, 1>& u,
                                   Eigen::Matrix<double, 15, 1>& gradient, Eigen::Matrix<double, 15, 15>* hessian) {
  const double A = M[0][0][0][0];
  Eigen::Vector3d x[3] = {u.segment<3>(0), u.segment<3>(3), u.segment<3>(6)};
  double eps[3][3], sigma[3][3], mean = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      eps[i][j] = 0.5 * x[i].dot(x[j]) - (i == 0 && j == 0 ? 0.5 : 0.0);
      mean += M[i][j][0][0] * eps[i][j] / A;
    }
  double J = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      sigma[i][j] = -M[i][j][0][0] * mean;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) sigma[i][j] += M[i][j][k][l] * eps[k][l];
      J += eps[i][j] * sigma[i][j];
    }
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) gradient.segment<3>(3 * k) -= 2 * c * sigma[k][j] * x[j];
  if (hessian != nullptr)
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        Matrix3 h = 2 * sigma[k][l] * Matrix3::Identity();
        for (int j = 0; j < 3; ++j)
          for (int q = 0; q < 3; ++q) {
            const double n = M[k][j][l][q] - M[k][j][0][0] * M[l][q][0][0] / A;
            if (n != 0.0) h.noalias() += 2 * n * x[j] * x[q].transpose();
          }
        hessian->block<3, 3>(3 * k, 3 * l) -= c * h;
      }
  return c * J;
}

}  // namespace

double ancf_section_energy(const double (&M)[3][3][3][3], const AncfSectionLaw& law,
                           const Eigen::Matrix<double, 15, 1>& u, Eigen::Matrix<double, 15, 1>& gradient,
                           Eigen::Matrix<double, 15, 15>* hessian) {
  const double lambda = law.lambda, mu = law.mu, poisson_correction = law.poisson_correction;
  // (k − 1)μ, the shear factor's addition to the transverse shear moduli (eq. A22); 0 at k = 1,
  // where every term it multiplies is skipped (the plain law's numbers, bit for bit).
  const double shear_excess = (law.shear_factor - 1) * mu;
  // F(y, z) = Σ_p φ_p F_p (eq. A7).
  Matrix3 F[3];
  F[0] << u.segment<3>(0), u.segment<3>(9), u.segment<3>(12);
  F[1].setZero();
  F[1].col(0) = u.segment<3>(3);
  F[2].setZero();
  F[2].col(0) = u.segment<3>(6);
  // E = Σ_ij φ_i φ_j Ê_ij with Ê_ij = ¼(F_iᵀF_j + F_jᵀF_i) − ½ I δ_i0 δ_j0; Ŝ_ij = λ tr Ê_ij I + 2μ Ê_ij
  // (eq. A13). F₁ = b e₀ᵀ and F₂ = c e₀ᵀ have one column, which leaves Ê₀₀ = ½(F₀ᵀF₀ − I),
  // Ê₀ⱼ = ¼(w e₀ᵀ + e₀ wᵀ) with w = F₀ᵀ x_j, and Ê_ij = ½ (x_i · x_j) e₀e₀ᵀ for i, j ≥ 1 (x₁ = b,
  // x₂ = c).
  // The matrices are built by whole-matrix expressions: writing single entries of a matrix that
  // is then read in packets stalls the store forwarding (perf: a third of the kernel's time).
  const Eigen::Vector3d e0 = Eigen::Vector3d::UnitX();
  const Matrix3 e0e0 = e0 * e0.transpose();
  Matrix3 E[3][3], Sbar[3][3];
  E[0][0] = 0.5 * (F[0].transpose() * F[0] - Matrix3::Identity());
  double e_scalar[3][3];  // (Ê_ij)₀₀ for i, j ≥ 1
  for (int j = 1; j < 3; ++j) {
    const Eigen::Vector3d w = 0.25 * F[0].transpose() * F[j].col(0);
    E[0][j] = E[j][0] = w * e0.transpose() + e0 * w.transpose();
    for (int i = 1; i <= j; ++i) {
      e_scalar[i][j] = e_scalar[j][i] = 0.5 * F[i].col(0).dot(F[j].col(0));
      E[i][j] = E[j][i] = e_scalar[i][j] * e0e0;
    }
  }
  // S̄_pq = ∫ φ_p φ_q S dA = Σ_ij M_pqij Ŝ_ij = λ tr(Ē_pq) I + 2μ Ē_pq + 2(k − 1)μ X∘Ē_pq with
  // Ē_pq = Σ_ij M_pqij Ê_ij (Ŝ is linear in Ê; X masks the transverse shear entries (0, 1), (0, 2)
  // and their transposes, eq. A22), summed over i ≤ j (M and Ê are symmetric in i, j).
  static const Matrix3 shear_mask =
      Matrix3::NullaryExpr([](Eigen::Index i, Eigen::Index j) { return transverse_shear(int(i), int(j)) ? 1.0 : 0.0; });
  double W = 0.0;
  for (int p = 0; p < 3; ++p)
    for (int q = p; q < 3; ++q) {
      const double(&m)[3][3] = M[p][q];
      const double tail = m[1][1] * e_scalar[1][1] + 2 * m[1][2] * e_scalar[1][2] + m[2][2] * e_scalar[2][2];
      const Matrix3 e = m[0][0] * E[0][0] + 2 * m[0][1] * E[0][1] + 2 * m[0][2] * E[0][2] + tail * e0e0;
      Matrix3 s = 2 * mu * e + lambda * e.trace() * Matrix3::Identity();
      if (shear_excess != 0.0) s += 2 * shear_excess * e.cwiseProduct(shear_mask);
      Sbar[p][q] = Sbar[q][p] = s;
      W += (p == q ? 0.5 : 1.0) * E[p][q].cwiseProduct(s).sum();  // W̄ = ½ Σ_pq Ê_pq : S̄_pq
    }
  // ∂W̄/∂u_v = ∫ φ_p P e_α dA = Σ_k F_k S̄_pk e_α (P = F S; eq. A14).
  // F_k S̄ e_α = x_k S̄(0, α) for k ≥ 1.
  for (int v = 0; v < 5; ++v) {
    const int p = variable_phi[v], alpha = variable_column[v];
    gradient.segment<3>(3 * v) = F[0] * Sbar[p][0].col(alpha) + Sbar[p][1](0, alpha) * F[1].col(0) +
                                 Sbar[p][2](0, alpha) * F[2].col(0);
  }
  if (hessian == nullptr)
    return poisson_correction == 0.0 ? W : W - subtract_poisson_correction(M, poisson_correction, u, gradient, nullptr);
  // ∂²W̄/∂u_v∂u_w = ∫ φ_p φ_q [S_αβ I + λ F_α F_βᵀ + μ(δ_αβ F Fᵀ + F_β F_αᵀ)] dA (eq. A15),
  // with ∫ φ_p φ_q F_α F_βᵀ dA = T_pq(α, β) = Σ_ij M_pqij F_i e_α (F_j e_β)ᵀ. F_i e_α vanishes for
  // i > 0 < α (F₁, F₂ have one column), which leaves ≤ 25 terms per (p, q) for all nine (α, β).
  // The shear factor adds (k − 1)μ [X_αβ T_pq(β, α) + δ_αβ Σ_γ X_αγ T_pq(γ, γ)] (eq. A23).
  Matrix3 T[3][3][3][3];  // [p][q][α][β], p ≤ q
  for (int p = 0; p < 3; ++p)
    for (int q = p; q < 3; ++q)
      for (int alpha = 0; alpha < 3; ++alpha)
        for (int beta = 0; beta < 3; ++beta) {
          Matrix3& t = T[p][q][alpha][beta];
          t.setZero();
          for (int i = 0; i < (alpha == 0 ? 3 : 1); ++i)
            for (int j = 0; j < (beta == 0 ? 3 : 1); ++j)
              if (M[p][q][i][j] != 0.0) t.noalias() += M[p][q][i][j] * F[i].col(alpha) * F[j].col(beta).transpose();
        }
  for (int v = 0; v < 5; ++v)
    for (int w = v; w < 5; ++w) {
      int p = variable_phi[v], alpha = variable_column[v];
      int q = variable_phi[w], beta = variable_column[w];
      // T_qp(β, α) = T_pq(α, β)ᵀ: order the pair so that p ≤ q, and transpose the block back.
      const bool swapped = p > q;
      if (swapped) {
        std::swap(p, q);
        std::swap(alpha, beta);
      }
      Matrix3 block = Sbar[p][q](alpha, beta) * Matrix3::Identity() + lambda * T[p][q][alpha][beta] +
                      mu * T[p][q][beta][alpha];
      if (alpha == beta) block += mu * (T[p][q][0][0] + T[p][q][1][1] + T[p][q][2][2]);
      if (shear_excess != 0.0) {
        if (transverse_shear(alpha, beta)) block += shear_excess * T[p][q][beta][alpha];
        else if (alpha == beta)
          block += shear_excess * (alpha == 0 ? (T[p][q][1][1] + T[p][q][2][2]).eval() : T[p][q][0][0]);
      }
      if (swapped) block.transposeInPlace();
      hessian->block<3, 3>(3 * v, 3 * w) = block;
      if (w != v) hessian->block<3, 3>(3 * w, 3 * v) = block.transpose();
    }
  if (poisson_correction != 0.0) W -= subtract_poisson_correction(M, poisson_correction, u, gradient, hessian);
  return W;
}

// Element ---------------------------------------------------------------------------------------

template <int transverse>
AncfBeamElement<transverse>::AncfBeamElement(std::vector<int> blocks, std::shared_ptr<const Tables> tables,
                                             const Configuration& q0, int index)
    : blocks_(std::move(blocks)), tables_(std::move(tables)), index_(index) {
  const std::string where = "core::AncfBeamElement (" + name() + ")";
  const std::size_t expected = transverse == 2 ? 2 : 3;
  if (blocks_.size() != expected)
    throw Error("expected " + std::to_string(expected) + " blocks, got " + std::to_string(blocks_.size()),
                where, "give the two nodes (and, for the 30-coordinate element, its own block of 6)");
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const int want = b < 2 ? 12 : 6;
    if (blocks_[b] < 0 || blocks_[b] >= q0.block_count() || q0.is_frame(blocks_[b]) ||
        q0.blocks[blocks_[b]].size != want)
      throw Error("block " + std::to_string(blocks_[b]) + " is not a vector block of " + std::to_string(want),
                  where, "nodes are vector blocks (r, r_x, r_y, r_z); the extra block has 6 entries");
  }
  // The reference configuration must be strain free: F₀ = [a g h] orthogonal, b = c = 0.
  // The nodes' distance is a difference of two positions, each rounded to its own magnitude, so
  // it is known to 1e-12 of the length only up to ε (|r_A| + |r_B|): a 5e-5 m element of a 1 m
  // beam, or a 5 cm one 1e4 m from the origin, has a length known to ~1e-16 or ~2e-12 m, below
  // 1e-12 of it (issue 29: ancf_cantilever refused its own beam from ~10⁴ elements).
  const Vector e0 = coordinates(q0);
  const Eigen::Vector3d r_A = e0.template head<3>(), r_B = e0.template segment<3>(12);
  const double l = (r_B - r_A).norm();
  const double roundoff = std::numeric_limits<double>::epsilon() * (r_A.norm() + r_B.norm());
  if (std::fabs(l - tables_->length) > 1e-12 * tables_->length + roundoff)
    throw Error("the nodes are " + significant(l) + " apart, the tables' length is " + significant(tables_->length) +
                    " (they differ by " + significant(l - tables_->length) + ")",
                where, "build the tables for this element's length");
  for (int g = 0; g < Tables::points; ++g) {
    Eigen::Matrix<double, 15, 1> u;
    Eigen::Map<Eigen::Matrix<double, 3, 5>>(u.data()) =
        Eigen::Map<const Eigen::Matrix<double, 3, Tables::n>>(e0.data()) * tables_->coefficients[g].transpose();
    Matrix3 F0;
    F0 << u.template segment<3>(0), u.template segment<3>(9), u.template segment<3>(12);
    const double distortion = (F0.transpose() * F0 - Matrix3::Identity()).norm() +
                              l * (u.template segment<6>(3).norm());
    if (!(distortion < 1e-9))
      throw Error("the reference configuration is not straight and undistorted (|F0ᵀF0 − I| + l|∇r_y,z| = " +
                      std::to_string(distortion) + ")",
                  where, "place the nodes on a line with orthonormal r_x, r_y, r_z (elements/ancf/ancf_beam.hpp)");
  }
}

template <int transverse>
std::string AncfBeamElement<transverse>::name() const {
  return "ANCF beam element " + std::to_string(index_) + " (" + std::to_string(dofs) + " coordinates)";
}

template <int transverse>
typename AncfBeamElement<transverse>::Vector AncfBeamElement<transverse>::coordinates(const Configuration& q) const {
  Vector e;
  int k = 0;
  for (int b : blocks_) {
    const int size = q.blocks[b].size;
    e.segment(k, size) = q.values.segment(q.blocks[b].offset, size);
    k += size;
  }
  return e;
}

template <int transverse>
double AncfBeamElement<transverse>::strain_energy(const Vector& e) const {
  Vector Q;
  return elastic_force(e, Q, nullptr);
}

template <int transverse>
double AncfBeamElement<transverse>::elastic_force(const Vector& e, Vector& Q, Matrix* K) const {
  return tables_->method == AncfForceMethod::invariant ? invariant_force(e, Q, K) : gerstmayr_force(e, Q, K);
}

template <int transverse>
double AncfBeamElement<transverse>::invariant_force(const Vector& e, Vector& Q, Matrix* K) const {
  constexpr int n = Tables::n;
  const Tables& t = *tables_;
  const Eigen::Map<const Eigen::Matrix<double, 3, n>> nodes(e.data());
  // Γ_ab = e_a · e_b; K₂(e) = κ₂ ⊗ I₃ with κ₂_ab = Σ_cd τ_abcd Γ_cd (001 eq. 32, eq. A19),
  // summed over the symmetric pairs a ≤ b, c ≤ d (Tables::invariant_quartic_pairs).
  constexpr int pairs = Tables::pairs;
  // lazyProduct: coefficient-based, as for all the small products here; for n = 10 Eigen's
  // default would dispatch to its blocked GEMM, whose packing costs more than the product.
  const Eigen::Matrix<double, n, n> gram = nodes.transpose().lazyProduct(nodes);
  Eigen::Matrix<double, pairs, 1> gram_pairs, k2_pairs;
  for (int k = 0; k < pairs; ++k) gram_pairs(k) = gram(Tables::pair_first[k], Tables::pair_second[k]);
  k2_pairs.noalias() = t.invariant_quartic_pairs * gram_pairs;
  Eigen::Matrix<double, n, n> k2;
  for (int k = 0; k < pairs; ++k)
    k2(Tables::pair_first[k], Tables::pair_second[k]) = k2(Tables::pair_second[k], Tables::pair_first[k]) = k2_pairs(k);
  const Eigen::Matrix<double, n, n> k = t.invariant_linear + k2;
  // Q = (K₁ + K₂(e)) e (001 eq. 36 with eq. 23).
  Eigen::Map<Eigen::Matrix<double, 3, n>>(Q.data()).noalias() = nodes.lazyProduct(k);
  if (K != nullptr) {
    // J = K₁ + K₂(e) + 2 D(e), D_(a)(m) = Σ_bc τ_abcm e_b e_cᵀ (001 eq. 37, eq. A20).
    for (int a = 0; a < n; ++a)
      for (int m = 0; m < n; ++m) {
        Eigen::Matrix<double, n, n> tam;  // tam(b, c) = τ_abcm
        for (int c = 0; c < n; ++c) tam.col(c) = t.invariant_quartic.col(c + n * m).template segment<n>(n * a);
        const Eigen::Matrix<double, 3, n> nodes_tam = nodes.lazyProduct(tam);
        K->template block<3, 3>(3 * a, 3 * m) =
            k(a, m) * Matrix3::Identity() + 2 * nodes_tam.lazyProduct(nodes.transpose());
      }
  }
  // U = U₀ + ½ Σ κ₁_ab Γ_ab + ¼ Σ κ₂_ab Γ_ab.
  return t.invariant_constant + (0.5 * t.invariant_linear + 0.25 * k2).cwiseProduct(gram).sum();
}

/// The node vectors that row v of the coefficients B touches (its other entries are zero by
/// construction): a = r₀′ the axial vectors, b = r_y′ and g = r_y the y vectors, c and h the z ones.
template <int transverse>
std::span<const int> AncfBeamElement<transverse>::row_vectors(int v) {
  if (v == 0) return Shape::axial_vectors;
  return v == 1 || v == 3 ? std::span<const int>(Shape::y_vectors) : std::span<const int>(Shape::z_vectors);
}

template <int transverse>
double AncfBeamElement<transverse>::gerstmayr_force(const Vector& e, Vector& Q, Matrix* K) const {
  constexpr int n = Tables::n;
  const Tables& t = *tables_;
  const Eigen::Map<const Eigen::Matrix<double, 3, n>> nodes(e.data());
  Eigen::Map<Eigen::Matrix<double, 3, n>> force(Q.data());
  double U = 0.0;
  Q.setZero();
  if (K != nullptr) K->setZero();
  Eigen::Matrix<double, 15, 1> u, gradient;
  Eigen::Matrix<double, 15, 15> hessian;
  Matrix3 HB[5][n];
  for (int g = 0; g < Tables::points; ++g) {
    // u = (B ⊗ I₃) e: the columns a, b, c, g, h of nodes · Bᵀ (eq. A7), over B's non-zeros.
    const Eigen::Matrix<double, 5, n>& B = t.coefficients[g];
    for (int v = 0; v < 5; ++v) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int l : row_vectors(v)) sum += B(v, l) * nodes.col(l);
      u.template segment<3>(3 * v) = sum;
    }
    U += t.weight[g] * ancf_section_energy(t.moment, t.law, u, gradient, K != nullptr ? &hessian : nullptr);
    // Q = ∫ (B ⊗ I₃)ᵀ ∂W̄/∂u dx (eq. A16).
    for (int v = 0; v < 5; ++v)
      for (int l : row_vectors(v)) force.col(l) += t.weight[g] * B(v, l) * gradient.template segment<3>(3 * v);
    if (K == nullptr) continue;
    // K = ∫ (B ⊗ I₃)ᵀ ∂²W̄/∂u² (B ⊗ I₃) dx block by block, skipping B's zeros (each variable
    // touches 2 to 4 of the n node vectors).
    for (int v = 0; v < 5; ++v)
      for (int l = 0; l < n; ++l) {
        HB[v][l].setZero();
        for (int w = 0; w < 5; ++w)
          if (B(w, l) != 0.0) HB[v][l].noalias() += B(w, l) * hessian.template block<3, 3>(3 * v, 3 * w);
      }
    for (int k = 0; k < n; ++k)
      for (int v = 0; v < 5; ++v) {
        if (B(v, k) == 0.0) continue;
        const double c = t.weight[g] * B(v, k);
        for (int l = k; l < n; ++l) K->template block<3, 3>(3 * k, 3 * l).noalias() += c * HB[v][l];
      }
  }
  if (K != nullptr)
    for (int k = 0; k < n; ++k)
      for (int l = k + 1; l < n; ++l) K->template block<3, 3>(3 * l, 3 * k) = K->template block<3, 3>(3 * k, 3 * l).transpose();
  return U;
}

template <int transverse>
typename AncfBeamElement<transverse>::Matrix AncfBeamElement<transverse>::mass_matrix() const {
  Matrix M = Matrix::Zero();
  for (int k = 0; k < Tables::n; ++k)
    for (int l = 0; l < Tables::n; ++l)
      M.template block<3, 3>(3 * k, 3 * l) = tables_->scalar_mass(k, l) * Matrix3::Identity();
  return M;
}

template <int transverse>
void AncfBeamElement<transverse>::compute(const ElementInput& in, const ElementRequest& request,
                                          ElementOutput& out) const {
  const Tables& t = *tables_;
  const Vector e = coordinates(*in.q);
  Vector Q;
  Matrix K;
  const double U = elastic_force(e, Q, request.stiffness ? &K : nullptr);
  // Weight f_g = ∫ ρ Sᵀ g dV = w ⊗ g, scaled by the load factor.
  Vector weight;
  for (int k = 0; k < Tables::n; ++k)
    weight.template segment<3>(3 * k) = in.load_factor * t.gravity_weights(k) * in.gravity;
  if (request.residual) out.residual += Q - weight;
  if (request.stiffness) out.stiffness += K;
  // The strain energy comes with the force and the gravity potential costs one dot product: both
  // are always filled; the kinetic energy, which needs the velocities, only on request (as the
  // other elements do).
  out.energy.strain = U;
  out.energy.gravity = -weight.dot(e);
  if (!in.dynamic()) return;
  // Constant mass matrix M = m ⊗ I₃: M v̇ is m applied to the 3 × n node vectors, no velocity
  // terms (001 eq. 8).
  const auto times_mass = [&](const Vector& x) {
    Vector y;
    Eigen::Map<Eigen::Matrix<double, 3, Tables::n>>(y.data()).noalias() =
        Eigen::Map<const Eigen::Matrix<double, 3, Tables::n>>(x.data()).lazyProduct(t.scalar_mass);
    return y;
  };
  if (request.residual) {
    Vector a;
    gather(*in.q, blocks_, *in.acceleration, a);
    out.residual += times_mass(a);
  }
  if (request.energy) {
    Vector v;
    gather(*in.q, blocks_, *in.velocity, v);
    out.energy.kinetic = 0.5 * v.dot(times_mass(v));
  }
  if (request.mass) out.mass += mass_matrix();
}

template class AncfBeamElement<2>;
template class AncfBeamElement<3>;

}  // namespace spar::core
