#pragma once
/// \file
/// Bézier extraction (Borden, Scott, Evans & Hughes 2011, Algorithm 1): on element e the p+1
/// non-zero B-spline functions are N_e(ξ) = C_e B(ξ), B the Bernstein polynomials of degree p on
/// the element (ξ ∈ [0, 1]). The element loop built on it gives, for every element, the basis
/// functions and their derivatives at the Gauss points, with respect to the parameter u or, for a
/// reference curve, to its arc length s.

#include <spar/error.hpp>
#include <spar/iga/basis.hpp>
#include <spar/iga/detail/text.hpp>
#include <spar/iga/knot_vector.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

namespace spar::iga {

/// The (p+1)×(p+1) extraction operators C_e, one per element (Borden et al. 2011, Alg. 1):
/// row a = local basis function span−p+a, column b = Bernstein polynomial B_b.
std::vector<Eigen::MatrixXd> bezier_extraction(const KnotVector& U);

/// The Bernstein polynomials of degree p on [0, 1] and their derivatives up to `order` ≤ max_derivative_order.
void bernstein_derivatives(int degree, double xi, int order, BasisTable& out);

/// One element of the element loop: its interval, span and first basis function, the Gauss
/// points, and at each point the quadrature weight in the coordinate x (u, or s for an arc-length
/// loop), dx/du, and the basis table with derivatives with respect to x.
struct ElementQuadrature {
  int element;
  int span;
  int first_basis;  // = span − p: the global index of table column 0
  double first;
  double last;
  std::vector<double> parameters;
  std::vector<double> weights;
  std::vector<double> jacobians;
  std::vector<BasisTable> basis;
};

/// The element loop for the B-spline basis of U (rational if `weights` are given, one per basis
/// function): `points` Gauss–Legendre points per element, derivatives up to `order` ≤ max_derivative_order with
/// respect to u, computed as C_e B(ξ) with du = (last − first) dξ. jacobians are 1.
std::vector<ElementQuadrature> element_quadrature(const KnotVector& U, int points, int order = 2);
std::vector<ElementQuadrature> element_quadrature(const KnotVector& U, int points,
                                                  const Eigen::VectorXd& weights, int order = 2);

/// The element loop on a reference curve, mapped to its arc length s: with J = |C′(u)| and
/// J′ = C′·C″/J, dN/ds = N′/J, d²N/ds² = (N″ − N′J′/J)/J², ds = J du; the basis is the
/// curve's (rational) basis. order ≤ 2.
template <int Dim>
std::vector<ElementQuadrature> arc_length_quadrature(const NurbsCurve<Dim>& reference, int points,
                                                     int order = 2) {
  if (order < 0 || order > 2)
    throw Error("derivative order " + std::to_string(order) + " is outside 0 … 2",
                "iga::arc_length_quadrature", "ask for at most second derivatives in s");
  std::vector<ElementQuadrature> loop =
      element_quadrature(reference.knots(), points, reference.weights(), order);
  for (ElementQuadrature& element : loop)
    for (std::size_t q = 0; q < element.parameters.size(); ++q) {
      const auto D = reference.derivatives(element.parameters[q], 2);
      const double J = D.col(1).norm();
      if (!(J > 0.0))
        throw Error("the reference curve has a vanishing tangent at u = " +
                        detail::number(element.parameters[q]),
                    "iga::arc_length_quadrature", "use a regular reference curve");
      const double dJ = D.col(1).dot(D.col(2)) / J;
      BasisTable& N = element.basis[q];
      if (order >= 2) N.row(2) = (N.row(2) - N.row(1) * (dJ / J)) / (J * J);
      if (order >= 1) N.row(1) /= J;
      element.weights[q] *= J;
      element.jacobians[q] = J;
    }
  return loop;
}

}  // namespace spar::iga
