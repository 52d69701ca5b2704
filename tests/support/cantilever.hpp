#pragma once
// A cantilever along +X clamped at the origin: the model used by the statics validation tests.
#include <spar/core/model.hpp>

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
  c.beam = c.model.add_beam({.centerline = straight_centerline(length, elements, degree),
                             .stiffness = cantilever_stiffness()});
  const core::GeometricallyExactBeam& beam = c.model.beam(c.beam);
  c.root = beam.node(0);
  c.tip = beam.node(beam.control_point_count() - 1);
  c.model.fix(c.root);
  return c;
}

}  // namespace spar::test
