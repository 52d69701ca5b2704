// The KLU backend: klu_analyze once per pattern, klu_factor for the first factorization (with
// partial pivoting), then klu_refactor, which reuses that pivot order and is several times
// cheaper, for every later matrix of the same pattern.
//
// The fill-reducing ordering is chosen per pattern on its first matrix: AMD (KLU's default, on
// the pattern of A + Aᵀ) and COLAMD (on AᵀA) are both analyzed and factorized, and the one whose
// factorization took fewer flops is kept. Neither wins everywhere on the saddle-point matrices of
// constrained dynamics: the zero diagonal of the multipliers forces off-diagonal pivots that AMD
// cannot foresee. On the slider-crank AMD is 2.6 % cheaper than COLAMD (callgrind,
// docs/performance.md). With substructures given (LinearSolver::set_substructures), a third
// candidate is the substructured factorization of substructuring.hpp, kept when it needs less
// than half the flops of the better whole-matrix ordering (its solves refine against A, one to
// three extra back-substitutions): on the truss unit, 7 times fewer (docs/dynamics.md D12). When
// the substructured matrix is singular or the refinement does not reach its target
// (LinearSolver::refinement_target), that matrix is factorized as a whole; after three such
// failures in a row, the rest of the pattern too.
#include "linear_solver_backends.hpp"
#include "substructuring.hpp"

#include <spar/error.hpp>

#include <klu.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace spar::solvers::detail {

namespace {

class KluSolver final : public LinearSolver {
public:
  KluSolver() : LinearSolver(LinearSolverKind::klu) { klu_defaults(&common_); }

  bool substructured() const noexcept override {
    return mode_ == Mode::substructured && !whole_this_matrix_;
  }

private:
  struct SymbolicDeleter {
    klu_common* common;
    void operator()(klu_symbolic* symbolic) const { klu_free_symbolic(&symbolic, common); }
  };
  struct NumericDeleter {
    klu_common* common;
    void operator()(klu_numeric* numeric) const { klu_free_numeric(&numeric, common); }
  };
  using Symbolic = std::unique_ptr<klu_symbolic, SymbolicDeleter>;
  using Numeric = std::unique_ptr<klu_numeric, NumericDeleter>;

  /// A compressed-column matrix as KLU takes it.
  struct Columns {
    int* starts;
    int* rows;
    double* values;
  };

  /// One way of factorizing the pattern: its symbolic analysis, its last numeric factorization and
  /// the pivot ratio (klu_rcond = min |U_kk| / max |U_kk|) of its last pivoting factorization.
  struct Factorization {
    Factorization(klu_common* common, double tolerance, int scaling)
        : symbolic(nullptr, {common}), numeric(nullptr, {common}), pivot_tolerance(tolerance),
          row_scaling(scaling) {}
    Symbolic symbolic;
    Numeric numeric;
    double pivoting_rcond = 0.0;
    /// KLU's partial pivoting keeps the diagonal while |a_kk| ≥ this · the column's largest entry.
    double pivot_tolerance;
    /// klu_common::scale of the pivoting factorization: 2 divides each row by its largest entry
    /// for the choice of pivots; −1 does not scale. Refactorizations never scale (factorize_with).
    int row_scaling;
  };

  /// undecided: the pattern's first factorization chooses; whole: A with the better of AMD and
  /// COLAMD; substructured: P (substructuring.hpp) and refinement against A.
  enum class Mode { undecided, whole, substructured };

