#pragma once
/// \file
/// One fuzz case of model building and a short solve: a cantilevered geometrically exact beam of
/// random material, section, end points, mesh, degree, section axis and quadrature, with a tip
/// force, sometimes a tip moment (dead or follower), gravity and a fixed rigid body, then a static
/// solve of 1–3 load steps or two generalized-α steps from a random tip velocity.

#include "fuzz_case.hpp"

namespace spar::fuzz {

/// How far a model case got.
struct ModelOutcome {
  bool built = false;   ///< the model was accepted
  bool solved = false;  ///< the solve returned
};

/// Properties: every call ends in a spar::Error or returns; a returned solve leaves finite
/// positions and rotations, and a dynamic one finite energies, work, dissipation and velocities.
ModelOutcome model_case(FuzzSource& f, CaseLog& log);

}  // namespace spar::fuzz
