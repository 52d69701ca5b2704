#pragma once
// Private to spar_solvers: the iteration-matrix strategies of the generalized-α Newton iterations
// (DynamicOptions::iteration_matrix; docs/dynamics.md D5) and the linear solver they keep.

#include <spar/core/model.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/linear_solver.hpp>

#include "system_assembly.hpp"

#include <memory>

namespace spar::solvers::detail {

/// When the Newton iterations assemble and factorize their iteration matrix:
/// - update: every iteration;
/// - frozen: every iteration, the rotation–rotation blocks of M, C and K those stored by
///   SystemAssembly::freeze (003 §5.1);
/// - modified: once, the factorization kept across iterations and steps until the corrections
///   contract by less than DynamicOptions::modified_newton_contraction, h changes or a step fails.
/// Owns the linear solver; counts the factorizations and J_θ evaluations in the run's counters.
class IterationMatrixStrategy {
public:
  /// `options` and `counters` are the integrator's and outlive the strategy.
  IterationMatrixStrategy(const DynamicOptions& options, DynamicCounters& counters);

  LinearSolver& solver() { return *solver_; }

  /// The linear solver's analysis of the assembly's current pattern, with the model's
  /// substructures where every iteration factorizes (docs/dynamics.md D12): modified Newton solves
  /// ~100 times per factorization, and P's two back-substitutions and two products with A per
  /// solve cost more than the whole matrix's one (the truss's cosine law, 10 s: 2.5 against 1.8 s).
  void analyze(const SystemAssembly& assembly);

  /// Whether the iterations take the rotation–rotation blocks stored by SystemAssembly::freeze.
  bool frozen() const { return options_.iteration_matrix == IterationMatrix::frozen; }
  /// The frozen strategy stores those blocks at `in`: at every (re)start of the method and after
  /// every structure change.
  void freeze(SystemAssembly& assembly, const core::ElementInput& in) const {
    if (frozen()) assembly.freeze(in);
  }

  /// A step of h starts: a factorization kept for another h is no iteration matrix of it.
  void start_step(double h) {
    if (h != factorized_step_) have_factorization_ = false;
  }
  /// Whether the next Newton iteration needs a new iteration matrix.
  bool needs_matrix() const {
    return options_.iteration_matrix != IterationMatrix::modified || !have_factorization_ || refactor_requested_;
  }
  /// Factorizes the iteration matrix just assembled for a step of h, at `time`. False, with
  /// nothing factorized, when it has a NaN or infinite entry: the iteration has failed (a
  /// non-finite tangent at an iterate is no sign of a redundant constraint).
  bool factorize_step_matrix(SystemAssembly& assembly, const core::Model& model, double time, double h);
  /// After a Newton correction of norm `norm` following one of `previous_norm`.
  void after_correction(double norm, double previous_norm) {
    if (options_.iteration_matrix == IterationMatrix::modified &&
        norm > options_.modified_newton_contraction * previous_norm)
      refactor_requested_ = true;
  }
  /// After a failed step: the next iteration factorizes anew.
  void request_refactorization() { refactor_requested_ = true; }

  /// Factorizes the assembled matrix after the Dirichlet conditions; a singular matrix is a
  /// modelling error that no smaller step repairs (spar::Error naming the step at `time` and what
  /// the model's elements say of freedoms they leave without mass).
  void factorize(SystemAssembly& assembly, const core::Model& model, double time);
  /// The factorization holds no iteration matrix: the pattern was rebuilt, or the start-up
  /// factorized [M Bᵀ; B 0].
  void invalidate() { have_factorization_ = false; }

private:
  const DynamicOptions& options_;
  DynamicCounters& counters_;
  std::unique_ptr<LinearSolver> solver_;
  bool have_factorization_ = false, refactor_requested_ = false;
  double factorized_step_ = 0.0;
};

}  // namespace spar::solvers::detail
