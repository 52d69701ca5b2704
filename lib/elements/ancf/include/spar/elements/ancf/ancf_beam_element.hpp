#pragma once
/// \file
/// Fully parameterized three-dimensional ANCF beam elements (Shabana & Yakoub; 001 §2 and §5;
/// docs/ancf.md). The position of a material point (x along the reference line, y and z in the
/// section) is r(x, y, z) = r₀(x) + y r_y(x) + z r_z(x) (001 eqs. 5, 24, 56):
///   - r₀ cubic Hermite in the nodal r and r_x,
///   - r_y, r_z interpolated from their nodal values: linearly in the 24-coordinate element
///     (001 eq. 5), quadratically in the 30-coordinate element of 001 eqs. (52)–(57), whose six
///     extra coordinates (the x²y and x²z terms) are the element's own vector block.
/// Each node is a vector block of 12 coordinates (r, r_x, r_y, r_z). The reference configuration
/// must be straight and undistorted (r_x, r_y, r_z orthonormal), so F = ∂r/∂(x, y, z) is the
/// deformation gradient and E = ½(FᵀF − I) the Green–Lagrange strain.
///
/// Material: St. Venant–Kirchhoff, S = λ tr(E) I + 2μ E, optionally with a shear correction factor
/// k on the transverse shear stresses (S_xy = 2kμ E_xy, S_xz = 2kμ E_xz) and a Poisson locking
/// remedy (AncfLockingRemedy). The elastic force and its Jacobian come from method II (default: section
/// resultants of the first Piola–Kirchhoff stress P = F S, Gerstmayr & Shabana 2005, 001 eqs.
/// 38–51; docs/ancf.md eqs. A12–A16) or method I (invariant tensors, García-Vallejo et al. 2004,
/// 001 eqs. 31–37; eqs. A17–A20). Both integrate the section in closed form through its moments
/// of order ≤ 4 (core/section_integrals.hpp) and the axis by five-point Gauss (exact: the
/// integrands are polynomials of degree ≤ 8 in x), so they agree to round-off. Mass matrix and
/// gravity are constant (001 eq. 8).

#include <spar/core/cross_section.hpp>
#include <spar/core/element.hpp>
#include <spar/core/section_integrals.hpp>

