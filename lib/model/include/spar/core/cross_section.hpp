#pragma once
/// \file
/// Cross sections and materials of beams, and the section stiffness matrix C of 003 eq. (15).
///
/// Section axes: ξ₁ along the beam, ξ₂ and ξ₃ in the section, origin at the centroid. Strains are
/// ε = (γ₁, γ₂, γ₃, κ₁, κ₂, κ₃): extension, two shears, twist, two curvatures (003 eq. 9). The axial
/// strain of a fibre is γ₁ + κ₃ξ₂ − κ₂ξ₃ (003 eq. 12), so curvature κ₂ (about axis 2) is resisted by
/// E∫ξ₃² dA and κ₃ by E∫ξ₂² dA, coupled through −E∫ξ₂ξ₃ dA.

#include <Eigen/Core>

namespace spar::core {

/// An isotropic linear elastic material.
struct Material {
  double young_modulus = 0.0;   ///< E [Pa]
  double poisson_ratio = 0.0;   ///< ν [-], in (−1, 0.5)
  double density = 0.0;         ///< ρ [kg/m³]

  /// G = E / (2(1 + ν)).
  double shear_modulus() const { return young_modulus / (2.0 * (1.0 + poisson_ratio)); }
  /// Throws spar::Error unless E > 0, −1 < ν < 0.5 and ρ ≥ 0.
  void validate() const;
};

/// Geometric properties of a cross section about its centroid.
struct CrossSection {
  double area = 0.0;                 ///< A = ∫ dA
  double second_moment_2 = 0.0;      ///< I₂ = ∫ ξ₃² dA, bending about axis 2 (003: I₃₃)
  double second_moment_3 = 0.0;      ///< I₃ = ∫ ξ₂² dA, bending about axis 3 (003: I₂₂)
  double product_moment = 0.0;       ///< I₂₃ = ∫ ξ₂ ξ₃ dA
  double torsion_constant = 0.0;     ///< J (Saint-Venant); equals I₂ + I₃ for circles and tubes
  double shear_coefficient_2 = 1.0;  ///< τ₂ (shear along ξ₂)
  double shear_coefficient_3 = 1.0;  ///< τ₃ (shear along ξ₃)

  /// Polar moment I₀ = I₂ + I₃ (003 eq. 16), the rotary inertia about the axis per unit density.
  double polar_moment() const { return second_moment_2 + second_moment_3; }
  /// Throws spar::Error unless A, I₂, I₃, J, τ₂, τ₃ are positive and I₂I₃ > I₂₃².
  void validate() const;

  /// A solid rectangle, `width` along ξ₂ and `height` along ξ₃. J from Saint-Venant's series,
  /// τ from Cowper (1966): 10(1 + ν)/(12 + 11ν).
  static CrossSection rectangle(double width, double height, double poisson_ratio);
  /// A solid circle of the given diameter; J = I₀; τ = 6(1 + ν)/(7 + 6ν) (Cowper).
  static CrossSection circle(double diameter, double poisson_ratio);
  /// A circular tube (e.g. the truss's 0.060/0.055 m members); J = I₀; τ from Cowper's hollow
  /// circle formula with m = inner/outer diameter.
  static CrossSection tube(double outer_diameter, double inner_diameter, double poisson_ratio);
};

/// The section stiffness C (6×6) relating (N, M) = C ε (003 eq. 15):
/// diag(EA, τ₂GA, τ₃GA, GJ, EI₂, EI₃) with C₄₅ = C₅₄ = −E I₂₃.
struct SectionStiffness {
  double axial = 0.0;       ///< EA
  double shear_2 = 0.0;     ///< τ₂ G A
  double shear_3 = 0.0;     ///< τ₃ G A
  double torsion = 0.0;     ///< G J
  double bending_2 = 0.0;   ///< E I₂
  double bending_3 = 0.0;   ///< E I₃
  double bending_23 = 0.0;  ///< E I₂₃ (enters C with a minus sign)

  /// The stiffness of a material and a cross section.
  static SectionStiffness from(const Material& material, const CrossSection& section);
  /// The 6×6 matrix C.
  Eigen::Matrix<double, 6, 6> matrix() const;
  /// Throws spar::Error unless every diagonal stiffness is positive and C is positive definite.
  void validate() const;
};

/// The inertia of a section per unit length (003 eqs. 30–31): mass ρA and the rotary inertia
/// tensor in the material frame, ρ [[I₂ + I₃, 0, 0], [0, I₂, −I₂₃], [0, −I₂₃, I₃]] (003's J with
/// its I₃₃ = our I₂ = ∫ξ₃² dA).
struct SectionInertia {
  double mass_per_length = 0.0;                              ///< ρA [kg/m]
  Eigen::Matrix3d rotary = Eigen::Matrix3d::Zero();          ///< ρJ [kg m]

  static SectionInertia from(const Material& material, const CrossSection& section);
  /// Throws spar::Error unless ρA ≥ 0 and the rotary inertia is symmetric positive
  /// semi-definite.
  void validate() const;
};

}  // namespace spar::core
