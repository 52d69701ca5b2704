#pragma once
// A property check for a recorded dynamic trajectory: the stored velocities are the rate of the
// stored configurations, and the kinetic energy never grows by more than the work done on it.
//
// Why: a rotation increment is only known modulo 2π (exp(Δφ) = exp(Δφ (1 + 2πk/|Δφ|))). Before
// the fix, the slider-crank's Rod I root reported ~50 400 rad/s while its rotations (quaternions)
// turned at 377 rad/s: the velocity had been updated with an increment aliased by 8π, invisible
// in the configuration. Comparing each step's finite-difference rate of the configuration with
// the velocities catches that, whatever the model.
//
// For every step n → n + 1 (h = t_{n+1} − t_n) and every block:
//   frame: (x_{n+1} − x_n)/h  vs  ½(ẋ_n + ẋ_{n+1});  log(R_nᵀ R_{n+1})/h  vs  ½(Ω_n + Ω_{n+1});
//   vector: (p_{n+1} − p_n)/h  vs  ½(ṗ_n + ṗ_{n+1}).
// Both sides approximate the rate at t_{n+½} to O(h): the difference is bounded by
// acceleration_scale · h (+ a round-off floor) for motions whose accelerations stay below
// acceleration_scale. (For generalized-α, Δq = h v_n + h²((½ − β) a_n + β a_{n+1}) and
// v_{n+1} = v_n + h((1 − γ) a_n + γ a_{n+1}) give Δq/h − ½(v_n + v_{n+1}) = h c (a_{n+1} − a_n)
// with c = β − γ/2 = (γ − ½)²/4 = ((1 − ρ∞)/(1 + ρ∞))²/4: 0 for ρ∞ = 1, 6.9e-4 for 0.9, 3.1e-3
// for 0.8 — a large margin unless the algorithmic accelerations a are huge.)
// Energy: T_{n+1} − T_n ≤ (W_{n+1} − W_n) − (V_{n+1} − V_n) + energy_tolerance, with W the
// external work and V the strain and gravity potential — kinetic energy can come only from the
// work of the loads and constraints or from the potential energy.
#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace spar::test {

/// One recorded instant of a dynamic run.
struct TrajectoryFrame {
  double time = 0.0;
  core::Configuration q;
  Eigen::VectorXd v;             ///< global tangent layout (ẋ inertial, Ω material)
  double kinetic = 0.0;          ///< J
  double potential = 0.0;        ///< strain + gravity potential, J
  double external_work = 0.0;    ///< since t = 0, J
};

struct ConsistencyOptions {
  double acceleration_scale = 0.0;  ///< bound on the accelerations of the motion (m/s², rad/s²)
  double rate_floor = 1e-9;         ///< absolute floor of the rate comparison (round-off)
  double energy_tolerance = 0.0;    ///< J per step
};

struct ConsistencyResult {
  bool consistent = true;
  std::string first_violation;      ///< what, where, when
  double worst_rate_ratio = 0.0;    ///< max |rate − mean velocity| / (acceleration_scale h + floor)
  double worst_energy_excess = 0.0; ///< max of ΔT − ΔW + ΔV over the steps, J
};

inline ConsistencyResult check_velocity_consistency(const std::vector<TrajectoryFrame>& frames,
                                                    const ConsistencyOptions& options) {
  ConsistencyResult result;
  const auto fail = [&result](const std::string& what) {
    if (result.consistent) result.first_violation = what;
    result.consistent = false;
  };
  for (std::size_t n = 0; n + 1 < frames.size(); ++n) {
    const TrajectoryFrame &a = frames[n], &b = frames[n + 1];
    const double h = b.time - a.time;
    const double bound = options.acceleration_scale * h + options.rate_floor;
    const auto compare = [&](const Eigen::VectorXd& rate, const Eigen::VectorXd& mean, int block, const char* part) {
      const double gap = (rate - mean).norm();
      result.worst_rate_ratio = std::max(result.worst_rate_ratio, gap / bound);
      if (gap > bound) {
        std::ostringstream what;
        what << "step " << n << " (t = " << a.time << " -> " << b.time << "), block " << block << ", " << part
             << ": rate of the configuration " << rate.transpose() << ", mean velocity " << mean.transpose();
        fail(what.str());
      }
    };
    const Eigen::VectorXd rate = b.q.increment_from(a.q) / h;  // (q_{n+1} ⊖ q_n)/h
    for (int k = 0; k < a.q.block_count(); ++k) {
      const core::Block& block = a.q.blocks[k];
      const Eigen::VectorXd mean = 0.5 * (a.v.segment(block.offset, block.size) + b.v.segment(block.offset, block.size));
      if (a.q.is_frame(k)) {
        compare(rate.segment<3>(block.offset), mean.head<3>(), k, "translation");
        compare(rate.segment<3>(block.offset + 3), mean.tail<3>(), k, "rotation");
      } else {
        compare(rate.segment(block.offset, block.size), mean, k, "vector");
      }
    }
    const double excess = (b.kinetic - a.kinetic) - (b.external_work - a.external_work) + (b.potential - a.potential);
    result.worst_energy_excess = std::max(result.worst_energy_excess, excess);
    if (excess > options.energy_tolerance) {
      std::ostringstream what;
      what << "step " << n << " (t = " << a.time << "): kinetic energy " << a.kinetic << " -> " << b.kinetic
           << " J, more than the work " << b.external_work - a.external_work << " J and the potential released "
           << a.potential - b.potential << " J";
      fail(what.str());
    }
  }
  return result;
}

}  // namespace spar::test
