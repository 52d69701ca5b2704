/// The ANCF beam element's tables: its shape functions and the invariant matrices of the section
/// integrals, computed once per element length (docs/ancf.md).
#include <spar/elements/ancf/ancf_beam_element.hpp>

#include "ancf_variables.hpp"

#include <spar/error.hpp>
#include <spar/iga/quadrature.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <span>
#include <utility>

namespace spar::core {

using detail::transverse_shear;
using detail::variable_column;
using detail::variable_phi;

void check_ancf_shear_factor(double shear_factor, const char* where) {
  // k = (∫τ dA)²/(A ∫τ² dA) for the energy-equivalent factors (Timoshenko's, Cowper's), ≤ 1 by
  // Cauchy–Schwarz; its reciprocal, the shear form factor A/A_s ≥ 1 (6/5 for a rectangle), is
  // the likely mix-up above 1 (docs/ancf.md §7).
  if (!(shear_factor > 0.0 && shear_factor <= 1.0))
    throw Error("the shear correction factor is " + significant(shear_factor), where,
                "give 0 < k <= 1 (1: no correction, 5/6 for a rectangle); a form factor A/A_s >= 1 is 1/k");
}

// Shape functions -------------------------------------------------------------------------------

template <int transverse>
std::array<double, 4> AncfShapeFunctions<transverse>::axial(double xi, double l) {
  // 001 eq. (5): S1, S2, S5, S6.
  const double x2 = xi * xi, x3 = x2 * xi;
  return {1 - 3 * x2 + 2 * x3, l * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, l * (x3 - x2)};
}

template <int transverse>
std::array<double, 4> AncfShapeFunctions<transverse>::axial_derivative(double xi, double l) {
  const double x2 = xi * xi;
  return {6 * (x2 - xi) / l, 1 - 4 * xi + 3 * x2, 6 * (xi - x2) / l, 3 * x2 - 2 * xi};
}

template <int transverse>
std::array<double, transverse> AncfShapeFunctions<transverse>::transverse_values(double xi, double l) {
  if constexpr (transverse == 2) {
    (void)l;
    return {1 - xi, xi};  // 001 eq. (5)
  } else {
    return {1 - xi * xi, xi * xi, l * (xi - xi * xi)};  // 001 eq. (55)
  }
}

template <int transverse>
std::array<double, transverse> AncfShapeFunctions<transverse>::transverse_derivative(double xi, double l) {
  if constexpr (transverse == 2) {
    return {-1 / l, 1 / l};
  } else {
    return {-2 * xi / l, 2 * xi / l, 1 - 2 * xi};
  }
}

// Tables ----------------------------------------------------------------------------------------

template <int transverse>
AncfElementTables<transverse>::AncfElementTables(double length_, const Material& material,
                                                 const SectionIntegrals& section, AncfForceMethod method_,
                                                 AncfLockingRemedy remedy, double shear_factor)
    : method(method_), length(length_), density(material.density) {
  material.validate();
  if (!(length > 0.0) || !std::isfinite(length))
    throw Error("the element length is " + std::to_string(length), "core::AncfElementTables",
                "give distinct end nodes");
  check_ancf_shear_factor(shear_factor, "core::AncfElementTables");
  const double E = material.young_modulus, nu = material.poisson_ratio;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  // The remedy's c uses the unscaled moduli: it concerns the normal stresses only, which k leaves
  // alone (docs/ancf.md §7).
  law = {.lambda = lambda,
         .mu = mu,
         .shear_factor = shear_factor,
         .poisson_correction = remedy == AncfLockingRemedy::uniaxial_bending ? (lambda + 2 * mu - E) / 2 : 0.0};
  // M[p][q][i][j] = ∫ φ_p φ_q φ_i φ_j dA, φ = (1, y, z): the moment of y^(#1) z^(#2) (eq. A12).
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const int idx[4] = {p, q, i, j};
          int ay = 0, az = 0;
          for (int k : idx) {
            ay += (k == 1);
            az += (k == 2);
          }
          moment[p][q][i][j] = section.moment(ay, az);
        }

  const iga::GaussRule rule = iga::gauss_legendre(points);
  scalar_mass.setZero();
  gravity_weights.setZero();
  for (int g = 0; g < points; ++g) {
    const double xi = 0.5 * (rule.points[g] + 1);
    weight[g] = 0.5 * rule.weights[g] * length;
    const auto ax = Shape::axial(xi, length), dax = Shape::axial_derivative(xi, length);
    const auto tr = Shape::transverse_values(xi, length), dtr = Shape::transverse_derivative(xi, length);
    Eigen::Matrix<double, 5, n>& B = coefficients[g];
    B.setZero();
    // Position r = Σ_p φ_p r_p(x): r₀ (Hermite), r_y, r_z (transverse functions).
    Eigen::Matrix<double, 3, n> N = Eigen::Matrix<double, 3, n>::Zero();
    for (int k = 0; k < 4; ++k) {
      B(0, Shape::axial_vectors[k]) = dax[k];
      N(0, Shape::axial_vectors[k]) = ax[k];
    }
    for (int k = 0; k < transverse; ++k) {
      B(1, Shape::y_vectors[k]) = dtr[k];
      B(2, Shape::z_vectors[k]) = dtr[k];
      B(3, Shape::y_vectors[k]) = tr[k];
      B(4, Shape::z_vectors[k]) = tr[k];
      N(1, Shape::y_vectors[k]) = tr[k];
      N(2, Shape::z_vectors[k]) = tr[k];
    }
    // m = ρ ∫ Σ_pq M_pq00 N_pᵀ N_q dx, w = ρ ∫ Σ_p M_p000 N_p dx (eq. A5).
    for (int p = 0; p < 3; ++p) {
      gravity_weights += density * weight[g] * moment[p][0][0][0] * N.row(p).transpose();
      for (int q = 0; q < 3; ++q)
        scalar_mass += density * weight[g] * moment[p][q][0][0] * N.row(p).transpose() * N.row(q);
    }
  }
  if (method == AncfForceMethod::invariant) compute_invariants();
}

