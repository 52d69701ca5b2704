#include <spar/elements/beam/beam_inertia.hpp>

namespace spar::core {

// 003 eq. 32 with interpolated nodal velocities: m_IJ = ∫ N_I N_J dS.
FrameInertia beam_element_inertia(const GeometricallyExactBeam& beam, int e) {
  const SectionInertia& inertia = beam.inertia();
  return FrameInertia(beam.element(e).mass_coefficients, inertia.mass_per_length, inertia.rotary);
}

}  // namespace spar::core