  void analyze_pattern(const SparseMatrix& A) override {
    const int n = static_cast<int>(A.rows());
    mode_ = Mode::undecided;
    whole_this_matrix_ = false;
    failures_ = 0;
    whole_.numeric.reset();
    whole_.symbolic.reset();
    substructured_.numeric.reset();
    substructured_.symbolic.reset();
    for (int ordering : {amd, colamd}) {
      candidates_[ordering].numeric.reset();
      common_.ordering = ordering;
      candidates_[ordering].symbolic.reset(
          klu_analyze(n, column_starts(A), row_indices(A), &common_));
      if (!candidates_[ordering].symbolic) throw_library_failure("klu_analyze", common_.status);
    }
    if (substructures().empty()) return;
    pattern_ = substructured_pattern(A, substructures());
    // The given ordering as it is: no block triangular form (P is irreducible but for the fixed
    // dofs) and the same permutation for rows and columns, so that the diagonal stays preferred.
    common_.btf = 0;
    substructured_.symbolic.reset(klu_analyze_given(n, pattern_.column_starts.data(),
                                                    pattern_.row_indices.data(),
                                                    pattern_.ordering.data(),
                                                    pattern_.ordering.data(), &common_));
    common_.btf = 1;
    if (!substructured_.symbolic) throw_library_failure("klu_analyze_given", common_.status);
    system_ = A;
    system_rows_ = row_order(A);
    preconditioner_values_.resize(pattern_.source.size());
  }

  FactorizationOutcome factorize_values(const SparseMatrix& A) override {
    if (substructured_.symbolic && mode_ != Mode::whole) {
      std::copy(A.valuePtr(), A.valuePtr() + A.nonZeros(), system_.valuePtr());
      for (std::size_t k = 0; k < pattern_.source.size(); ++k)
        preconditioner_values_[k] = system_.valuePtr()[pattern_.source[k]];
      row_scale_stale_ = true;
    }
    if (mode_ == Mode::undecided) return factorize_choosing_method(A);
    if (mode_ == Mode::substructured) {
      whole_this_matrix_ = false;
      if (factorize_with(preconditioner(), substructured_) == FactorizationOutcome::succeeded)
        return FactorizationOutcome::succeeded;
      note_failure();  // P is singular (a body held only through a dropped coupling)
    }
    return factorize_with(whole(A), whole_);
  }

  void solve_in_place(Eigen::Ref<Eigen::VectorXd> b) override {
    if (mode_ != Mode::substructured || whole_this_matrix_) {
      back_substitute(whole_, b);
      return;
    }
    right_hand_side_ = b;
    back_substitute(substructured_, b);
    if (pattern_.dropped == 0 || refined(b)) {
      failures_ = 0;
      return;
    }
    // The dropped couplings are too strong for the refinement (seen at a diverging Newton iterate
    // of the linear law, which the step's cut-back then left): A as a whole for this matrix.
    note_failure();
    if (factorize_with(whole(system_), whole_) == FactorizationOutcome::singular)
      throw Error("numerically singular iteration matrix — check for a redundant constraint or an "
                  "unconstrained rigid-body mode",
                  "solvers::LinearSolver::solve (klu)",
                  "remove the redundant constraint or add the support that fixes the free motion");
    b = right_hand_side_;
    back_substitute(whole_, b);
  }

  /// The current matrix goes as a whole; after max_substructured_failures failures in a row, every
  /// later one of the pattern too.
  void note_failure() {
    whole_this_matrix_ = true;
    if (++failures_ >= max_substructured_failures) mode_ = Mode::whole;
  }

  /// The first factorization of a pattern, by each candidate method: keeps the cheapest (the
  /// substructured one only when it takes less than half the flops of the better ordering of A,
  /// its refinement costing one or two more solves, or always when so asked). When nothing
  /// factorizes (a singular matrix), mode_ stays undecided and the candidates wait for the
  /// pattern's next matrix.
  FactorizationOutcome factorize_choosing_method(const SparseMatrix& A) {
    double best_flops = INFINITY;
    int status = KLU_OK;
    for (int ordering : {amd, colamd}) {
      Factorization& candidate = candidates_[ordering];
      if (factorize_with(whole(A), candidate) == FactorizationOutcome::singular ||
          !klu_flops(candidate.symbolic.get(), candidate.numeric.get(), &common_)) {
        status = common_.status;
        continue;
      }
      if (common_.flops < best_flops) {
        best_flops = common_.flops;
        std::swap(whole_, candidate);
      }
    }
    if (substructured_.symbolic &&
        factorize_with(preconditioner(), substructured_) == FactorizationOutcome::succeeded &&
        klu_flops(substructured_.symbolic.get(), substructured_.numeric.get(), &common_) &&
        (substructuring() == Substructuring::always ||
         common_.flops < (pattern_.dropped > 0 ? substructured_flop_share : 1.0) * best_flops)) {
      mode_ = Mode::substructured;
    } else if (whole_.numeric) {
      mode_ = Mode::whole;
      substructured_.numeric.reset();
    } else {
      common_.status = status;
      return FactorizationOutcome::singular;
    }
    for (Factorization& candidate : candidates_) candidate.numeric.reset();
    common_.status = KLU_OK;
    return FactorizationOutcome::succeeded;
  }

