#pragma once
// Private to spar_solvers: the one place where the elements and constraints of a model are
// evaluated and gathered into the global residual and iteration matrix, for statics and dynamics
// alike (docs/model.md, "Assembly"). Every load, gravity and inertia reaches both solvers by this
// path.

#include <spar/core/element.hpp>
#include <spar/core/model.hpp>
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/joints/constraint.hpp>

#include "execution_choice.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace spar::solvers::detail {

/// Coefficients of one assembly of the iteration matrix: c_M M + c_C C + c_K (K + K_λ) T.
struct MatrixCoefficients {
  double mass = 1.0, damping = 0.0, stiffness = 0.0;
};

/// How element and constraint derivatives, taken in local increments q ⊕ Δ, become derivatives in
/// the Newton unknowns.
enum class Chart {
  /// Dynamics (Brüls et al. 2012): the unknown is the step's increment; K and B are
  /// right-multiplied by T(increment) on frame rotation columns (docs/model.md eq. M3).
  local_increment,
  /// Statics (Cardona–Géradin): the converged chart, forces pulled back with T(φ)ᵀ and the
  /// tangent made symmetric (core/converged_chart.hpp).
  converged,
};

/// The model's energies summed over its elements.
struct SummedEnergies {
  double kinetic = 0.0, strain = 0.0, gravity = 0.0;
};

class SystemAssembly {
public:
  SystemAssembly(core::Model& model, std::vector<joints::Constraint*> constraints,
                 solvers::AssemblyExecution execution);

  /// Re-reads the model's elements and blocks and the constraints' blocks and equation counts;
  /// rebuilds the sparse pattern. The caller re-analyzes its linear solver.
  void rebuild();

  int dof_count() const { return dof_count_; }
  int multiplier_count() const { return multiplier_count_; }
  int size() const { return dof_count_ + multiplier_count_; }
  /// The first multiplier of constraint ci.
  int first_multiplier(int ci) const { return constraint_work_[ci].first_multiplier; }
  /// For substructuring (LinearSolver::set_substructures): per unknown, the substructure of its
  /// block — blocks joined by elements form one (a beam, a rigid body) —, interface_unknown for
  /// the multipliers and the blocks no element holds (a sliding joint's ζ), fixed_unknown for the
  /// model's fixed dofs (whose rows and columns the Dirichlet conditions empty).
  const std::vector<int>& substructures() const { return substructures_; }
  solvers::SparsePattern& pattern() { return *pattern_; }
  const solvers::SparsePattern& pattern() const { return *pattern_; }

  /// Evaluates every element at `in` and every constraint at (in.q, in.time, λ) and gathers
  ///   residual = [Σ_e r_e + Σ_c Bᵀλ ; Φ]  (size() entries, in the chart's rows),
  ///   scale    = Σ |terms| per dynamic row (what "small" means for each row),
  /// and, when `c` is given, assembles c_M M + c_C C + c_K (K + K_λ) and B into the pattern, mapped
  /// to the chart's unknowns with `increment` (the step's increment or the converged chart φ).
  /// With `use_frozen`, the rotation–rotation blocks of frames are those stored by freeze().
  /// An element's or joint's spar::Error propagates (after every thread has finished).
  /// A residual-only evaluation also gathers the energies and external forces unless
  /// `with_energies` is false (an iterate that is not going to be accepted).
  void evaluate(const core::ElementInput& in, const Eigen::VectorXd& lambda,
                const MatrixCoefficients* c, Chart chart, const Eigen::VectorXd& increment,
                bool use_frozen, bool with_energies = true);

  /// What a Newton test that leaves the dynamic residual untested needs at an iterate, at a
  /// fraction of evaluate()'s cost: every constraint (Φ into residual()'s multiplier rows, Bᵀλ
  /// into constraint_force()) and the elements whose work the energy balance books (Element::
  /// has_external_force and has_dissipation, into external_force() and dissipative_force()).
  /// residual()'s dynamic rows, scale() and
  /// energies() keep their values of the last evaluate(): stale for this state.
  void evaluate_constraints_and_loads(const core::ElementInput& in, const Eigen::VectorXd& lambda,
                                      const Eigen::VectorXd& increment);

