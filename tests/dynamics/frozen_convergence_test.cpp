// 003's frozen iteration matrix (docs/dynamics.md D5) keeps the rotation–rotation blocks J_θ of
// t = 0. A rigid rotation of an unstressed beam leaves them as they were (the local frame), and
// the stress of a vibration that does not turn the beam far changes them little: both converge as
// with the updated matrix. A beam that turns far while stressed does not: the frozen blocks miss
// how the stress turned with it. This is the truss unit's linear law, whose members ring while the
// unit unfolds by 85°: 6.8 frozen iterations per step against 2.4 updated (docs/performance.md,
// "Truss deployment"); the smooth laws barely stress the members and stay within 6 %.
#include <spar/spar.hpp>

#include <catch2/catch.hpp>

#include "beam_fixtures.hpp"

using namespace spar;

namespace {

enum class Motion {
  rigid_spin,          ///< a free beam at 3 rad/s about Z through its middle: 1.5 rad in 0.5 s
  small_vibration,     ///< a cantilever in its first mode, the tip at 0.01 m/s (~1 mm)
  large_vibration,     ///< the same at 3 m/s (~0.27 m on 1 m)
  spinning_vibration,  ///< the free beam spinning and bending about Y at 3 m/s
};

/// Newton iterations of 0.5 s at h = 1e-3 with the given strategy.
long iterations(Motion motion, solvers::IterationMatrix strategy) {
  core::Model model = test::slender_free_beam(4, 3);
  const bool cantilever = motion == Motion::small_vibration || motion == Motion::large_vibration;
  if (cantilever) model.fix(0);
  solvers::GeneralizedAlpha integrator(model, {},
                                       {.time_step = 1e-3, .spectral_radius = 0.9, .iteration_matrix = strategy,
                                        .tolerance = 1e-16, .constraint_tolerance = 1e-10,
                                        .residual_tolerance = 1e-8});
  for (int k = 0; k < model.block_count(); ++k) {
    const double x = model.state().position[k].x(), s = x - 0.5;
    Eigen::Vector3d v = Eigen::Vector3d::Zero(), omega = Eigen::Vector3d::Zero();
    if (cantilever && k > 0) {  // the first mode's shape x² (slope 2x)
      const double V = motion == Motion::small_vibration ? 0.01 : 3.0;
      v.y() = V * x * x;
      omega.z() = 2.0 * V * x;
    } else if (!cantilever) {
      v.y() = 3.0 * s;  // the spin
      omega.z() = 3.0;
      if (motion == Motion::spinning_vibration) {  // bending about Y, shape s²
        v.z() = 3.0 * s * s;
        omega.y() = -6.0 * s;
      }
    }
    integrator.set_velocity(k, v, omega);
  }
  integrator.initialize();
  while (integrator.time() < 0.5 - 0.5e-3) integrator.step();
  return integrator.counters().newton_iterations;
}

}  // namespace

TEST_CASE("frozen J_theta: a rigid spin or a vibration converges as updated, a spinning vibration does not",
          "[dynamics][frozen]") {
  using solvers::IterationMatrix;
  // 500 steps each; Newton's test at 1e-8 (increment) and 1e-8 of the residual's terms.
  // Measured: 1000 and 1000 for the spin, the small and the large vibration; 1500 frozen against
  // 1000 updated for the spinning vibration (one more iteration at every step).
  for (const Motion motion : {Motion::rigid_spin, Motion::small_vibration, Motion::large_vibration}) {
    INFO("motion " << static_cast<int>(motion));
    CHECK(iterations(motion, IterationMatrix::frozen) == iterations(motion, IterationMatrix::update));
  }
  const long frozen = iterations(Motion::spinning_vibration, IterationMatrix::frozen),
             updated = iterations(Motion::spinning_vibration, IterationMatrix::update);
  CHECK(updated == 1000);
  CHECK(frozen >= 1.4 * updated);
}
