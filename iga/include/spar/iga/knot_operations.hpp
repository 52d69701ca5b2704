#pragma once
/// \file
/// Knot insertion (The NURBS Book A5.1), knot refinement (A5.4) and degree elevation (eq. 5.36 on
/// each element's Bézier form), and
/// the h-, p- and k-refinement built on them. Every operation returns its operator matrix T as
/// well as the new curve: the new homogeneous control points are Qw = T · Pw (rows = control
/// points), so the same T transfers any field discretized on the old basis (e.g. a beam's
/// displacements) to the new one. The geometry and the parameterization are unchanged.

#include <spar/iga/knot_vector.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace spar::iga {

/// A knot operation on a basis: the new knot vector and the operator T (new basis count × old
/// basis count) with Qw = T · Pw for the homogeneous control points.
struct KnotOperator {
  KnotVector knots;
  Eigen::MatrixXd matrix;
};

/// Inserts u `times` times (A5.1); u strictly inside the knot range and its final multiplicity
/// at most p, else spar::Error.
KnotOperator knot_insertion_operator(const KnotVector& U, double u, int times);

/// Inserts the non-decreasing knots X, all strictly inside the knot range (A5.4). Interior
/// multiplicities may reach p+1.
KnotOperator knot_refinement_operator(const KnotVector& U, const std::vector<double>& X);

/// Raises the degree from p to p+t (t ≥ 0) keeping the continuity at every knot: each distinct
/// knot's multiplicity grows by t. Computed through the Bézier form of each element, not by
/// A5.9, whose knot removal loses digits next to short spans (docs/iga.md).
KnotOperator degree_elevation_operator(const KnotVector& U, int t);

/// The knots that split every element of U into `elements_per_span` equal parts (h-refinement).
std::vector<double> uniform_refinement_knots(const KnotVector& U, int elements_per_span);

/// A refined curve and the operator that produced it (Qw = matrix · Pw).
template <int Dim>
struct RefinedCurve {
  NurbsCurve<Dim> curve;
  Eigen::MatrixXd matrix;
};

/// Applies a knot operator to the homogeneous control points of `curve`.
template <int Dim>
RefinedCurve<Dim> apply(const NurbsCurve<Dim>& curve, KnotOperator op) {
  const typename NurbsCurve<Dim>::HomogeneousPoints Qw =
      curve.homogeneous_points() * op.matrix.transpose();
  return {NurbsCurve<Dim>::from_homogeneous(std::move(op.knots), Qw), std::move(op.matrix)};
}

/// The curve with u inserted `times` times (A5.1).
template <int Dim>
RefinedCurve<Dim> insert_knot(const NurbsCurve<Dim>& curve, double u, int times = 1) {
  return apply(curve, knot_insertion_operator(curve.knots(), u, times));
}

/// The curve with the knots X inserted (A5.4).
template <int Dim>
RefinedCurve<Dim> refine_knots(const NurbsCurve<Dim>& curve, const std::vector<double>& X) {
  return apply(curve, knot_refinement_operator(curve.knots(), X));
}

/// The curve of degree p+t (degree_elevation_operator).
template <int Dim>
RefinedCurve<Dim> elevate_degree(const NurbsCurve<Dim>& curve, int t) {
  return apply(curve, degree_elevation_operator(curve.knots(), t));
}

/// h-refinement: every element split into `elements_per_span` equal elements, C^{p−1} at the
/// new knots.
template <int Dim>
RefinedCurve<Dim> h_refine(const NurbsCurve<Dim>& curve, int elements_per_span) {
  return refine_knots(curve, uniform_refinement_knots(curve.knots(), elements_per_span));
}

/// p-refinement: the degree raised by t, the continuity at the existing knots kept.
template <int Dim>
RefinedCurve<Dim> p_refine(const NurbsCurve<Dim>& curve, int t) {
  return elevate_degree(curve, t);
}

/// k-refinement: the degree raised by t first, then every element split into
/// `elements_per_span` parts, so the new knots carry C^{p+t−1}.
template <int Dim>
RefinedCurve<Dim> k_refine(const NurbsCurve<Dim>& curve, int t, int elements_per_span) {
  RefinedCurve<Dim> elevated = elevate_degree(curve, t);
  RefinedCurve<Dim> refined = h_refine(elevated.curve, elements_per_span);
  return {std::move(refined.curve), refined.matrix * elevated.matrix};
}

}  // namespace spar::iga
