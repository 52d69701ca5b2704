// The start of the generalized-α integrator and its restarts (docs/dynamics.md D6, D6a, D6b,
// D6d): the initial assembly of positions and velocities onto the constraints by least change in
// the metric of M, consistent accelerations and multipliers, and the perturbed starting values.
#include "integrator.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace spar::solvers {

using detail::MatrixCoefficients;

/// M v̇₀ + Bᵀλ₀ = −(f_qv + f_int − f_ext), B v̇₀ = −c(q₀, v₀, 0).
/// The first call starts the run (and its energy balance); a later one restarts the method from
/// consistent accelerations at the current state, the balance carrying on.
void GeneralizedAlpha::Implementation::initialize() {
  if (!initialized && options.initial_assembly) {
    assemble_initial_state();
    consistent_accelerations(true);
  } else {
    consistent_accelerations(false);
  }
  if (!initialized && options.perturbed_starting_values) perturb_starting_values();
  matrix.freeze(assembly, input(state.time));
  evaluate(state.time, nullptr, 1.0);
  // The balance starts at t = 0 with the consistent accelerations.
  if (!initialized) {
    balance.initial_energy = detail::mechanical_energy(assembly);
    balance.initial_gravity = assembly.energies().gravity;
  }
  // Finite inputs may still overflow in the energies (a mass of 1e300 kg at z = -1e300 m): the
  // balance would be NaN from the start (found by tests/input/fuzz_test.cpp).
  if (!std::isfinite(detail::mechanical_energy(assembly)))
    throw Error("the mechanical energy at t = " + significant(state.time) +
                    " is not finite (kinetic, strain or gravity potential overflows)",
                "solvers::GeneralizedAlpha::initialize",
                "check the model's masses, positions, velocities and gravity for absurd magnitudes");
  restart_balance();
  initialized = true;
}

/// Assembles [M Bᵀ; B 0] at the current state (the residual then holds [r ; Φ]) and factorizes
/// it with the Dirichlet conditions. It is not an iteration matrix. Its chart is the current
/// state: with the last step's increment left in it, B came out as B T(hΔq), and the
/// accelerations of initialize() during a run missed the joints by ½ h (Ω × v̇) (tests/dynamics/
/// heavy_top_test.cpp, "initialize() during a run …").
void GeneralizedAlpha::Implementation::factorize_mass_and_constraints() {
  increment.setZero();
  const MatrixCoefficients mass_only{.mass = 1.0, .damping = 0.0, .stiffness = 0.0};
  evaluate(state.time, &mass_only, 1.0, true);
  factorize(state.time);
  matrix.invalidate();
}

/// v̇ and λ consistent with the equations at the current (q, v, t), and a = v̇: the method's
/// start at t = 0, and its restart after an event changed the equations.
/// M v̇ + Bᵀλ = −(f_qv + f_int − f_ext), B v̇ = −c(q, v, t).
/// `factorized`: [M Bᵀ; B 0] is factorized at the current state and the residual holds
/// [r ; Φ] with v̇ = 0, λ = 0 at the current v (what assemble_initial_state leaves).
void GeneralizedAlpha::Implementation::consistent_accelerations(bool factorized) {
  state.acceleration.setZero();
  state.multipliers.setZero();
  if (!factorized) factorize_mass_and_constraints();
  const int n = assembly.dof_count();
  solution = -assembly.residual();
  constraint_terms(solution, [&](const joints::Constraint& c, Eigen::Ref<Eigen::VectorXd> out) {
    c.acceleration_terms(state.q, state.velocity, state.time, out);
    out = -out;
  });
  for (int dof : model.fixed_dofs()) solution(dof) = 0.0;
  matrix.solver().solve(solution);
  state.acceleration = solution.head(n);
  state.algorithmic_acceleration = state.acceleration;
  state.multipliers = solution.tail(assembly.multiplier_count());
  if (!solution.allFinite())
    throw Error("the consistent accelerations are not finite at t = " + significant(state.time),
                "solvers::GeneralizedAlpha", "check the model's masses, loads and velocities for NaN or infinite values");
}

