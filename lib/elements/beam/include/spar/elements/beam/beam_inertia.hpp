#pragma once
/// \file
/// The consistent mass of a geometrically exact beam element (003 eqs. 30–32) as the frames'
/// factored inertia of core/frame_inertia.hpp, m_IJ = ∫ N_I N_J dS.

#include <spar/core/frame_inertia.hpp>
#include <spar/elements/beam/beam.hpp>

namespace spar::core {

static_assert(max_beam_element_nodes <= max_inertia_frames, "a beam element's frames fit one FrameInertia");

/// The inertia of element e of a beam (k = p + 1 frames, 003 eqs. 30–32).
FrameInertia beam_element_inertia(const GeometricallyExactBeam& beam, int e);

}  // namespace spar::core
