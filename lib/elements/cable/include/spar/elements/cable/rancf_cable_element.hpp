#pragma once
/// \file
/// The RANCF cable element and its variable-length ALE-RANCF form (paper 000, Ding & Ouyang,
/// Machines 2022, 10, 174, §§2–3; docs/rancf.md).
///
/// Nodal coordinates e = [r_A, r_x^A, r_B, r_x^B] (000 eq. (4)) live in two vector blocks per
/// node, [r, r_x] with 2·Dim entries (Dim = 2: the X–Y plane, gravity's first two components;
/// Dim = 3). The element is a rational cubic Bézier in u ∈ [0, 1] with constant weights w0…w3
/// (000 eq. (9)); with equal weights it is the plain ANCF cable (000 eq. (10)).
///
/// - RancfCableElement: fixed reference length l, material coordinate x = u l; constant mass
///   matrix; local order [node A, node B].
/// - AleRancfCableElement: the material coordinates x_A, x_B of its end nodes are generalized
///   coordinates, each a scalar vector block (000 eq. (11)); u = (x − x_A)/(x_B − x_A) (000
///   eq. (13)); configuration-dependent mass matrix and quadratic-velocity forces; local order
///   [node A, node B, x_A, x_B]. With unit weights it is the ALE-ANCF element.
///
/// Both: axial strain ε = (r_xᵀ r_x − 1)/2 and curvature κ = |r_x × r_xx|/|r_x|³ (000 eq. (19))
/// with energy ∫ (EA ε² + EI κ²)/2 dx and Kelvin–Voigt damping (000 eq. (17)), gravity ρA g, all
/// by Gauss–Legendre quadrature in u. Stiffness and damping are exact: the residual is
/// evaluated with dual numbers (core/dual.hpp). A planar cable may have a curved stress-free
/// shape (RancfCableParameters::reference, elements/cable/cable_reference.hpp): ε − ε₀(x), κ − κ₀(x).

#include <spar/elements/cable/cable_reference.hpp>
#include <spar/core/element.hpp>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace spar::core {

namespace rancf {
/// One Gauss point on u ∈ [0, 1]: u, its weight, and the shape functions with their first
/// three u-derivatives (iga::rancf_shape_function_derivatives: s_2 and s_4 divided by l).
struct QuadraturePoint {
  double u = 0.0;
  double weight = 0.0;
  Eigen::Matrix<double, 4, 4> s;
};
}  // namespace rancf

/// Section properties of a cable (Euler–Bernoulli, no shear, no torsion).
struct RancfSection {
  double axial_stiffness = 0.0;    ///< EA (N)
  double bending_stiffness = 0.0;  ///< EI (N m²)
  double mass_per_length = 0.0;    ///< ρA (kg/m)
  /// Kelvin–Voigt coefficient c (s): axial force EA (ε + c ε̇), moment EI (κ + c κ̇) (000 eq. (17)).
  double damping_coefficient = 0.0;

  /// A solid circular rod of `radius` (m), Young's modulus E (Pa) and density ρ (kg/m³):
  /// A = πr², I = A r²/4, so EA, EI = E A r²/4 and ρA (000 §6: r = 0.01 or 0.02 m, E = 20 or
  /// 200 MPa, ρ = 7200 kg/m³). Undamped.
  static RancfSection circular(double radius, double young_modulus, double density);
};

/// What a RANCF or ALE-RANCF element is built from.
struct RancfCableParameters {
  int node_a = -1;  ///< vector block [r_A, r_x^A] (2·Dim entries)
  int node_b = -1;  ///< vector block [r_B, r_x^B]
  /// Fixed-length element: its reference length l > 0 (unused by the ALE element).
  double length = 0.0;
  /// ALE element: the scalar vector blocks holding x_A and x_B (unused by the fixed element).
  int material_a = -1;
  int material_b = -1;
  RancfSection section;
  Eigen::Vector4d weights = Eigen::Vector4d::Ones();  ///< w0…w3 > 0 (000 eq. (9))
  int quadrature_points = 5;                           ///< Gauss points in u, 2 … 16
  std::string name = "RANCF cable";
  /// The stress-free curved shape of a planar cable (Dim = 2 only): its strains ε₀(x), κ₀(x) are
  /// subtracted from ε and κ at the Gauss points' material coordinates. Null: straight and
  /// unstretched, 000's strains as written.
  std::shared_ptr<const CableReference> reference;
  /// Fixed-length element with a reference: the material coordinate of node A (x = x_A + u l).
  double material_start = 0.0;
};

/// What the fixed-length and the ALE element share: their parameters, blocks and quadrature table,
/// checked and built once, and the Element answers that follow from them.
class RancfCableBase : public Element {
public:
  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return parameters_.name; }
  /// Damped (RancfSection::damping_coefficient > 0): the Kelvin–Voigt force is its dissipative force.
  bool has_dissipation() const override { return parameters_.section.damping_coefficient > 0.0; }
  const RancfCableParameters& parameters() const { return parameters_; }

protected:
  /// Checks `parameters` for the ALE element (`ale`: four blocks, the material coordinates' too)
  /// or the fixed-length one (two) in `dim` dimensions, naming `where` in its errors, and builds
  /// the quadrature table.
  RancfCableBase(const RancfCableParameters& parameters, int dim, bool ale, const char* where);
  RancfCableParameters parameters_;
  std::vector<int> blocks_;
  std::vector<rancf::QuadraturePoint> table_;
};

template <int Dim>
class RancfCableElement final : public RancfCableBase {
public:
  static_assert(Dim == 2 || Dim == 3, "RANCF cables are planar or spatial");
  /// Throws spar::Error for non-positive length, weights or section values, missing blocks or a
  /// quadrature outside 2 … 16 points.
  explicit RancfCableElement(const RancfCableParameters& parameters);

private:
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
  std::vector<ReferenceStrain<double>> reference_table_;  ///< ε₀, κ₀ at the Gauss points, or empty
  /// The constant 4×4 mass matrix m of the shape functions: M = m ⊗ I_Dim (000 eq. (19)).
  Eigen::Matrix4d shape_mass_;
};

template <int Dim>
class AleRancfCableElement final : public RancfCableBase {
public:
  static_assert(Dim == 2 || Dim == 3, "RANCF cables are planar or spatial");
  /// Throws spar::Error as RancfCableElement, and for material blocks that are not scalars.
  explicit AleRancfCableElement(const RancfCableParameters& parameters);

private:
  /// Throws spar::Error when x_B ≤ x_A (an element turned inside out).
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
};

extern template class RancfCableElement<2>;
extern template class RancfCableElement<3>;
extern template class AleRancfCableElement<2>;
extern template class AleRancfCableElement<3>;

}  // namespace spar::core
