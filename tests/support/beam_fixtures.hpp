#pragma once
// Beams used across the test suites: a straight beam along +X, and a quarter circle of NURBS arcs.
#include <spar/core/beam.hpp>
#include <spar/core/configuration.hpp>
#include <spar/iga/knot_vector.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <cmath>
#include <numbers>

namespace spar::test {

/// A straight centerline from the origin along +X: open-uniform C^{p−1} knots, control points at
/// the Greville abscissae (so dS/du = length everywhere).
inline iga::NurbsCurve<3> straight_centerline(double length, int elements, int degree) {
  iga::KnotVector U = iga::KnotVector::open_uniform(elements, degree, degree - 1);
  const std::vector<double> greville = U.greville();
  iga::NurbsCurve<3>::Points P = iga::NurbsCurve<3>::Points::Zero(3, greville.size());
  for (std::size_t i = 0; i < greville.size(); ++i) P(0, i) = length * greville[i];
  return iga::NurbsCurve<3>(U, P);
}

/// Section stiffness with distinct, order-one values (and a bending coupling), so that a wrong
/// index in a stiffness formula shows.
inline core::SectionStiffness generic_stiffness() {
  core::SectionStiffness C;
  C.axial = 3.0;
  C.shear_2 = 2.0;
  C.shear_3 = 2.5;
  C.torsion = 0.7;
  C.bending_2 = 1.1;
  C.bending_3 = 0.9;
  C.bending_23 = 0.2;
  return C;
}

}  // namespace spar::test