  /// Refactorizes with the kept pivot order; factorizes with pivoting when there is none, a pivot
  /// has become zero, or the pivot ratio has fallen by more than refactor_rcond_drop against the
  /// last pivoting factorization (that order is then no longer stable).
  ///
  /// The pivot order is chosen on the row-scaled matrix (f.row_scaling), but every factorization
  /// kept for solving is unscaled: with the permutations fixed, the LU of R A (R diagonal) is R
  /// times that of A's rows, so scaling changes the factors by rounding only, while KLU's pass that
  /// computes R and divides every entry by it was 6 % of a slider-crank run in `update`. A pivoting
  /// factorization is therefore followed by an unscaled refactorization of the same matrix, which
  /// also gives the pivot ratio the later, unscaled refactorizations are compared with.
  FactorizationOutcome factorize_with(const Columns& M, Factorization& f) {
    if (f.numeric) {
      if (refactor_unscaled(M, f) && common_.rcond >= refactor_rcond_drop * f.pivoting_rcond)
        return FactorizationOutcome::succeeded;
      f.numeric.reset();
    }
    common_.scale = f.row_scaling;
    common_.tol = f.pivot_tolerance;
    f.numeric.reset(klu_factor(M.starts, M.rows, M.values, f.symbolic.get(), &common_));
    if (common_.status == KLU_SINGULAR) {
      f.numeric.reset();
      return FactorizationOutcome::singular;
    }
    if (!f.numeric) throw_library_failure("klu_factor", common_.status);
    if (f.row_scaling == unscaled) {
      if (!klu_rcond(f.symbolic.get(), f.numeric.get(), &common_))
        throw_library_failure("klu_rcond", common_.status);
    } else if (!refactor_unscaled(M, f)) {  // a pivot that scaling kept above zero underflowed
      f.numeric.reset();
      return FactorizationOutcome::singular;
    }
    f.pivoting_rcond = common_.rcond;
    return FactorizationOutcome::succeeded;
  }

  /// klu_refactor without row scaling, then its pivot ratio into common_.rcond; false when a
  /// pivot is zero.
  bool refactor_unscaled(const Columns& M, Factorization& f) {
    common_.scale = unscaled;
    if (!klu_refactor(M.starts, M.rows, M.values, f.symbolic.get(), f.numeric.get(), &common_)) {
      if (common_.status != KLU_SINGULAR) throw_library_failure("klu_refactor", common_.status);
      return false;
    }
    if (!klu_rcond(f.symbolic.get(), f.numeric.get(), &common_))
      throw_library_failure("klu_rcond", common_.status);
    return true;
  }

  void back_substitute(Factorization& f, Eigen::Ref<Eigen::VectorXd> b) {
    const int n = static_cast<int>(b.size());
    if (!klu_solve(f.symbolic.get(), f.numeric.get(), n, 1, b.data(), &common_))
      throw_library_failure("klu_solve", common_.status);
  }

  /// Iterative refinement of x (P⁻¹ b on entry) against A = system_: x ← x + P⁻¹(b − A x) until
  /// the backward error reaches refinement_target(), or after max_refinement_sweeps, or when a
  /// sweep no longer halves it. True when it ends below the target or, stalled, below
  /// trusted_backward_error. The rows' scales are measured in the first pass after a
  /// factorization.
  bool refined(Eigen::Ref<Eigen::VectorXd> x) {
    double previous = INFINITY;
    for (int sweep = 0;; ++sweep) {
      const double omega = residual_and_backward_error(system_, system_rows_, x, right_hand_side_, correction_,
                                                       row_scale_, row_scale_stale_);
      row_scale_stale_ = false;
      if (omega <= refinement_target()) return true;
      if (sweep == max_refinement_sweeps || !(omega < 0.5 * previous))
        return omega <= trusted_backward_error;
      back_substitute(substructured_, correction_);
      x += correction_;
      previous = omega;
    }
  }

