#pragma once
/// \file
/// One fuzz case of the spline inputs: a knot vector, control points and weights (each sometimes
/// broken) → NurbsCurve, evaluation, knot insertion, refinement, degree elevation, h-refinement,
/// Bézier extraction, and an open-uniform knot vector of random size.

#include "fuzz_case.hpp"

namespace spar::fuzz {

/// How far a spline case got (the property test checks that most cases reach the properties).
struct SplineOutcome {
  bool curve = false;    ///< a NurbsCurve was built
  bool refined = false;  ///< a knot was inserted into it
};

/// Properties: every call ends in a spar::Error or returns; derivatives are finite; insertion,
/// refinement, elevation and h-refinement leave the curve unchanged to 1e-10 of the control net's
/// size (round-off of weights in 0.2 … 5); every column of every Bézier extraction operator sums
/// to 1 to 1e-12 (Σ_a N_a = 1 = Σ_b B_b).
SplineOutcome spline_case(FuzzSource& f, CaseLog& log);

}  // namespace spar::fuzz
