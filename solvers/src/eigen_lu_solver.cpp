// The Eigen backend: SparseLU (supernodal LU with partial pivoting) under a COLAMD ordering.
#include "linear_solver_backends.hpp"

#include <Eigen/SparseLU>

#include <memory>

namespace spar::solvers::detail {

namespace {

class EigenLuSolver final : public LinearSolver {
public:
  EigenLuSolver() : LinearSolver(LinearSolverKind::eigen_lu) {}

private:
  void analyze_pattern(const SparseMatrix& A) override {
    lu_.analyzePattern(A);
    right_hand_side_.resize(A.rows());
  }

  FactorizationOutcome factorize_values(const SparseMatrix& A) override {
    lu_.factorize(A);
    if (lu_.info() == Eigen::NumericalIssue) return FactorizationOutcome::singular;
    if (lu_.info() != Eigen::Success)
      throw_library_failure("Eigen::SparseLU::factorize", static_cast<int>(lu_.info()));
    return FactorizationOutcome::succeeded;
  }

  void solve_in_place(Eigen::Ref<Eigen::VectorXd> b) override {
    right_hand_side_ = b;
    b = lu_.solve(right_hand_side_);
  }

  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  Eigen::VectorXd right_hand_side_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_eigen_lu_solver() { return std::make_unique<EigenLuSolver>(); }

}  // namespace spar::solvers::detail