/// Perturbed starting values (DynamicOptions::perturbed_starting_values, docs/dynamics.md
/// D6d). The method's smooth numerical solution has a_n = v̇(t_n) + Δ_α h v̈(t_n) + O(h²) and
/// v_n = v(t_n) + c_v h² v̈(t_n) + O(h³), Δ_α = α_m − α_f, c_v = 1/6 − β − Δ_α/2 (the update
/// relations of D3 expanded about an exact trajectory, derived there; cf. Arnold & Brüls 2007,
/// Arnold, Brüls & Cardona 2015). Started from a₀ = v̇₀, v₀ = v(t₀), the index-3 method turns
/// the O(h²) velocity offset along the constraints into an O(h) acceleration and multiplier
/// transient that decays like (−ρ∞)ⁿ; started on the smooth solution it has none. v̈₀ is the
/// difference quotient (v̇₁ − v̇₀)/h of the consistent accelerations at t₀ and at the end of one
/// auxiliary step of h from the unperturbed values (its v₁ is O(h²) off, so v̈₀ is O(h) off and
/// the starting values O(h²) and O(h³) off). The auxiliary step is undone; its Newton
/// iterations and factorizations stay in the counters. A frame's rotation adds h²/12 Ω × Ω̇ to
/// its velocity (from log(R(t)ᵀR(t + h)), D6d).
void GeneralizedAlpha::Implementation::perturb_starting_values() {
  const double h = options.time_step;
  Snapshot initial;
  save(initial);
  // The step books its work and dissipation against the forces at its start, which initialize()
  // sets only afterwards; the auxiliary step's booking is discarded with it.
  balance.clear_forces(assembly.dof_count());
  if (!try_step(h, Predictor::extrapolated) && !try_step(h, Predictor::velocity_only))
    throw Error("the auxiliary step of the perturbed starting values did not converge at t = " +
                    significant(state.time) + " (h = " + significant(h) + "): " + last_failure,
                "solvers::GeneralizedAlpha::initialize",
                "reduce the time step, or switch DynamicOptions::perturbed_starting_values off");
  consistent_accelerations(false);
  const Eigen::VectorXd vdot_next = state.acceleration;
  restore(initial);
  const double delta_alpha = alpha.alpha_m - alpha.alpha_f;
  const Eigen::VectorXd vddot = (vdot_next - state.acceleration) / h;
  state.algorithmic_acceleration = state.acceleration + delta_alpha * h * vddot;
  // A frame's rotation also has log(R(t)ᵀR(t + h)) = … + h³/12 Ω × Ω̇ (D6d): its velocity the
  // extra h²/12 Ω × Ω̇.
  Eigen::VectorXd offset = h * h * (1.0 / 6.0 - alpha.beta - 0.5 * delta_alpha) * vddot;
  for (int b = 0; b < state.q.block_count(); ++b)
    if (state.q.is_frame(b)) {
      const int rotation = state.q.blocks[b].offset + 3;
      offset.segment<3>(rotation) +=
          h * h / 12.0 * state.velocity.segment<3>(rotation).cross(state.acceleration.segment<3>(rotation));
    }
  state.velocity += offset;
  for (int dof : model.fixed_dofs()) state.algorithmic_acceleration(dof) = state.velocity(dof) = 0.0;
}

/// Moves the positions onto Φ(q, t) = 0 by Gauss–Newton on the least change in the metric of
/// M: with d the change so far, [M Bᵀ; B 0] [Δ; μ] = [−M d; −Φ] (docs/dynamics.md D6b), whose
/// fixed point is the KKT point of min ½ dᵀM d subject to Φ(q ⊕ d) = 0. Leaves [M Bᵀ; B 0]
/// factorized at the final state with the residual [r ; Φ] at v̇ = 0, λ = 0. Returns the
/// iterations; `change` accumulates d. spar::Error (the state restored) when it does not converge
/// in max_iterations; `what` names the occasion for it.
int GeneralizedAlpha::Implementation::project_positions(Eigen::VectorXd& change, const std::string& what) {
  const int n = assembly.dof_count(), m = assembly.multiplier_count();
  const core::Configuration given = state.q;
  state.acceleration.setZero();
  state.multipliers.setZero();
  change = Eigen::VectorXd::Zero(n);
  for (int iteration = 0;; ++iteration) {
    factorize_mass_and_constraints();
    if (constraint_norm() <= options.constraint_tolerance) return iteration;
    if (iteration == options.max_iterations || !assembly.residual().allFinite()) {
      const double residual = constraint_norm();
      state.q = given;
      evaluate(state.time, nullptr, 1.0);
      throw Error("the configuration could not be projected onto the constraints " + what + " at t = " +
                      significant(state.time) + " (|Phi| = " + significant(residual) + " after " +
                      std::to_string(iteration) + " iterations)",
                  "solvers::GeneralizedAlpha",
                  "check that the constraints can hold together at this state (joint positions, axes and "
                  "drivers' angles at t = " + significant(state.time) + ")");
    }
    Eigen::VectorXd state_vector = Eigen::VectorXd::Zero(assembly.size());
    state_vector.head(n) = change;
    solution = assembly.pattern().matrix() * state_vector;
    solution.head(n) = -solution.head(n);
    solution.tail(m) = -assembly.residual().tail(m);
    for (int dof : model.fixed_dofs()) solution(dof) = 0.0;
    matrix.solver().solve(solution);
    change += solution.head(n);
    state.q.apply_increment(solution.head(n));
  }
}

