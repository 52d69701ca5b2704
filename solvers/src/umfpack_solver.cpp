// The UMFPACK backend: umfpack_di_symbolic once per pattern, umfpack_di_numeric per factorization,
// umfpack_di_wsolve with preallocated workspaces per solve.
#include "linear_solver_backends.hpp"

#include <umfpack.h>

#include <memory>
#include <vector>

namespace spar::solvers::detail {

namespace {

class UmfpackSolver final : public LinearSolver {
public:
  UmfpackSolver() : LinearSolver(LinearSolverKind::umfpack) {
    umfpack_di_defaults(control_);
    // No iterative refinement: it would need A at solve time, which the interface does not take
    // (and the Newton iteration around the solve corrects the same error).
    control_[UMFPACK_IRSTEP] = 0;
  }

private:
  struct SymbolicDeleter {
    void operator()(void* symbolic) const { umfpack_di_free_symbolic(&symbolic); }
  };
  struct NumericDeleter {
    void operator()(void* numeric) const { umfpack_di_free_numeric(&numeric); }
  };

  void analyze_pattern(const SparseMatrix& A) override {
    numeric_.reset();
    symbolic_.reset();
    const int n = static_cast<int>(A.rows());
    void* symbolic = nullptr;
    const int status = umfpack_di_symbolic(n, n, A.outerIndexPtr(), A.innerIndexPtr(), nullptr,
                                           &symbolic, control_, info_);
    symbolic_.reset(symbolic);
    if (status != UMFPACK_OK) throw_library_failure("umfpack_di_symbolic", status);
    right_hand_side_.resize(n);
    solve_indices_.resize(n);
    solve_work_.resize(n);  // n doubles suffice without iterative refinement
  }

  FactorizationOutcome factorize_values(const SparseMatrix& A) override {
    numeric_.reset();
    void* numeric = nullptr;
    const int status = umfpack_di_numeric(A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(),
                                          symbolic_.get(), &numeric, control_, info_);
    numeric_.reset(numeric);
    if (status == UMFPACK_WARNING_singular_matrix) {
      numeric_.reset();
      return FactorizationOutcome::singular;
    }
    // Positive statuses other than singular are determinant under/overflow warnings.
    if (status < UMFPACK_OK) throw_library_failure("umfpack_di_numeric", status);
    return FactorizationOutcome::succeeded;
  }

  void solve_in_place(Eigen::Ref<Eigen::VectorXd> b) override {
    right_hand_side_ = b;
    const int status = umfpack_di_wsolve(UMFPACK_A, nullptr, nullptr, nullptr, b.data(),
                                         right_hand_side_.data(), numeric_.get(), control_, info_,
                                         solve_indices_.data(), solve_work_.data());
    if (status != UMFPACK_OK) throw_library_failure("umfpack_di_wsolve", status);
  }

  double control_[UMFPACK_CONTROL]{};
  double info_[UMFPACK_INFO]{};
  std::unique_ptr<void, SymbolicDeleter> symbolic_;
  std::unique_ptr<void, NumericDeleter> numeric_;
  Eigen::VectorXd right_hand_side_;
  std::vector<int> solve_indices_;
  std::vector<double> solve_work_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

}  // namespace spar::solvers::detail
