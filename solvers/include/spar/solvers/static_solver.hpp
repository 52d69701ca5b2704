#pragma once
/// \file
/// Nonlinear statics: Newton–Raphson with load stepping and adaptive cut-back, in the chart about
/// the last converged configuration (Cardona–Géradin; 003 eqs. 20–28), so the tangent of the
/// internal forces is symmetric. Sparse assembly on a pattern built once; the linear solver's
/// symbolic analysis is done once per run.

#include <spar/core/model.hpp>
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/error.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/solvers/linear_solver.hpp>

#include <vector>

namespace spar::solvers {

struct StaticOptions {
  int load_steps = 10;                ///< initial number of equal load increments to λ = 1
  int max_iterations = 25;            ///< Newton iterations per step before a cut-back
  double residual_tolerance = 1e-9;   ///< ‖r‖∞ ≤ tol · max(‖f_int‖∞, ‖λ f_ext‖∞) on free dofs
  double increment_tolerance = 1e-10; ///< ‖Δ‖∞ of the last Newton increment (m and rad)
  double constraint_tolerance = 1e-10; ///< ‖Φ‖∞ at convergence (constraints only)
  int max_cutbacks = 10;              ///< halvings of the load increment (which never grows back) before giving up
  LinearSolverKind linear_solver = LinearSolverKind::klu;
  /// Parallel from solvers::parallel_assembly_min_blocks elements and joints up; below, with more than
  /// one thread, serial or parallel as the faster of the two is timed during the run (bitwise the
  /// serial result either way; docs/performance.md, "Parallel assembly").
  solvers::AssemblyExecution assembly = solvers::AssemblyExecution::automatic;
};

/// One converged load step.
struct StaticStep {
  double load_factor = 0.0;
  int iterations = 0;             ///< Newton iterations (linear solves) of this step
  double residual_norm = 0.0;     ///< ‖r‖∞ at convergence
  double increment_norm = 0.0;    ///< ‖Δ‖∞ of the last increment
};

struct StaticReport {
  std::vector<StaticStep> steps;  ///< one entry per converged load step
  /// The Lagrange multipliers λ of the constraints at load factor 1 (constraint by constraint).
  Eigen::VectorXd multipliers;
  int newton_iterations = 0;  ///< over all steps, including those of failed attempts
  int cutbacks = 0;
  int factorizations = 0;
  double wall_seconds = 0.0;
  /// The stability of the final state: the number of negative eigenvalues of the tangent
  /// stiffness on the constraints' null space (docs/errors.md). 0: stable; > 0: an unstable
  /// equilibrium (e.g. a straight column above its Euler load), which a real structure leaves;
  /// -1: not assessed (moment loads, which have no potential for 3D rotations; a tangent that is
  /// not symmetric to 1e-6 of its norm; a singular one at a critical point).
  int unstable_directions = -1;
};

/// Thrown when a load step does not converge even after the allowed cut-backs. The model keeps
/// the last converged state, whose load factor this error carries.
class ConvergenceError : public Error {
public:
  ConvergenceError(std::string_view what, std::string_view where, std::string_view fix,
                   double last_converged_load_factor)
      : Error(what, where, fix), last_converged_load_factor_(last_converged_load_factor) {}
  double last_converged_load_factor() const { return last_converged_load_factor_; }

private:
  double last_converged_load_factor_;
};

/// Brings model.state() into equilibrium with the loads and gravity, both scaled by the load
/// factor, at load factor 1, subject to `constraints` (Φ(q, 0) = 0, with multipliers). Returns
/// what it did; throws ConvergenceError (model at the last converged load factor) if a step fails,
/// its message opening with "the load is too large for the model" when Newton's iterates left the
/// range of double (a tip force of 1e200 N on a steel cantilever). Every other exception from a
/// step (spar::InputError for a load history that is not finite at t = 0) also leaves the state
/// of the last converged load factor. Refuses at once a model that Model::check_consistent refuses.
StaticReport solve_static(core::Model& model, const StaticOptions& options = {},
                          const std::vector<joints::Constraint*>& constraints = {});

}  // namespace spar::solvers