/// The least change of the velocities in the metric of M onto B v + Φ_t = 0:
/// [M Bᵀ; B 0] [Δv; μ] = [0; −(B v + Φ_t)], with B v read off the factorized matrix
/// (project_positions leaves it at the current state). Returns Δv; `violation` gets
/// ‖B v + Φ_t‖∞ before.
Eigen::VectorXd GeneralizedAlpha::Implementation::project_velocities(double& violation) {
  const int n = assembly.dof_count(), m = assembly.multiplier_count();
  Eigen::VectorXd velocities = Eigen::VectorXd::Zero(assembly.size());
  velocities.head(n) = state.velocity;
  solution = assembly.pattern().matrix() * velocities;
  solution.head(n).setZero();
  constraint_terms(solution, [&](const joints::Constraint& c, Eigen::Ref<Eigen::VectorXd> out) {
    Eigen::VectorXd phi_t(out.size());
    c.time_derivative(state.q, state.time, phi_t);
    out = -(out + phi_t);
  });
  violation = m ? solution.tail(m).lpNorm<Eigen::Infinity>() : 0.0;
  matrix.solver().solve(solution);
  Eigen::VectorXd change = solution.head(n);
  for (int dof : model.fixed_dofs()) change(dof) = 0.0;
  state.velocity += change;
  return change;
}

/// After an event that changed the constraint equations (an end stop locking a slider), the
/// state may violate the new constraints (the slider passed its stop within the step) and move
/// against them. Projects the positions onto Φ = 0 and the velocities onto B v + Φ_t = 0 in the
/// metric of the mass matrix — the perfectly plastic impact the event stands for, whose energy
/// loss shows in the numerical dissipation — and restarts from consistent accelerations
/// (docs/dynamics.md, "Events"). Without it the index-3 method meets the new constraint within
/// one step and its velocity rings, gaining energy.
void GeneralizedAlpha::Implementation::project_onto_constraints() {
  Eigen::VectorXd change;
  double violation = 0.0;
  project_positions(change, "after the event");
  project_velocities(violation);
  consistent_accelerations(false);
  evaluate(state.time, nullptr, 1.0);
  restart_balance();
}

/// The initial assembly (DynamicOptions::initial_assembly): positions, then velocities, onto
/// the constraints by least change in the metric of M; the report in `assembly_report`. Leaves
/// [M Bᵀ; B 0] factorized and the residual [r ; Φ] at v̇ = 0, λ = 0 at the assembled state.
void GeneralizedAlpha::Implementation::assemble_initial_state() {
  InitialAssembly& report = assembly_report;
  report = InitialAssembly{};
  report.performed = true;
  const core::Configuration given = state.q;
  // Φ of the state as given, before any change.
  for (const auto& constraint : constraints) {
    Eigen::VectorXd phi(constraint->equation_count());
    constraint->value(state.q, state.time, phi);
    if (phi.size()) report.constraint_residual = std::max(report.constraint_residual, phi.lpNorm<Eigen::Infinity>());
  }
  report.position_iterations = project_positions(report.position_change, "by the initial assembly");
  const Eigen::VectorXd& units = options.increment_units;
  for (int b = 0; b < state.q.block_count(); ++b) {
    const core::Block& block = state.q.blocks[b];
    for (int i = block.offset; i < block.offset + block.size; ++i) {
      const double change = std::abs(report.position_change(i)) / (units.size() ? units(i) : 1.0);
      if (change > report.largest_position_change) {
        report.largest_position_change = change;
        report.largest_position_change_block = b;
      }
    }
  }
  if (report.largest_position_change > options.initial_assembly_tolerance) {
    state.q = given;
    evaluate(state.time, nullptr, 1.0);
    std::ostringstream what;
    what << "the initial assembly would move block " << report.largest_position_change_block << " by "
         << report.largest_position_change << " (|Phi| = " << report.constraint_residual
         << " as given), more than initial_assembly_tolerance = " << options.initial_assembly_tolerance;
    throw Error(what.str(), "solvers::GeneralizedAlpha::initialize",
                "place the bodies and joints consistently (check the joints' points and the "
                "drivers' angles at t = 0), or raise DynamicOptions::initial_assembly_tolerance");
  }
  const double tau = options.initial_velocity_stiffness_time;
  if (tau > 0.0) {  // [M + τ²K, Bᵀ; B 0] for the velocities, [M Bᵀ; B 0] again for v̇ below
    const MatrixCoefficients weighted{.mass = 1.0, .damping = 0.0, .stiffness = tau * tau};
    evaluate(state.time, &weighted, 1.0, true);
    factorize(state.time);
    matrix.invalidate();
  }
  report.velocity_change = project_velocities(report.velocity_constraint_residual);
  report.largest_velocity_change =
      report.velocity_change.size() ? report.velocity_change.lpNorm<Eigen::Infinity>() : 0.0;
  if (tau > 0.0) {
    factorize_mass_and_constraints();
  } else if (report.largest_velocity_change > 0.0) {
    // The residual [r ; Φ] depends on v (gyroscopic and damping forces): evaluated again.
    evaluate(state.time, nullptr, 1.0);
  }
}

}  // namespace spar::solvers
