#pragma once
/// \file
/// Natural frequencies and mode shapes of a model linearized about its current configuration,
/// with constraints in the null-space form (docs/dynamics.md D11).

#include <spar/core/model.hpp>
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::solvers {

struct ModalOptions {
  int modes = 10;  ///< the lowest this many (fewer when the constrained model has fewer freedoms)
  /// Parallel from solvers::parallel_assembly_min_blocks elements and joints up; below, with more than
  /// one thread, serial or parallel as the faster of the two is timed during the run (bitwise the
  /// serial result either way; docs/performance.md, "Parallel assembly").
  solvers::AssemblyExecution assembly = solvers::AssemblyExecution::automatic;
};

/// The modes, lowest first.
struct Modes {
  /// ω [rad/s], ascending; a negative entry is −√|λ| of a negative eigenvalue (an unstable
  /// linearization, e.g. about a state that is not an equilibrium).
  Eigen::VectorXd angular_frequencies;
  /// Mode shapes, one per column, in the global tangent layout (Δx inertial, Δφ material),
  /// mass-normalized (φᵀ M φ = 1), zero on fixed dofs, satisfying B φ = 0.
  Eigen::MatrixXd shapes;
  /// f = ω/2π [Hz].
  Eigen::VectorXd frequencies() const;
};

/// Linearizes M Δ̈ + K Δ = 0, B Δ = 0 about the model's current state (velocities zero) and solves
/// K φ = ω² M φ on the null space of B: with N an orthonormal basis of the free dofs' null space
/// (Householder QR of Bᵀ; redundant constraints are dropped by its rank),
/// (Nᵀ K N) y = ω² (Nᵀ M N) y, φ = N y. K includes the constraints' K_λ = ∂(Bᵀλ)/∂Δ with the given
/// multipliers (e.g. StaticReport::multipliers after solve_static; zero when empty). Its symmetric
/// part is used: K is symmetric at an unstressed reference and at equilibria of conservative loads
/// in the limit of the converged chart, and its skew part is reported nowhere else. Dense: for
/// models of up to a few thousand dofs. spar::Error when Nᵀ M N is not positive definite (a freedom
/// without mass: a beam without section inertia, a massless coordinate left free).
Modes modal_analysis(core::Model& model, const std::vector<joints::Constraint*>& constraints = {},
                     const ModalOptions& options = {}, const Eigen::VectorXd& multipliers = {});

}  // namespace spar::solvers
