#include <spar/core/element.hpp>

namespace spar::core {

void ElementOutput::reset(int n, const ElementRequest& request) {
  // Sized even when not asked for: an element that computes it anyway writes in bounds.
  residual.setZero(n);
  if (request.stiffness) stiffness.setZero(n, n);
  if (request.damping) damping.setZero(n, n);
  if (request.mass) mass.setZero(n, n);
  energy = {};
  if (request.energy) external_force.setZero(n);
}

}  // namespace spar::core
