#pragma once
/// \file
/// B-spline basis functions and their derivatives (The NURBS Book A2.2/A2.3) and the NURBS
/// (rational) basis and its derivatives by the quotient rule in homogeneous form (The NURBS Book
/// eq. 4.2 and eq. 4.8, applied to the basis functions instead of the points). Both kernels work
/// on fixed-size tables and allocate nothing.

#include <spar/error.hpp>
#include <spar/iga/knot_vector.hpp>

#include <Eigen/Core>

#include <string>

namespace spar::iga {

/// The highest derivative order the basis kernels compute: every non-zero derivative of the
/// highest degree.
inline constexpr int max_derivative_order = max_degree;

/// Basis values and derivatives at one parameter: row k = k-th derivative with respect to u
/// (k = 0 … max_derivative_order), column j = basis function span − p + j (j = 0 … p); unused
/// entries are zero.
using BasisTable = Eigen::Matrix<double, max_derivative_order + 1, max_degree + 1>;

/// The non-zero B-spline basis functions N_{span−p+j,p}(u) and their derivatives up to `order`
/// (0 ≤ order ≤ max_derivative_order; derivatives above p are zero) — A2.3, whose first stage is the triangular
/// table of A2.2. `span` must be U.find_span(u) or a span whose closed interval holds u.
void basis_derivatives(const KnotVector& U, int span, double u, int order, BasisTable& out);

/// The NURBS basis R_{i,p} = w_i N_{i,p} / W, W = Σ w_j N_{j,p}, and its derivatives up to
/// `order` ≤ max_derivative_order: with A^(k)_i = w_i N^(k)_i and W^(k) = Σ A^(k)_i,
///   R^(k)_i = (A^(k)_i − Σ_{l=1..k} C(k,l) W^(l) R^(k−l)_i) / W   (The NURBS Book eq. 4.8).
/// `weights` holds all U.basis_count() weights, each > 0 (checked by NurbsCurve, not here).
void rational_basis_derivatives(const KnotVector& U, int span, double u, int order,
                                const Eigen::VectorXd& weights, BasisTable& out);

namespace detail {

/// Turns B-spline derivatives `table` (p+1 columns, rows 0 … order) into NURBS derivatives in
/// place, with the p+1 local weights `local_weights[0 … p]`.
void rationalize(BasisTable& table, int degree, int order, const double* local_weights);

/// Throws spar::Error unless 0 ≤ order ≤ max_derivative_order (inline, so that callers'
/// fixed-size storage is seen to be in bounds).
inline void check_derivative_order(int order, const char* where) {
  if (order < 0 || order > max_derivative_order)
    throw Error("derivative order " + std::to_string(order) + " is outside 0 … " +
                    std::to_string(max_derivative_order),
                where, "ask for at most the derivative of order max_derivative_order");
}

}  // namespace detail

}  // namespace spar::iga
