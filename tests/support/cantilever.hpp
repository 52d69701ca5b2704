#pragma once
// A cantilever along +X clamped at the origin: the model used by the statics validation tests.
#include <spar/core/model.hpp>
#include <spar/elements/beam/beam.hpp>

#include "beam_fixtures.hpp"

namespace spar::test {

/// Steel-like section (EI = 1e4 N m², EA = 1e8 N, GA = 4e7 N) on a beam of length 1 m.
inline core::SectionStiffness cantilever_stiffness() {
  core::SectionStiffness C;
  C.axial = 1e8;
  C.shear_2 = C.shear_3 = 4e7;
  C.torsion = 8e3;
  C.bending_2 = C.bending_3 = 1e4;
  return C;
}

struct Cantilever {
  core::Model model;
  int beam = 0;
  int root = 0;
  int tip = 0;
};

inline Cantilever make_cantilever(int elements, int degree, double length = 1.0) {
  Cantilever c;
  c.beam = core::add_beam(c.model, {.centerline = straight_centerline(length, elements, degree),
                             .stiffness = cantilever_stiffness()});
  const core::GeometricallyExactBeam& beam = core::beam(c.model, c.beam);
  c.root = beam.node(0);
  c.tip = beam.node(beam.control_point_count() - 1);
  c.model.fix(c.root);
  return c;
}

/// A steel cantilever of `elements` cubic elements along +X, 1 m long, of a 1 cm square section,
/// with inertia, clamped at the root: the model of the API boundary tests.
inline Cantilever make_steel_cantilever(int elements) {
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection section = core::CrossSection::rectangle(0.01, 0.01, 0.3);
  Cantilever c;
  c.beam = core::add_beam(c.model, {.centerline = straight_centerline(1.0, elements, 3),
                             .stiffness = core::SectionStiffness::from(steel, section),
                             .inertia = core::SectionInertia::from(steel, section)});
  const core::GeometricallyExactBeam& beam = core::beam(c.model, c.beam);
  c.root = beam.node(0);
  c.tip = beam.node(beam.control_point_count() - 1);
  c.model.fix(c.root);
  return c;
}

}  // namespace spar::test
