// The KLU backend: klu_analyze once per pattern, klu_factor for the first factorization (with
// partial pivoting), then klu_refactor, which reuses that pivot order and is several times
// cheaper, for every later matrix of the same pattern.
//
// The fill-reducing ordering is chosen per pattern on its first matrix: AMD (KLU's default, on
// the pattern of A + Aᵀ) and COLAMD (on AᵀA) are both analyzed and factorized, and the one whose
// factorization took fewer flops is kept. Neither wins everywhere on the saddle-point matrices of
// constrained dynamics: the zero diagonal of the multipliers forces off-diagonal pivots that AMD
// cannot foresee. On the truss unit (1 216 unknowns) COLAMD needs 27 % fewer instructions per
// step; on the slider-crank AMD is 2.6 % cheaper (callgrind, docs/performance.md).
#include "linear_solver_backends.hpp"

#include <klu.h>

#include <array>
#include <cmath>
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
    for (int ordering : {amd, colamd}) {
      common_.ordering = ordering;
      candidates_[ordering].reset(
          klu_analyze(static_cast<int>(A.rows()), column_starts(A), row_indices(A), &common_));
      if (!candidates_[ordering]) throw_library_failure("klu_analyze", common_.status);
    }
    symbolic_.reset();
  }

  /// The first factorization of a pattern, with each candidate ordering: keeps the cheaper
  /// ordering and its factorization. When neither factorizes (a singular matrix) numeric_ stays
  /// empty, common_.status says why, and both candidates wait for the pattern's next matrix.
  void factorize_choosing_ordering(const SparseMatrix& A) {
    double best_flops = INFINITY;
    int status = KLU_OK;
    for (int ordering : {amd, colamd}) {
      std::unique_ptr<klu_numeric, NumericDeleter> numeric(
          klu_factor(column_starts(A), row_indices(A), values(A), candidates_[ordering].get(), &common_),
          NumericDeleter{&common_});
      status = common_.status;
      if (!numeric || !klu_flops(candidates_[ordering].get(), numeric.get(), &common_)) continue;
      if (common_.flops < best_flops) {
        best_flops = common_.flops;
        symbolic_ = std::move(candidates_[ordering]);
        numeric_ = std::move(numeric);
      }
    }
    if (!numeric_) {
      common_.status = status;
      return;
    }
    for (auto& candidate : candidates_) candidate.reset();
    common_.status = KLU_OK;
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
    if (symbolic_)
      numeric_.reset(klu_factor(column_starts(A), row_indices(A), values(A), symbolic_.get(), &common_));
    else
      factorize_choosing_ordering(A);
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

  static constexpr int amd = 0, colamd = 1;  // klu_common::ordering

  klu_common common_{};
  double pivoting_rcond_ = 0.0;
  // Declared after common_, so destroyed (and freed through it) before it.
  std::unique_ptr<klu_symbolic, SymbolicDeleter> symbolic_{nullptr, SymbolicDeleter{&common_}};
  std::array<std::unique_ptr<klu_symbolic, SymbolicDeleter>, 2> candidates_{
      std::unique_ptr<klu_symbolic, SymbolicDeleter>{nullptr, SymbolicDeleter{&common_}},
      std::unique_ptr<klu_symbolic, SymbolicDeleter>{nullptr, SymbolicDeleter{&common_}}};
  std::unique_ptr<klu_numeric, NumericDeleter> numeric_{nullptr, NumericDeleter{&common_}};
};

}  // namespace

std::unique_ptr<LinearSolver> make_klu_solver() { return std::make_unique<KluSolver>(); }

}  // namespace spar::solvers::detail
