#pragma once
/// \file
/// A straight segment as an analysis-ready NURBS: the usual mesh of an initially straight beam.

#include <spar/error.hpp>
#include <spar/iga/knot_vector.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::iga {

/// The segment from a to b with `elements` equal elements of degree p and C^{p−1} continuity
/// (open-uniform knots on [0, 1]). The control points sit at the Greville abscissae, so the
/// parameterization is linear: the point at u is a + u (b − a) and |dC/du| = |b − a| everywhere.
template <int Dim>
NurbsCurve<Dim> straight_line(const Eigen::Matrix<double, Dim, 1>& a,
                              const Eigen::Matrix<double, Dim, 1>& b, int elements, int degree) {
  if ((b - a).norm() == 0.0)
    throw Error("the segment has zero length", "iga::straight_line", "give two distinct end points");
  // Checked before the continuity degree − 1 is formed (degree = INT_MIN overflowed there: found
  // by libFuzzer under UBSan, fuzz/model_fuzzer).
  if (degree < 1 || degree > max_degree)
    throw Error("degree " + std::to_string(degree) + " is outside 1 … max_degree = " + std::to_string(max_degree),
                "iga::straight_line", "give a degree from 1 to " + std::to_string(max_degree));
  const KnotVector knots = KnotVector::open_uniform(elements, degree, degree - 1);
  typename NurbsCurve<Dim>::Points points(Dim, knots.basis_count());
  const std::vector<double> greville = knots.greville();
  for (int i = 0; i < knots.basis_count(); ++i) points.col(i) = a + greville[i] * (b - a);
  return NurbsCurve<Dim>(knots, points);
}

}  // namespace spar::iga
