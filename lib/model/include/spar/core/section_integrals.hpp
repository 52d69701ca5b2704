#pragma once
/// \file
/// The integrals of a beam cross-section that the ANCF beam elements need (docs/ancf.md §3).
///
/// Section coordinates (y, z) are measured from the element's reference line (the line the nodal
/// positions r follow), along the reference directions r_y and r_z. The element's mass matrix
/// needs the moments of order ≤ 2, its strain energy those of order ≤ 4: the Green–Lagrange strain
/// is quadratic in (y, z) and the energy density quadratic in the strain (001 eqs. 33–35 and
/// 46–48, before the paper drops the odd and the fourth-order integrals). Nothing else of the
/// section's shape enters, so a section is any set of these fifteen numbers.

#include <Eigen/Core>

#include <array>
#include <vector>

namespace spar::core {

/// moment(a, b) = ∫ y^a z^b dA for a + b ≤ 4 (docs/ancf.md eq. A9).
class SectionIntegrals {
public:
  static constexpr int max_order = 4;

  /// ∫ y^a z^b dA; throws spar::Error unless a, b ≥ 0 and a + b ≤ 4.
  double moment(int a, int b) const;
  double area() const { return moments_[0][0]; }
  /// I_y = ∫ z² dA (bending about y), I_z = ∫ y² dA (bending about z), I_yz = ∫ y z dA, all
  /// about the reference line.
  double second_moment_y() const { return moments_[0][2]; }
  double second_moment_z() const { return moments_[2][0]; }
  double product_moment() const { return moments_[1][1]; }

  using Moments = std::array<std::array<double, max_order + 1>, max_order + 1>;

  /// A section given by its integrals: m[a][b] = ∫ y^a z^b dA for a + b ≤ 4 (entries with
  /// a + b > 4 must be zero). Throws spar::Error for a non-positive area, a non-finite entry or a
  /// non-zero entry beyond order 4.
  static SectionIntegrals from_moments(const Moments& m);
  /// The paper's simplification (001 eq. 47): only A, I_y, I_z and I_yz, every odd and every
  /// fourth-order integral set to zero ("small symmetric section").
  static SectionIntegrals second_order(double area, double second_moment_y, double second_moment_z,
                                       double product_moment = 0.0);
  /// A solid circle of the given radius centred at `center`.
  static SectionIntegrals circle(double radius, const Eigen::Vector2d& center = Eigen::Vector2d::Zero());
  /// A solid rectangle, `width` along y and `height` along z, centred at `center`.
  static SectionIntegrals rectangle(double width, double height,
                                    const Eigen::Vector2d& center = Eigen::Vector2d::Zero());
  /// A simple polygon (vertices (y, z) counter-clockwise, not repeated at the end), integrated
  /// exactly by Green's theorem edge by edge (docs/ancf.md eq. A10).
  static SectionIntegrals polygon(const std::vector<Eigen::Vector2d>& vertices);

  /// The union of two disjoint sections (moments add).
  SectionIntegrals operator+(const SectionIntegrals& other) const;
  /// These integrals with every fourth-order and odd moment dropped: second_order(A, I_y, I_z, I_yz).
  SectionIntegrals truncated_to_second_order() const;

private:
  /// Throws spar::Error for a non-positive area or a non-finite moment.
  void validate(const char* where) const;

  Moments moments_{};
};

}  // namespace spar::core