template <int transverse>
void AncfElementTables<transverse>::compute_invariants() {
  // C_αβ = eᵀ(H_αβ ⊗ I₃)e with H_αβ = Σ_{v∈α, w∈β} φ_v φ_w X_vw, X_vw = sym(B_v B_wᵀ), over the
  // variables v = (a, b, c, g, h) of column α(v) and section function φ_p(v) (eq. A17).
  // K₁ = −(3λ + 2μ)/2 ∫ Σ_α H_αα dV (001 eq. 31, whose minus sign the text lost),
  // τ = ∫ [λ/2 Σ_αβ H_αα ⊗ H_ββ + Σ_αβ μ_αβ H_αβ ⊗ H_αβ] dV (eq. 32 on node vectors, eq. A18) with
  // μ_αβ = kμ for the transverse shear pairs and μ otherwise (eq. A24; U₀ and K₁ keep μ).
  const double lambda = law.lambda, mu = law.mu, poisson_correction = law.poisson_correction;
  invariant_constant = (9 * lambda / 8 + 3 * mu / 4) * moment[0][0][0][0] * length;
  invariant_linear.setZero();
  invariant_quartic = Eigen::MatrixXd::Zero(n * n, n * n);
  Eigen::Matrix<double, n * n, 1> X[5][5];
  for (int g = 0; g < points; ++g) {
    const Eigen::Matrix<double, 5, n>& B = coefficients[g];
    for (int v = 0; v < 5; ++v)
      for (int w = 0; w < 5; ++w) {
        const Eigen::Matrix<double, n, n> x = 0.5 * (B.row(v).transpose() * B.row(w) + B.row(w).transpose() * B.row(v));
        X[v][w] = Eigen::Map<const Eigen::Matrix<double, n * n, 1>>(x.data());
      }
    auto M = [&](int v, int w, int v2, int w2) {
      return moment[variable_phi[v]][variable_phi[w]][variable_phi[v2]][variable_phi[w2]];
    };
    for (int v = 0; v < 5; ++v)
      for (int w = 0; w < 5; ++w) {
        if (variable_column[v] == variable_column[w])
          invariant_linear -= (3 * lambda + 2 * mu) / 2 * weight[g] * moment[variable_phi[v]][variable_phi[w]][0][0] *
                              Eigen::Map<const Eigen::Matrix<double, n, n>>(X[v][w].data());
        for (int v2 = 0; v2 < 5; ++v2)
          for (int w2 = 0; w2 < 5; ++w2) {
            double c = 0.0;
            // λ/2 (Σ_α H_αα) ⊗ (Σ_β H_ββ): both pairs within one column each.
            if (variable_column[v] == variable_column[w] && variable_column[v2] == variable_column[w2]) c += lambda / 2;
            // Σ_αβ μ_αβ H_αβ ⊗ H_αβ: the second pair in the same columns as the first.
            if (variable_column[v] == variable_column[v2] && variable_column[w] == variable_column[w2])
              c += transverse_shear(variable_column[v], variable_column[w]) ? law.shear_factor * mu : mu;
            // The locking remedy's −c ∫ E_xx² dA on the variables a, b, c of column 1 (eq. A21).
            if (v < 3 && w < 3 && v2 < 3 && w2 < 3) c -= poisson_correction;
            if (c != 0.0 && M(v, w, v2, w2) != 0.0)
              invariant_quartic.noalias() += c * weight[g] * M(v, w, v2, w2) * X[v][w] * X[v2][w2].transpose();
          }
      }
    // ... and its + c (∫ E_xx dA)²/A: J = ∫ E_xx² − (∫ E_xx)²/A is purely quartic in e.
    if (poisson_correction != 0.0) {
      Eigen::Matrix<double, n * n, 1> mean = Eigen::Matrix<double, n * n, 1>::Zero();
      for (int v = 0; v < 3; ++v)
        for (int w = 0; w < 3; ++w) mean += moment[v][w][0][0] * X[v][w];
      invariant_quartic.noalias() += poisson_correction * weight[g] / moment[0][0][0][0] * mean * mean.transpose();
    }
  }
  invariant_quartic_pairs.resize(pairs, pairs);
  for (int r = 0; r < pairs; ++r)
    for (int c = 0; c < pairs; ++c) {
      const int cd = pair_first[c] + n * pair_second[c];
      invariant_quartic_pairs(r, c) = (pair_first[c] == pair_second[c] ? 1.0 : 2.0) *
                                      invariant_quartic(pair_first[r] + n * pair_second[r], cd);
    }
}
template struct AncfShapeFunctions<2>;
template struct AncfShapeFunctions<3>;
template struct AncfElementTables<2>;
template struct AncfElementTables<3>;

}  // namespace spar::core
