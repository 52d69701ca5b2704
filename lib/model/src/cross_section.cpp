#include <spar/core/cross_section.hpp>
#include <spar/error.hpp>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <string>

namespace spar::core {

namespace {

void require_positive(double value, const char* name, const char* where) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw Error(std::string(name) + " must be positive and finite, got " + significant(value),
                where, std::string("give a positive ") + name);
}

/// An isotropic material's Poisson ratio lies in (−1, 0.5); NaN is refused too (it made the
/// shear coefficients of a section NaN without a word).
void require_poisson_ratio(double poisson_ratio, const char* where) {
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    throw Error("Poisson's ratio must lie in (-1, 0.5), got " + significant(poisson_ratio), where,
                "give an isotropic material's Poisson ratio");
}

}  // namespace

void Material::validate() const {
  require_positive(young_modulus, "Young's modulus", "core::Material");
  require_poisson_ratio(poisson_ratio, "core::Material");
  if (!(density >= 0.0) || !std::isfinite(density))
    throw Error("density must be non-negative, got " + std::to_string(density), "core::Material",
                "give the mass density in kg/m^3");
}

void CrossSection::validate() const {
  const char* where = "core::CrossSection";
  require_positive(area, "area", where);
  require_positive(second_moment_2, "second moment I2", where);
  require_positive(second_moment_3, "second moment I3", where);
  require_positive(torsion_constant, "torsion constant J", where);
  require_positive(shear_coefficient_2, "shear coefficient tau2", where);
  require_positive(shear_coefficient_3, "shear coefficient tau3", where);
  if (!(second_moment_2 * second_moment_3 > product_moment * product_moment))
    throw Error("the second-moment tensor is not positive definite (I2 I3 <= I23^2)", where,
                "check I2, I3 and the product moment I23");
}

// Saint-Venant torsion constant of a b × h rectangle (b ≥ h):
// J = (b h³/3) [1 − (192/π⁵)(h/b) Σ_{n odd} tanh(nπb/(2h))/n⁵] (Timoshenko & Goodier, §109).
CrossSection CrossSection::rectangle(double width, double height, double poisson_ratio) {
  require_positive(width, "width", "core::CrossSection::rectangle");
  require_positive(height, "height", "core::CrossSection::rectangle");
  require_poisson_ratio(poisson_ratio, "core::CrossSection::rectangle");
  const double b = std::max(width, height), h = std::min(width, height);
  const double pi = std::numbers::pi;
  double series = 0.0;
  for (int n = 1; n < 200; n += 2) series += std::tanh(n * pi * b / (2.0 * h)) / std::pow(n, 5);
  CrossSection section;
  section.area = width * height;
  section.second_moment_2 = width * height * height * height / 12.0;
  section.second_moment_3 = height * width * width * width / 12.0;
  section.torsion_constant = b * h * h * h / 3.0 * (1.0 - 192.0 / std::pow(pi, 5) * (h / b) * series);
  section.shear_coefficient_2 = section.shear_coefficient_3 =
      10.0 * (1.0 + poisson_ratio) / (12.0 + 11.0 * poisson_ratio);
  return section;
}

CrossSection CrossSection::circle(double diameter, double poisson_ratio) {
  return tube(diameter, 0.0, poisson_ratio);
}

// Cowper (1966), hollow circle: τ = 6(1 + ν)(1 + m²)² / ((7 + 6ν)(1 + m²)² + (20 + 12ν) m²),
// m = inner/outer diameter; m = 0 gives the solid circle's 6(1 + ν)/(7 + 6ν).
CrossSection CrossSection::tube(double outer_diameter, double inner_diameter, double poisson_ratio) {
  require_positive(outer_diameter, "outer diameter", "core::CrossSection::tube");
  require_poisson_ratio(poisson_ratio, "core::CrossSection::tube");
  if (!(inner_diameter >= 0.0 && inner_diameter < outer_diameter))
    throw Error("inner diameter must lie in [0, outer diameter)", "core::CrossSection::tube",
                "give inner < outer, or 0 for a solid circle");
  const double pi = std::numbers::pi;
  const double ro = outer_diameter / 2.0, ri = inner_diameter / 2.0;
  const double m = ri / ro, m2 = m * m;
  CrossSection section;
  section.area = pi * (ro * ro - ri * ri);
  section.second_moment_2 = section.second_moment_3 = pi / 4.0 * (std::pow(ro, 4) - std::pow(ri, 4));
  section.torsion_constant = section.polar_moment();
  const double nu = poisson_ratio;
  section.shear_coefficient_2 = section.shear_coefficient_3 =
      6.0 * (1.0 + nu) * (1.0 + m2) * (1.0 + m2) /
      ((7.0 + 6.0 * nu) * (1.0 + m2) * (1.0 + m2) + (20.0 + 12.0 * nu) * m2);
  return section;
}

SectionStiffness SectionStiffness::from(const Material& material, const CrossSection& section) {
  material.validate();
  section.validate();
  const double E = material.young_modulus, G = material.shear_modulus();
  SectionStiffness C;
  C.axial = E * section.area;
  C.shear_2 = section.shear_coefficient_2 * G * section.area;
  C.shear_3 = section.shear_coefficient_3 * G * section.area;
  C.torsion = G * section.torsion_constant;
  C.bending_2 = E * section.second_moment_2;
  C.bending_3 = E * section.second_moment_3;
  C.bending_23 = E * section.product_moment;
  return C;
}

Eigen::Matrix<double, 6, 6> SectionStiffness::matrix() const {
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  C.diagonal() << axial, shear_2, shear_3, torsion, bending_2, bending_3;
  C(4, 5) = C(5, 4) = -bending_23;
  return C;
}

void SectionStiffness::validate() const {
  const char* where = "core::SectionStiffness";
  require_positive(axial, "axial stiffness EA", where);
  require_positive(shear_2, "shear stiffness GA2", where);
  require_positive(shear_3, "shear stiffness GA3", where);
  require_positive(torsion, "torsional stiffness GJ", where);
  require_positive(bending_2, "bending stiffness EI2", where);
  require_positive(bending_3, "bending stiffness EI3", where);
  if (!(bending_2 * bending_3 > bending_23 * bending_23))
    throw Error("the bending block is not positive definite (EI2 EI3 <= EI23^2)", where,
                "check EI2, EI3 and the coupling EI23");
}

SectionInertia SectionInertia::from(const Material& material, const CrossSection& section) {
  material.validate();
  section.validate();
  const double rho = material.density;
  SectionInertia inertia;
  inertia.mass_per_length = rho * section.area;
  inertia.rotary << section.polar_moment(), 0.0, 0.0,  //
      0.0, section.second_moment_2, -section.product_moment,   //
      0.0, -section.product_moment, section.second_moment_3;
  inertia.rotary *= rho;
  return inertia;
}

void SectionInertia::validate() const {
  const char* where = "core::SectionInertia";
  if (!(mass_per_length >= 0.0) || !std::isfinite(mass_per_length))
    throw Error("mass per length must be non-negative, got " + std::to_string(mass_per_length),
                where, "give rho*A in kg/m (0 for a massless beam)");
  if (!rotary.allFinite() || (rotary - rotary.transpose()).norm() > 1e-12 * rotary.norm() ||
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(rotary).eigenvalues().minCoeff() <
          -1e-12 * rotary.norm())
    throw Error("the rotary inertia is not symmetric positive semi-definite", where,
                "give rho*J of the section (SectionInertia::from)");
}

}  // namespace spar::core