  /// The elements' energies, external and dissipative forces at `in` (energies(), external_force(),
  /// dissipative_force()), and
  /// nothing else: each element is asked for its energy alone (ElementRequest::residual false).
  void evaluate_energies(const core::ElementInput& in);

  /// Stores each element's rotation–rotation blocks of M, C and K at `in` (003's frozen matrix).
  void freeze(const core::ElementInput& in);

  const Eigen::VectorXd& residual() const { return residual_; }
  Eigen::VectorXd& residual() { return residual_; }
  const Eigen::VectorXd& scale() const { return scale_; }
  /// The energies of the last residual-only evaluate() (elements compute them only there).
  SummedEnergies energies() const;
  /// The external force of the elements' non-potential loads at the last residual-only
  /// evaluate() (global tangent layout, dof_count() entries).
  const Eigen::VectorXd& external_force() const { return external_force_; }
  /// The dissipative force of the elements that have one (Element::has_dissipation), at the same
  /// evaluation as external_force().
  const Eigen::VectorXd& dissipative_force() const { return dissipative_force_; }
  /// Σ Bᵀλ of the constraints at the last evaluate() (global tangent layout): the constraint
  /// forces on the blocks are its negative.
  const Eigen::VectorXd& constraint_force() const { return constraint_force_; }
  /// Adds constraint ci's Bᵀλ of the last evaluation to `force` (global tangent layout).
  void add_constraint_force(int ci, Eigen::VectorXd& force) const {
    const ConstraintWork& w = constraint_work_[static_cast<std::size_t>(ci)];
    for (std::size_t i = 0; i < w.dofs.size(); ++i) force(w.dofs[i]) += w.force(static_cast<Eigen::Index>(i));
  }
  /// The constraints given to the constructor, in the order of their multipliers.
  const std::vector<joints::Constraint*>& constraints() const { return constraints_; }

private:
  struct ElementWork {
    std::vector<int> dofs;
    core::ElementOutput output;
    /// Frozen rotation–rotation entries (mass, damping, stiffness), full-size element matrices.
    Eigen::MatrixXd frozen_mass, frozen_damping, frozen_stiffness;
  };
  struct ConstraintWork {
    std::vector<int> dofs;
    int first_multiplier = 0;
    Eigen::VectorXd value;
    Eigen::MatrixXd jacobian;
    Eigen::VectorXd force;               // Bᵀλ
    Eigen::MatrixXd multiplier_tangent;  // ∂(Bᵀλ)/∂Δ (scratch)
    Eigen::MatrixXd mapped_jacobian;     // B T (scratch)
  };

  void compute_element(int id, const core::ElementInput& in, const MatrixCoefficients* c,
                       Chart chart, const Eigen::VectorXd& increment, bool use_frozen,
                       Eigen::MatrixXd* K, bool with_energies = true);
  void compute_constraint(int ci, const core::ElementInput& in, const Eigen::VectorXd& lambda,
                          const MatrixCoefficients* c, Chart chart,
                          const Eigen::VectorXd& increment, Eigen::MatrixXd* K);

  /// Adds a constraint's Bᵀλ to the dynamic rows of residual_ (with `with_residual`) and to
  /// constraint_force_, and writes its Φ into its multiplier rows.
  void gather_constraint(const ConstraintWork& w, bool with_residual);
  /// Fills substructures_ from the elements' blocks.
  void find_substructures();

  core::Model& model_;
  std::vector<joints::Constraint*> constraints_;
  solvers::AssemblyExecution execution_;
  /// For `automatic` below solvers::parallel_assembly_min_blocks: serial or parallel as timed, for
  /// the evaluations with a matrix and for those of the residual alone.
  ExecutionChoice matrix_execution_, residual_execution_;
  int dof_count_ = 0, multiplier_count_ = 0;
  std::vector<ElementWork> element_work_;
  std::vector<ConstraintWork> constraint_work_;
  /// The elements whose work the energy balance books: external forces (Element::
  /// has_external_force) or dissipative ones (has_dissipation).
  std::vector<int> work_elements_;
  std::unique_ptr<solvers::SparsePattern> pattern_;
  std::vector<int> substructures_;
  Eigen::VectorXd residual_, scale_, external_force_, dissipative_force_, constraint_force_;
};

}  // namespace spar::solvers::detail
