#pragma once
/// \file
/// The stress-free shape of a curved planar cable as a function of its material coordinate
/// (docs/rancf.md, "Curved cables"; paper 000 §6.3).
///
/// 000's strain measures (eq. (19)) have no reference values: ε = (r_xᵀr_x − 1)/2 and κ vanish only
/// on a straight cable parameterized by arc length. An exact rational arc (000 eq. (43)) is neither
/// straight nor parameterized by arc length — its slope magnitude at the nodes is 2 sin(θ/2)/θ < 1 —
/// so without reference strains the semicircle of 000 §6.3 would start prestressed in bending
/// (EI/R) and axially. Here the reference strains are those of the initial shape:
///   ε₀(x) = (|r₀_x|² − 1)/2,  κ₀(x) = (r₀_x × r₀_xx)/|r₀_x|³   (the signed planar curvature),
/// functions of the material coordinate x. They belong to the material, not to an element: an
/// ALE-RANCF element evaluates them at its Gauss points' current material coordinates
/// x_g = x_A + u_g (x_B − x_A), so a segmentation (exact, 000 eqs. (22)–(28)) leaves the strain
/// energy unchanged and the elements next to a sliding node carry the material's reference with
/// them. The mass stays ρA per unit x: with |r₀_x| ≠ 1 inside an element the mass per unit of
/// length deviates by O(θ²) (0.16 % for θ = π/16) inside each element, and not at all in total
/// (the breakpoints are placed by arc length).
///
/// The shape is given as one rational Bézier piece (degree 1 to 3) per material span
/// [X_i, X_{i+1}], u = (x − X_i)/(X_{i+1} − X_i). Each is raised to a cubic (iga::elevate) and
/// reparameterized (iga::reparameterize) so that consecutive pieces have the same slope r_x at
/// their common node: a RANCF node has one slope. That leaves one free factor for the whole
/// chain, chosen so that the pieces' end speeds are, in least squares of their logarithms, as
/// equal as they can be; a uniform arc then has |r_x| = 2 sin(θ/2)/θ at every node and the
/// weights of 000 eq. (43).

#include <spar/core/dual.hpp>
#include <spar/iga/circular_arc.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace spar::core {

/// The reference strains at a material point and their rates along the material.
template <class T>
struct ReferenceStrain {
  T axial;            ///< ε₀
  T axial_slope;      ///< dε₀/dx
  T curvature;        ///< κ₀ (signed, planar)
  T curvature_slope;  ///< dκ₀/dx
};

class CableReference {
public:
  /// pieces[i] is the shape of the material span [breakpoints[i], breakpoints[i + 1]]. Throws
  /// spar::Error unless the breakpoints increase, there is one piece per span of degree 1 … 3, and
  /// consecutive pieces meet (positions to 1e-9 of the span, tangent directions to 1e-9 rad).
  CableReference(const std::vector<iga::RationalBezier<2>>& pieces, std::vector<double> breakpoints);

  /// The circular arc `arc` cut at the material coordinates `breakpoints` (arc length from its
  /// start, breakpoints.front() = 0, back() = radius · sweep), one exact piece per span (A7.1 for
  /// a sweep below π; 000 eq. (43) once elevated). Throws spar::Error for a span of π or more.
  static CableReference circular_arc(const iga::CircularArc<2>& arc, std::vector<double> breakpoints);
  /// The shape an ALE-ANCF cable (unit weights, 000 eq. (10)) can hold in place of this one: on
  /// each span the cubic Bézier with unit weights through this shape's nodes, its inner control
  /// points a third of the span's material length along the unit tangents there (|r_x| = 1 at the
  /// nodes, the Hermite cubic of an arc-length parameterization). Same breakpoints.
  CableReference polynomial_interpolant() const;

  int elements() const { return static_cast<int>(lengths_.size()); }
  const std::vector<double>& breakpoints() const { return breakpoints_; }
  /// The node [r, r_x] at breakpoint i (000 eq. (4)).
  Eigen::Vector4d node(int i) const { return nodes_[i]; }
  /// The RANCF weights w0 … w3 of span k (000 eq. (9)), w0 = 1.
  const Eigen::Vector4d& weights(int k) const { return weights_[k]; }

  /// ε₀, κ₀ and their x-derivatives at the material coordinate x (T = double or a dual number:
  /// the derivatives with respect to x are exact inside a span; x is clamped to the first or last
  /// span outside [X_0, X_N]).
  template <class T>
  ReferenceStrain<T> at(const T& x) const;

private:
  std::vector<double> breakpoints_, lengths_;
  /// The homogeneous cubic [w r; w](u) of each span in the power basis: column j multiplies u^j.
  std::vector<Eigen::Matrix<double, 3, 4>> polynomials_;
  std::vector<Eigen::Vector4d> nodes_, weights_;
};

template <class T>
ReferenceStrain<T> CableReference::at(const T& x) const {
  using std::sqrt;
  const auto upper = std::upper_bound(breakpoints_.begin() + 1, breakpoints_.end() - 1, value_of(x));
  const int k = static_cast<int>(upper - breakpoints_.begin()) - 1;
  const double L = lengths_[k];
  const T u = (x - T(breakpoints_[k])) / T(L);
  // The homogeneous point and its first three u-derivatives (Horner in the power basis).
  const Eigen::Matrix<double, 3, 4>& c = polynomials_[k];
  std::array<Eigen::Matrix<T, 3, 1>, 4> h;
  for (int i = 0; i < 3; ++i) {
    h[0](i) = T(c(i, 0)) + u * (T(c(i, 1)) + u * (T(c(i, 2)) + u * T(c(i, 3))));
    h[1](i) = T(c(i, 1)) + u * (T(2.0 * c(i, 2)) + u * T(3.0 * c(i, 3)));
    h[2](i) = T(2.0 * c(i, 2)) + u * T(6.0 * c(i, 3));
    h[3](i) = T(6.0 * c(i, 3));
  }
  // r = A/W and its derivatives by the quotient rule (as iga::rancf_shape_function_derivatives).
  using Vec = Eigen::Matrix<T, 2, 1>;
  const T inv_w = T(1.0) / h[0](2);
  const Vec r = h[0].template head<2>() * inv_w;
  const Vec r1 = (h[1].template head<2>() - r * h[1](2)) * inv_w;
  const Vec r2 = (h[2].template head<2>() - r1 * T(2.0) * h[1](2) - r * h[2](2)) * inv_w;
  const Vec r3 = (h[3].template head<2>() - r2 * T(3.0) * h[1](2) - r1 * T(3.0) * h[2](2) -
                  r * h[3](2)) *
                 inv_w;
  const auto cross = [](const Vec& a, const Vec& b) { return a(0) * b(1) - a(1) * b(0); };
  const T s = r1.squaredNorm();
  const T inv_s15 = T(1.0) / (s * sqrt(s));
  const T c12 = cross(r1, r2);
  // ε₀ = (|r_u|²/L² − 1)/2, κ₀ = (r_u × r_uu)/|r_u|³ (invariant under reparameterization); d/dx = (1/L) d/du.
  return {T(0.5) * (s / T(L * L) - T(1.0)), r1.dot(r2) / T(L * L * L), c12 * inv_s15,
          (cross(r1, r3) - T(3.0) * c12 * r1.dot(r2) / s) * inv_s15 / T(L)};
}

}  // namespace spar::core
