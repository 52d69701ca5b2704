// The KLU backend: klu_analyze once per pattern, klu_factor for the first factorization (with
// partial pivoting), then klu_refactor, which reuses that pivot order and is several times
// cheaper, for every later matrix of the same pattern.
#include "linear_solver_backends.hpp"

#include <klu.h>

#include <memory>

namespace spar::solvers::detail {

namespace {

class KluSolver final : public LinearSolver {
public:
  KluSolver() : LinearSolver(LinearSolverKind::klu) { klu_defaults(&common_); }

private:
  struct SymbolicDeleter {
    klu_common* common;
    void operator()(klu_symbolic* symbolic) const { klu_free_symbolic(&symbolic, common); }
  };
  struct NumericDeleter {
    klu_common* common;
    void operator()(klu_numeric* numeric) const { klu_free_numeric(&numeric, common); }
  };

  void analyze_pattern(const SparseMatrix& A) override {
    numeric_.reset();
    symbolic_.reset(
        klu_analyze(static_cast<int>(A.rows()), column_starts(A), row_indices(A), &common_));
    if (!symbolic_) throw_library_failure("klu_analyze", common_.status);
  }

  FactorizationOutcome factorize_values(const SparseMatrix& A) override {
    if (numeric_) {
      // Refactorization keeps the first factorization's pivot order. If a pivot has become zero
      // or has shrunk by more than refactor_rcond_drop relative to the last pivoting
      // factorization (klu_rcond = min |U_kk| / max |U_kk|), that order is no longer stable and
      // the matrix is factorized again with pivoting.
      const bool refactored =
          klu_refactor(column_starts(A), row_indices(A), values(A), symbolic_.get(),
                       numeric_.get(), &common_) != 0;
      if (!refactored && common_.status != KLU_SINGULAR)
        throw_library_failure("klu_refactor", common_.status);
      if (refactored && klu_rcond(symbolic_.get(), numeric_.get(), &common_) &&
          common_.rcond >= refactor_rcond_drop * pivoting_rcond_)
        return FactorizationOutcome::succeeded;
      numeric_.reset();
    }
    numeric_.reset(klu_factor(column_starts(A), row_indices(A), values(A), symbolic_.get(),
                              &common_));
    if (common_.status == KLU_SINGULAR) {
      numeric_.reset();
      return FactorizationOutcome::singular;
    }
    if (!numeric_) throw_library_failure("klu_factor", common_.status);
    if (!klu_rcond(symbolic_.get(), numeric_.get(), &common_))
      throw_library_failure("klu_rcond", common_.status);
    pivoting_rcond_ = common_.rcond;
    return FactorizationOutcome::succeeded;
  }

  void solve_in_place(Eigen::Ref<Eigen::VectorXd> b) override {
    const int n = static_cast<int>(b.size());
    if (!klu_solve(symbolic_.get(), numeric_.get(), n, 1, b.data(), &common_))
      throw_library_failure("klu_solve", common_.status);
  }

  /// The factor by which the pivot ratio of a refactorization may fall below that of the last
  /// pivoting factorization before KLU pivots again: three orders of magnitude of lost accuracy.
  static constexpr double refactor_rcond_drop = 1e-3;

  klu_common common_{};
  double pivoting_rcond_ = 0.0;
  // Declared after common_, so destroyed (and freed through it) before it.
  std::unique_ptr<klu_symbolic, SymbolicDeleter> symbolic_{nullptr, SymbolicDeleter{&common_}};
  std::unique_ptr<klu_numeric, NumericDeleter> numeric_{nullptr, NumericDeleter{&common_}};
};

}  // namespace

std::unique_ptr<LinearSolver> make_klu_solver() { return std::make_unique<KluSolver>(); }

}  // namespace spar::solvers::detail
