#pragma once
/// \file
/// Gauss–Legendre quadrature of any order on [−1, 1].

#include <vector>

namespace spar::iga {

/// Points (increasing) and weights of a quadrature rule on [−1, 1].
struct GaussRule {
  std::vector<double> points;
  std::vector<double> weights;
};

/// The most points of a Gauss–Legendre rule: exact to degree 127, far above any element's
/// integrand, and small enough that the O(n²) root search ends at once (100 000 points hung).
inline constexpr int max_gauss_points = 64;

/// The n-point Gauss–Legendre rule (1 ≤ n ≤ max_gauss_points), exact for polynomials of degree ≤ 2n−1. The nodes
/// are the roots of the Legendre polynomial P_n found by Newton's method in extended precision
/// from the asymptotic guess cos(π(i + 3/4)/(n + 1/2)); w_i = 2 / ((1 − x_i²) P_n′(x_i)²).
GaussRule gauss_legendre(int n);

}  // namespace spar::iga
