#include <spar/solvers/linear_solver.hpp>

#include <spar/error.hpp>

#include "finite_values.hpp"
#include "linear_solver_backends.hpp"

#include <btf.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace spar::solvers {

namespace {

constexpr std::string_view valid_names = "\"klu\", \"umfpack\", \"eigen-lu\"";

/// The structural rank of a square compressed column matrix: the size of a maximum matching of
/// rows to columns (Duff's maximum transversal, BTF's btf_maxtrans).
int structural_rank(const SparseMatrix& A) {
  const int n = static_cast<int>(A.cols());
  std::vector<int> match(n);
  std::vector<int> work(5 * static_cast<std::size_t>(n));
  double work_done = 0.0;
  return btf_maxtrans(n, n, const_cast<int*>(A.outerIndexPtr()),
                      const_cast<int*>(A.innerIndexPtr()), 0.0, &work_done, match.data(),
                      work.data());
}

}  // namespace

LinearSolverKind linear_solver_kind_from_string(std::string_view name) {
  for (LinearSolverKind kind :
       {LinearSolverKind::klu, LinearSolverKind::umfpack, LinearSolverKind::eigen_lu})
    if (name == to_string(kind)) return kind;
  throw Error("unknown linear solver \"" + std::string(name) + "\"",
              "solvers::linear_solver_kind_from_string",
              "use one of " + std::string(valid_names));
}

std::string_view to_string(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::klu: return "klu";
    case LinearSolverKind::umfpack: return "umfpack";
    case LinearSolverKind::eigen_lu: return "eigen-lu";
  }
  return "unknown";
}

std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::klu: return detail::make_klu_solver();
    case LinearSolverKind::umfpack: return detail::make_umfpack_solver();
    case LinearSolverKind::eigen_lu: return detail::make_eigen_lu_solver();
  }
  throw Error("invalid LinearSolverKind value " + std::to_string(static_cast<int>(kind)),
              "solvers::make_linear_solver", "pass one of the enumerators of LinearSolverKind");
}

std::string LinearSolver::where(std::string_view operation) const {
  return "solvers::LinearSolver::" + std::string(operation) + " (" + std::string(to_string(kind_)) +
         ")";
}

void LinearSolver::check_square_compressed(const SparseMatrix& A,
                                           std::string_view operation) const {
  if (A.rows() != A.cols())
    throw Error("matrix is " + std::to_string(A.rows()) + " × " + std::to_string(A.cols()) +
                    ", not square",
                where(operation), "pass the square iteration matrix");
  if (A.rows() == 0)
    throw Error("matrix is empty (0 × 0)", where(operation), "assemble the system first");
  if (!A.isCompressed())
    throw Error("matrix is not in compressed form", where(operation),
                "call makeCompressed() on it, or assemble it with solvers::SparsePattern");
}

void LinearSolver::analyze(const SparseMatrix& A) {
  check_square_compressed(A, "analyze");
  analyzed_ = false;
  factorized_ = false;
  const int n = static_cast<int>(A.rows());
  if (!substructures_.empty() && static_cast<int>(substructures_.size()) != n)
    throw Error("substructures were given for " + std::to_string(substructures_.size()) +
                    " unknowns, the matrix has " + std::to_string(n),
                where("analyze"), "call set_substructures again for the new system (or with {})");
  for (std::size_t i = 0; i < substructures_.size(); ++i)
    if (substructures_[i] < fixed_unknown)
      throw Error("unknown " + std::to_string(i) + " has the substructure id " +
                      std::to_string(substructures_[i]),
                  where("analyze"),
                  "give a substructure id ≥ 0, interface_unknown (−1) or fixed_unknown (−2)");
  if (const int rank = structural_rank(A); rank < n)
    throw Error("structurally singular iteration matrix (structural rank " +
                    std::to_string(rank) + " of " + std::to_string(n) +
                    ": some rows cannot be matched to columns, e.g. an empty row or column)",
                where("analyze"),
                "check for a redundant constraint or an unconstrained rigid-body mode, and that "
                "every dof appears in some element or constraint");
  analyze_pattern(A);
  analyzed_column_starts_.assign(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
  analyzed_row_indices_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  analyzed_ = true;
  ++analyses_;
}

void LinearSolver::factorize(const SparseMatrix& A) {
  if (!analyzed_)
    throw Error("factorize called before analyze", where("factorize"),
                "call analyze(A) once for the sparsity pattern first");
  check_square_compressed(A, "factorize");
  const int n = static_cast<int>(analyzed_column_starts_.size()) - 1;
  if (A.rows() != n)
    throw Error("size mismatch: matrix is " + std::to_string(A.rows()) + " × " +
                    std::to_string(A.cols()) + ", the analyzed one " + std::to_string(n) + " × " +
                    std::to_string(n),
                where("factorize"), "call analyze(A) again for a system of a new size");
  if (!std::equal(analyzed_column_starts_.begin(), analyzed_column_starts_.end(),
                  A.outerIndexPtr()) ||
      !std::equal(analyzed_row_indices_.begin(), analyzed_row_indices_.end(), A.innerIndexPtr()))
    throw Error("sparsity pattern differs from the analyzed one", where("factorize"),
                "call analyze(A) again after a change of pattern");
  factorized_ = false;
  // KLU factorizes a NaN matrix and solves to NaN; every backend refuses it here, naming the entry.
  if (!detail::all_finite(A.valuePtr(), A.nonZeros()))
    for (int column = 0; column < n; ++column)
      for (SparseMatrix::InnerIterator entry(A, column); entry; ++entry)
        if (!std::isfinite(entry.value()))
          throw Error("the matrix has the non-finite entry " + significant(entry.value()) + " at (" +
                          std::to_string(entry.row()) + ", " + std::to_string(column) + ")",
                      where("factorize"), "check the model: an element or a constraint gave a NaN or infinite tangent");
  if (factorize_values(A) == FactorizationOutcome::singular)
    throw Error(
        "numerically singular iteration matrix — check for a redundant constraint or an "
        "unconstrained rigid-body mode",
        where("factorize"),
        "remove the redundant constraint or add the support that fixes the free motion");
  factorized_ = true;
  ++factorizations_;
}

void LinearSolver::solve(Eigen::Ref<Eigen::VectorXd> b) {
  if (!factorized_)
    throw Error(analyzed_ ? "solve called without a successful factorization"
                          : "solve called before analyze and factorize",
                where("solve"), "call analyze(A) and factorize(A) first");
  const Eigen::Index n = static_cast<Eigen::Index>(analyzed_column_starts_.size()) - 1;
  if (b.size() != n)
    throw Error("size mismatch: right-hand side has " + std::to_string(b.size()) +
                    " entries, the matrix " + std::to_string(n) + " rows",
                where("solve"), "pass a right-hand side of the factorized system");
  solve_in_place(b);
  ++solves_;
}

void LinearSolver::set_refinement_target(double backward_error) {
  if (!(backward_error > 0.0 && backward_error < 1.0))
    throw Error("refinement target " + significant(backward_error) + " is not in (0, 1)",
                where("set_refinement_target"),
                "give a backward error such as solvers::round_off_backward_error or 1e-9");
  refinement_target_ = backward_error;
}

void LinearSolver::throw_library_failure(std::string_view call, int status) const {
  throw Error(std::string(call) + " failed with status " + std::to_string(status),
              where(call), "check the matrix for NaN or Inf values and the available memory");
}

}  // namespace spar::solvers