  static Columns whole(const SparseMatrix& A) {
    return {column_starts(A), row_indices(A), values(A)};
  }
  Columns preconditioner() {
    return {pattern_.column_starts.data(), pattern_.row_indices.data(),
            preconditioner_values_.data()};
  }

  /// The factor by which the pivot ratio of a refactorization may fall below that of the last
  /// pivoting factorization before KLU pivots again: three orders of magnitude of lost accuracy.
  static constexpr double refactor_rcond_drop = 1e-3;
  /// KLU's default threshold for A as a whole.
  static constexpr double whole_pivot_tolerance = 1e-3;
  /// On P, the interface's diagonal (the dual Schur complement, small against the couplings of a
  /// sliding joint's ζ) is kept unless a million times smaller than its column: with KLU's 1e-3,
  /// more pivots go off the diagonal and the truss unit takes 0.67 against 0.64 Mflop (with the
  /// boundaries eliminated before the interface, 88 of its 208 interface pivots did, 2.1 against
  /// 1.3 Mflop). The refinement against A and the pivot-ratio test of every refactorization guard
  /// the accuracy.
  static constexpr double substructured_pivot_tolerance = 1e-6;
  /// klu_common::scale: no scaling (and no check of the matrix, which the pattern guarantees).
  static constexpr int unscaled = -1;
  /// KLU's default row scaling for A as a whole (each row by its largest entry), for the pivot
  /// choice only (factorize_with).
  static constexpr int whole_row_scaling = 2;
  /// P unscaled: KLU's scaling pass over the matrix at every refactorization was 5 % of the truss
  /// unit's run; unscaled, the run takes 8 % less with the same iterates (its pivot choices may
  /// differ from a scaled P's; the refinement against A and the pivot-ratio test of every
  /// refactorization hold the accuracy either way).
  static constexpr int substructured_row_scaling = unscaled;
  /// The substructured factorization is kept when its flops are below this share of A's.
  static constexpr double substructured_flop_share = 0.5;
  /// A refinement that stalls (a sweep no longer halves the error) is trusted below this, 450 unit
  /// round-offs; above it the couplings P leaves out are too strong, and the matrix is factorized
  /// as a whole.
  static constexpr double trusted_backward_error = 1e-13;
  static constexpr int max_refinement_sweeps = 10;
  /// Substructuring is given up for the pattern after this many failures in a row (P singular or
  /// the refinement stalling above trusted_backward_error), each of which cost a factorization of P,
  /// the sweeps and a factorization of A.
  static constexpr int max_substructured_failures = 3;

  static constexpr int amd = 0, colamd = 1;  // klu_common::ordering

  klu_common common_{};
  Mode mode_ = Mode::undecided;
  /// The current matrix was factorized as a whole after a failure of substructuring.
  bool whole_this_matrix_ = false;
  /// Failures of substructuring in a row.
  int failures_ = 0;
  // Declared after common_, so destroyed (and freed through it) before it.
  Factorization whole_{&common_, whole_pivot_tolerance, whole_row_scaling};
  Factorization substructured_{&common_, substructured_pivot_tolerance, substructured_row_scaling};
  std::array<Factorization, 2> candidates_{
      Factorization{&common_, whole_pivot_tolerance, whole_row_scaling},
      Factorization{&common_, whole_pivot_tolerance, whole_row_scaling}};
  SubstructuredPattern pattern_;
  /// A's pattern and the values of its last factorization (the refinement's residual).
  SparseMatrix system_;
  RowOrder system_rows_;  ///< system_'s entries row by row, for the refinement's residual
  std::vector<double> preconditioner_values_;
  Eigen::VectorXd row_scale_, right_hand_side_, correction_;
  /// row_scale_ is that of the last matrix but one (a factorization since).
  bool row_scale_stale_ = true;
};

}  // namespace

std::unique_ptr<LinearSolver> make_klu_solver() { return std::make_unique<KluSolver>(); }

}  // namespace spar::solvers::detail
