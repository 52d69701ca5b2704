// One step of the Lie-group generalized-α integrator (docs/dynamics.md D3–D6; Brüls, Cardona &
// Arnold 2012, Algorithm 1, with the index-3 constraints of Arnold & Brüls 2007 and 003 eq. 49).
//
// Unknowns of a Newton iteration: the increment Δx of the step's motion h·Δq (one entry per dof
// of the tangent layout: 6 per frame block, n per vector block) and the scaled multipliers
// λ̃ = λ/β′. The dynamic rows are divided by β′ = (1 − α_m)/(h²β(1 − α_f)), so the iteration matrix
//     [ M + (γ′/β′) C + (1/β′)(K + K_λ) T    Bᵀ ]
//     [ B T                                   0  ]
// has entries of the size of the mass and of the constraint Jacobian for every h (the scaling of
// Bottasso, Bauchau & Cardoso 2007), and Newton's increment of the multipliers is h²β-sized.
#include "integrator.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace spar::solvers {

/// A frame turned by π or more within one step has left the chart: exp(hΔφ) cannot tell hΔφ from
/// hΔφ + 2πk (docs/model.md eq. M2). Such an iterate is refused, and the step cut back.
bool GeneralizedAlpha::Implementation::inside_chart() {
  if (state.q.largest_rotation(increment) < std::numbers::pi) return true;
  ++counters.rejected_rotations;
  last_failure = "a frame turned by pi or more within the step";
  return false;
}

/// Tries one step of size h from the current state; on failure restores it and returns false.
bool GeneralizedAlpha::Implementation::try_step(double h, Predictor predictor) {
  const double t_next = state.time + h;
  const detail::StepCoefficients c = detail::StepCoefficients::of(h, alpha);
  save(start);
  const Eigen::VectorXd& v0 = start.state.velocity;
  const Eigen::VectorXd& vdot0 = start.state.acceleration;
  const Eigen::VectorXd& a0 = start.state.algorithmic_acceleration;
  matrix.start_step(h);

  // Predictor (Brüls et al. 2012, Algorithm 1): a_{n+1} = base + (1 − α_f)/(1 − α_m) v̇_{n+1}.
  const Eigen::VectorXd a = (c.alpha_f * vdot0 - c.alpha_m * a0) / (1 - c.alpha_m);
  Eigen::VectorXd& acceleration = state.acceleration;
  acceleration.setZero();
  if (predictor == Predictor::velocity_only)  // (½ − β) a_n + β a_{n+1} = 0
    acceleration = (-(0.5 - c.beta) / c.beta * a0 - a) * (1 - c.alpha_m) / (1 - c.alpha_f);
  const Eigen::VectorXd a_next = a + (1 - c.alpha_f) / (1 - c.alpha_m) * acceleration;
  state.velocity = v0 + h * (1 - c.gamma) * a0 + h * c.gamma * a_next;
  increment = h * v0 + h * h * (0.5 - c.beta) * a0 + h * h * c.beta * a_next;
  for (int dof : model.fixed_dofs()) state.velocity(dof) = increment(dof) = acceleration(dof) = 0.0;

  bool converged = false;
  if (inside_chart()) {
    state.q.assign_increment(start.state.q, increment);
    try {
      converged = newton(c, t_next);
    } catch (const EvaluationFailure&) {
      converged = false;
    }
  }
  if (converged) {
    state.algorithmic_acceleration = a + (1 - c.alpha_f) / (1 - c.alpha_m) * acceleration;
    balance.book_step(assembly, increment, detail::driver_force(assembly, state.q, t_next, balance.driven));
    state.time = t_next;
    return true;
  }
  // Not converged: restore the step's start.
  restore(start);
  matrix.request_refactorization();
  return false;
}

void GeneralizedAlpha::Implementation::guarded_evaluate(double time, const detail::MatrixCoefficients* c,
                                                        double residual_scale, bool with_energies) {
  guarded([&] { evaluate(time, c, residual_scale, false, with_energies); });
}