#include <Eigen/Core>

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace spar::core {

/// How the elastic force and its Jacobian are computed; both give the same numbers to round-off.
enum class AncfForceMethod {
  /// Method I (García-Vallejo et al. 2004; 001 eqs. 31–37): U = U₀ + ½eᵀK₁e + ¼τ(e, e, e, e) with
  /// the constant matrix K₁ and the invariant tensor τ precomputed per element geometry;
  /// Q = (K₁ + K₂(e)) e, K₂(e)_ij = eᵀC_ij e (docs/ancf.md eqs. A17–A20).
  invariant,
  /// Method II (Gerstmayr & Shabana 2005, Liu, Tian & Hu 2010; 001 eqs. 38–51): section
  /// resultants of the first Piola–Kirchhoff stress at each axial point (eqs. A13–A16).
  gerstmayr,
};

/// A named remedy for Poisson locking (docs/ancf.md §6). `none` is the element of paper 001.
enum class AncfLockingRemedy {
  none,
  /// The part of the axial strain that varies across the section (bending) is taken in uniaxial
  /// stress: W̄ − c ∫ (E_xx − Ē_xx)² dA with c = (λ + 2μ − E)/2 and Ē_xx the section average, so
  /// bending sees E instead of λ + 2μ while the section-averaged strain keeps the full 3D law
  /// (docs/ancf.md eq. A21). Zero change at ν = 0.
  uniaxial_bending,
};

/// The section law (docs/ancf.md eqs. A2–A4, A21, A22): St. Venant–Kirchhoff with Lamé λ and μ,
/// the transverse shear stresses scaled by the shear correction factor k (S_xy = 2kμ E_xy,
/// S_xz = 2kμ E_xz; k = 1 is the plain law) and the locking remedy's c (0 without it).
struct AncfSectionLaw {
  double lambda = 0.0;              ///< Lamé λ = Eν/((1 + ν)(1 − 2ν))
  double mu = 0.0;                  ///< Lamé μ = E/(2(1 + ν))
  double shear_factor = 1.0;        ///< k (eq. A22)
  double poisson_correction = 0.0;  ///< c = (λ + 2μ − E)/2 with the uniaxial_bending remedy (eq. A21)
};

/// Throws spar::Error unless the shear correction factor k is finite with 0 < k ≤ 1 (docs/ancf.md
/// §7: k ≤ 1 for every energy-equivalent factor; a value above 1 is the reciprocal form factor).
void check_ancf_shear_factor(double shear_factor, const char* where);

/// Shape functions of the element with `transverse` functions per transverse gradient (2: the
/// 24-coordinate element, 3: the 30-coordinate element). Coordinates are grouped in 3-vectors
/// ("node vectors"), in the element's block order:
///   0 r_A, 1 r_x,A, 2 r_y,A, 3 r_z,A, 4 r_B, 5 r_x,B, 6 r_y,B, 7 r_z,B[, 8 d_y, 9 d_z].
template <int transverse>
struct AncfShapeFunctions {
  static_assert(transverse == 2 || transverse == 3);
  static constexpr int node_vectors = 4 + 2 * transverse;
  static constexpr int dofs = 3 * node_vectors;
  /// Node vectors interpolated by the Hermite functions (r₀), by the transverse functions (r_y
  /// and r_z).
  static constexpr std::array<int, 4> axial_vectors{0, 1, 4, 5};
  static constexpr std::array<int, transverse> y_vectors = [] {
    if constexpr (transverse == 2) return std::array<int, 2>{2, 6};
    else return std::array<int, 3>{2, 6, 8};
  }();
  static constexpr std::array<int, transverse> z_vectors = [] {
    if constexpr (transverse == 2) return std::array<int, 2>{3, 7};
    else return std::array<int, 3>{3, 7, 9};
  }();

  /// Hermite functions S1, S2, S5, S6 (001 eq. 5) at ξ = x/l and their x-derivatives.
  static std::array<double, 4> axial(double xi, double length);
  static std::array<double, 4> axial_derivative(double xi, double length);
  /// Transverse functions: (1 − ξ, ξ) (001 eq. 5: S3 = l(η − ξη) = y(1 − ξ), S7 = y ξ) or
  /// (1 − ξ², ξ², l(ξ − ξ²)) (001 eq. 55: S3 = l(1 − ξ²)η, S7 = lξ²η, S9 = l²(ξ − ξ²)η), and
  /// their x-derivatives.
  static std::array<double, transverse> transverse_values(double xi, double length);
  static std::array<double, transverse> transverse_derivative(double xi, double length);
};

/// The constant data of one element geometry (length, material, section), shared by all elements
/// that have it: axial quadrature with the shape functions at its points, the section's moment
/// tensor, the scalar mass matrix and the gravity weights.
template <int transverse>
struct AncfElementTables {
  using Shape = AncfShapeFunctions<transverse>;
  static constexpr int n = Shape::node_vectors;
  static constexpr int points = 5;  ///< axial Gauss points: exact for the degree-8 integrands

  AncfElementTables(double length, const Material& material, const SectionIntegrals& section,
                    AncfForceMethod method = AncfForceMethod::gerstmayr,
                    AncfLockingRemedy remedy = AncfLockingRemedy::none, double shear_factor = 1.0);

  AncfForceMethod method;
  double length;
  AncfSectionLaw law;
  double density;
  /// M[p][q][i][j] = ∫ φ_p φ_q φ_i φ_j dA with φ = (1, y, z) (docs/ancf.md eq. A12).
  double moment[3][3][3][3];
  std::array<double, points> weight;  ///< Gauss weight × l
  /// Per Gauss point: the coefficients B (5 × n) of the node vectors in u = (a, b, c, g, h) =
  /// (r₀′, r_y′, r_z′, r_y, r_z), so that F = [a + y b + z c, g, h] and u = (B ⊗ I₃) e
  /// (docs/ancf.md eq. A7).
  std::array<Eigen::Matrix<double, 5, n>, points> coefficients;
  /// Scalar mass matrix m (M = m ⊗ I₃, docs/ancf.md eq. A5) and gravity weights w (f_g = w ⊗ g),
  /// both with the density.
  Eigen::Matrix<double, n, n> scalar_mass;
  Eigen::Matrix<double, n, 1> gravity_weights;
  /// Method I only (empty otherwise): U₀ = (9λ/8 + 3μ/4) A l, the scalar K₁ (K₁ = κ₁ ⊗ I₃) and
  /// τ_abcd (n² × n², row a + n b, column c + n d), the invariant tensor on node vectors:
  /// ¼ τ(e, e, e, e) = ¼ Σ τ_abcd (e_a · e_b)(e_c · e_d) (docs/ancf.md eqs. A17–A18, with the
  /// shear factor eq. A24).
  double invariant_constant = 0.0;
  Eigen::Matrix<double, n, n> invariant_linear;
  Eigen::MatrixXd invariant_quartic;
  /// τ on the symmetric pairs: Γ and κ₂ are symmetric and τ_abcd = τ_bacd = τ_abdc, so
  /// κ₂_ab = Σ_{c≤d} (2 − δ_cd) τ_abcd Γ_cd for a ≤ b; row and column k are the pair
  /// (pair_first[k], pair_second[k]), the column's factor 2 − δ_cd included. The force's product
  /// then costs (n(n+1)/2)² multiply-adds instead of n⁴ (1296 instead of 4096 for 24 coordinates).
  static constexpr int pairs = n * (n + 1) / 2;
  static constexpr std::array<int, pairs> pair_first = [] {
    std::array<int, pairs> first{};
    for (int a = 0, k = 0; a < n; ++a)
      for (int b = a; b < n; ++b) first[k++] = a;
    return first;
  }();
  static constexpr std::array<int, pairs> pair_second = [] {
    std::array<int, pairs> second{};
    for (int a = 0, k = 0; a < n; ++a)
      for (int b = a; b < n; ++b) second[k++] = b;
    return second;
  }();
  Eigen::MatrixXd invariant_quartic_pairs;

private:
  void compute_invariants();
};

/// The section-integrated strain energy density W̄ = ∫ W dA of a SVK material at one axial point,
/// its gradient with respect to u = (a, b, c, g, h) (the section resultants of P, docs/ancf.md
/// eq. A14) and, if `hessian` is not null, its Hessian (eq. A15; with the shear factor eq. A23).
/// Allocation-free.
double ancf_section_energy(const double (&moment)[3][3][3][3], const AncfSectionLaw& law,
                           const Eigen::Matrix<double, 15, 1>& u, Eigen::Matrix<double, 15, 1>& gradient,
                           Eigen::Matrix<double, 15, 15>* hessian);

template <int transverse>
class AncfBeamElement final : public Element {
public:
  using Shape = AncfShapeFunctions<transverse>;
  using Tables = AncfElementTables<transverse>;
  static constexpr int dofs = Shape::dofs;
  using Vector = Eigen::Matrix<double, dofs, 1>;
  using Matrix = Eigen::Matrix<double, dofs, dofs>;

  /// `blocks`: node A (12), node B (12)[, the element's own block of 6]. Throws spar::Error for
  /// blocks of the wrong size or a reference configuration q0 that is not straight and undistorted
  /// with the tables' length.
  AncfBeamElement(std::vector<int> blocks, std::shared_ptr<const Tables> tables,
                  const Configuration& q0, int index);

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override;

  const Tables& tables() const { return *tables_; }
  /// U(e) = ∫ W̄ dx.
  double strain_energy(const Vector& e) const;
  /// Q = ∂U/∂e and, if K is not null, K = ∂Q/∂e, by the tables' method (method II: 001 eqs. 44
  /// and 51; method I: eqs. 36–37); returns U. Allocation-free.
  double elastic_force(const Vector& e, Vector& Q, Matrix* K) const;
  /// The constant mass matrix ∫ ρ Sᵀ S dV.
  Matrix mass_matrix() const;
  /// The element coordinates e from the configuration.
  Vector coordinates(const Configuration& q) const;

private:
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
  double gerstmayr_force(const Vector& e, Vector& Q, Matrix* K) const;
  /// The node vectors that row v of Tables::coefficients touches.
  static std::span<const int> row_vectors(int v);
  double invariant_force(const Vector& e, Vector& Q, Matrix* K) const;

  std::vector<int> blocks_;
  std::shared_ptr<const Tables> tables_;
  int index_;
};

using AncfBeam24Element = AncfBeamElement<2>;
using AncfBeam30Element = AncfBeamElement<3>;

extern template struct AncfShapeFunctions<2>;
extern template struct AncfShapeFunctions<3>;
extern template struct AncfElementTables<2>;
extern template struct AncfElementTables<3>;
extern template class AncfBeamElement<2>;
extern template class AncfBeamElement<3>;

}  // namespace spar::core
