#pragma once
// Beams used across the test suites: a straight beam along +X, and a quarter circle of NURBS arcs.
#include <spar/elements/beam/beam.hpp>
#include <spar/core/configuration.hpp>
#include <spar/core/model.hpp>
#include <spar/iga/knot_vector.hpp>
#include <spar/iga/nurbs_curve.hpp>
#include <spar/iga/straight_line.hpp>

#include <cmath>
#include <numbers>

namespace spar::test {

/// A straight centerline from the origin along +X (dS/du = length everywhere).
inline iga::NurbsCurve<3> straight_centerline(double length, int elements, int degree) {
  return iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0), elements, degree);
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

/// A slender free beam of length 1 along +X with EI = 10, EA = 1e4 and the mass of a thin rod
/// (ρA = 1, ρJ small): its first cantilever mode is at 11 rad/s.
inline core::Model slender_free_beam(int elements, int degree) {
  core::SectionStiffness C;
  C.axial = 1e4;
  C.shear_2 = C.shear_3 = 5e3;
  C.torsion = 8.0;
  C.bending_2 = C.bending_3 = 10.0;
  core::SectionInertia inertia;
  inertia.mass_per_length = 1.0;
  inertia.rotary = Eigen::Vector3d(2e-4, 1e-4, 1e-4).asDiagonal();
  core::Model model;
  core::add_beam(model, {.centerline = straight_centerline(1.0, elements, degree), .stiffness = C,
                  .inertia = inertia});
  return model;
}

}  // namespace spar::test