/// Newton iterations of one step from the predictor; true when converged.
bool GeneralizedAlpha::Implementation::newton(const detail::StepCoefficients& c, double t_next) {
  const int n = assembly.dof_count(), m = assembly.multiplier_count();
  double previous_norm = INFINITY, norm_squared = INFINITY;
  for (int iteration = 0;; ++iteration) {
    // Once the increment is below the tolerance the next evaluation is most likely the last:
    // it computes the residual only, and the matrix follows if the residual check fails.
    const bool expect_convergence = norm_squared <= options.tolerance;
    const bool need_matrix = matrix.needs_matrix();
    // With the dynamic residual untested (003's test), an iterate that may be the last needs
    // only Φ: the elements are evaluated when the test fails (docs/dynamics.md D4).
    const bool constraints_only = expect_convergence && !std::isfinite(options.residual_tolerance);
    if (constraints_only)
      guarded([&] { evaluate_constraints_and_loads(t_next); });
    else  // the energies only where the iterate may be accepted
      guarded_evaluate(t_next, need_matrix && !expect_convergence ? &c.matrix : nullptr, c.beta_prime,
                       expect_convergence);
    if (!assembly.residual().allFinite()) {
      last_failure = "the residual is not finite";
      return false;
    }
    if (iteration > 0 && norm_squared <= options.tolerance && constraint_norm() <= options.constraint_tolerance &&
        dynamic_residual_small(c.beta_prime)) {
      last_iterations = iteration;
      return true;
    }
    if (iteration == options.max_iterations) {
      last_failure = "Newton did not converge in max_iterations";
      return false;
    }
    if (constraints_only)
      guarded_evaluate(t_next, need_matrix ? &c.matrix : nullptr, c.beta_prime, false);
    else if (need_matrix && expect_convergence)
      guarded_evaluate(t_next, &c.matrix, c.beta_prime);
    if (need_matrix && !matrix.factorize_step_matrix(assembly, model, t_next, c.h)) {
      last_failure = "the iteration matrix has a NaN or infinite entry";
      return false;
    }
    solution = -assembly.residual();
    for (int dof : model.fixed_dofs()) solution(dof) = 0.0;
    matrix.solver().solve(solution);
    ++counters.newton_iterations;
    if (!solution.allFinite()) {  // a failed iteration: the step is cut back
      last_failure = "the Newton increment is not finite";
      return false;
    }
    const auto dx = solution.head(n);
    const auto dlambda = solution.tail(m);
    increment += dx;
    state.velocity += c.gamma_prime * dx;
    state.acceleration += c.beta_prime * dx;
    state.multipliers += c.beta_prime * dlambda;
    if (!inside_chart()) return false;
    state.q.assign_increment(start.state.q, increment);
    // 003 §5.1: D = [Δq, h²β Δλ].
    const double dlambda_norm = c.h * c.h * c.beta * c.beta_prime * dlambda.norm();
    norm_squared = increment_norm_squared(dx, dlambda_norm);
    const double norm = std::sqrt(norm_squared);
    matrix.after_correction(norm, previous_norm);
    previous_norm = norm;
  }
}

/// One step of h — a user step, or what is left of it after an event, or a try of event location
/// — all or nothing: when it fails even after the cut-backs (or anything in it throws), state,
/// velocities, accelerations, multipliers, time and energy balance are restored to the step's
/// start, so no converged sub-step of it is left behind.
void GeneralizedAlpha::Implementation::whole_step(double h) {
  save(step_start);
  const long steps0 = counters.steps;
  try {
    advance(h, 0);
  } catch (...) {
    restore(step_start);
    counters.steps = steps0;
    matrix.request_refactorization();
    evaluate(state.time, nullptr, 1.0);  // the energies and residual of the restored state
    throw;
  }
}

void GeneralizedAlpha::Implementation::advance(double h, int depth) {
  // The predictor that converged last is tried first, the other one next.
  const Predictor other = (predictor == Predictor::extrapolated) ? Predictor::velocity_only : Predictor::extrapolated;
  if (try_step(h, predictor) || try_step(h, predictor = other)) {
    ++counters.steps;
    return;
  }
  if (depth >= options.max_cutbacks) {
    std::ostringstream what;
    what << "Newton did not converge at t = " << state.time + h << " (step " << counters.steps + 1 << ", h = " << h
         << ") after " << depth << " halvings of the time step; last failure: " << last_failure;
    throw Error(what.str(), "solvers::GeneralizedAlpha",
                "reduce the time step, raise max_iterations, or check the model: a diverging "
                "Newton often means an unrealistic load or an inconsistent initial state");
  }
  ++counters.cutbacks;
  advance(h / 2, depth + 1);
  advance(h / 2, depth + 1);
}

}  // namespace spar::solvers
