#pragma once
// Carrier centerlines for the sliding-joint tests: a quarter circle (rational, so the NURBS
// weights matter) cut into elements of a chosen degree and continuity.
#include <spar/iga/circular_arc.hpp>
#include <spar/iga/knot_operations.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <vector>

namespace spar::test {

/// The quarter circle of radius `radius` in the X–Y plane, of degree `degree` ≥ 2, with
/// `elements` equal elements joined with C^continuity (0 ≤ continuity ≤ degree − 1).
inline iga::NurbsCurve<3> quarter_circle_carrier(double radius, int elements, int degree,
                                                 int continuity) {
  iga::NurbsCurve<3> curve = iga::quarter_circle<3>(radius);
  if (degree > curve.degree()) curve = iga::elevate_degree(curve, degree - curve.degree()).curve;
  std::vector<double> knots;
  for (int e = 1; e < elements; ++e)
    for (int k = 0; k < degree - continuity; ++k)
      knots.push_back(curve.knots().first() +
                      (curve.knots().last() - curve.knots().first()) * e / elements);
  return knots.empty() ? curve : iga::refine_knots(curve, knots).curve;
}

}  // namespace spar::test
