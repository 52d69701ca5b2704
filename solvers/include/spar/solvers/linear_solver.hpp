#pragma once
/// \file
/// Sparse direct solvers for the iteration matrix of Newton and generalized-α.
///
/// A LinearSolver splits the work the way those integrators reuse it: `analyze` (fill-reducing
/// ordering, symbolic factorization) once per sparsity pattern, `factorize` (numeric LU) whenever
/// the values change, `solve` for every right-hand side. The base class checks the call order,
/// sizes and pattern, counts the calls and raises the errors; a backend (KLU, UMFPACK, Eigen's
/// SparseLU) only calls its library.

#include <spar/solvers/sparse_assembly.hpp>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace spar::solvers {

using solvers::SparseMatrix;

/// The available sparse LU backends.
enum class LinearSolverKind {
  klu,      ///< SuiteSparse KLU: BTF + AMD ordering, left-looking LU; refactorizes in place
  umfpack,  ///< SuiteSparse UMFPACK: multifrontal LU with BLAS-3 kernels
  eigen_lu  ///< Eigen's SparseLU (supernodal, COLAMD ordering), no external library
};

/// The solver kind named "klu", "umfpack" or "eigen-lu". Throws spar::Error listing the valid
/// names for anything else.
LinearSolverKind linear_solver_kind_from_string(std::string_view name);

/// The name of a solver kind, as accepted by linear_solver_kind_from_string.
std::string_view to_string(LinearSolverKind kind);

/// Substructure ids of LinearSolver::set_substructures that are not a substructure.
inline constexpr int interface_unknown = -1;
inline constexpr int fixed_unknown = -2;

/// The backward error of a solve at round-off: four unit round-offs, what an LU with partial
/// pivoting gives at best.
inline constexpr double round_off_backward_error = 4.0 * std::numeric_limits<double>::epsilon();

/// When a backend that can factorize by substructures (LinearSolver::set_substructures) does.
enum class Substructuring {
  when_cheaper,  ///< when its factorization takes clearly fewer flops than the whole matrix's
  always,        ///< whenever it can (benchmarks, tests); the fallbacks below still apply
};

/// A sparse direct solver for square systems A x = b, used as
/// `analyze(A)` once per pattern, then `factorize(A)` and `solve(b)` as often as needed.
///
/// Errors (spar::Error): factorize before analyze, solve before factorize, a matrix that is not
/// square, empty or compressed, a size or sparsity pattern that differs from the analyzed one, a
/// structurally singular matrix (at analyze) and a numerically singular one (at factorize).
/// After a failed factorize, solve throws until a factorize succeeds.
class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  /// The backend of this solver.
  LinearSolverKind kind() const noexcept { return kind_; }

  /// Symbolic analysis of A's sparsity pattern (ordering, symbolic factorization); the values of
  /// A are not used. Discards any previous analysis and factorization. Throws spar::Error if A is
  /// not square, empty, not compressed, or structurally singular (no zero-free diagonal exists
  /// under any row permutation, e.g. an empty row or column).
  void analyze(const SparseMatrix& A);

  /// Numeric LU factorization of A, which must have the analyzed pattern. Throws spar::Error if no
  /// analysis was done, if A's size or pattern differs from the analyzed one, or if A is
  /// numerically singular.
  void factorize(const SparseMatrix& A);

  /// Solves A x = b in place (b becomes x) with the last factorization. Throws spar::Error if
  /// there is no valid factorization or b's size is not n.
  void solve(Eigen::Ref<Eigen::VectorXd> b);

  /// Optional, before analyze: the substructure of every unknown (≥ 0; e.g. the beam it belongs
  /// to), interface_unknown for the interface (multipliers, coordinates that no element holds) or
  /// fixed_unknown for a fixed dof (its row and column hold only the diagonal). A backend may
  /// then factorize by substructuring, refining the solution against A itself (KLU does when it
  /// pays; docs/dynamics.md D12); the others ignore it. Empty (the default): A as a whole. Kept
  /// for later analyses; analyze throws spar::Error when its size is not A's.
  void set_substructures(std::vector<int> substructure,
                         Substructuring use = Substructuring::when_cheaper) {
    substructures_ = std::move(substructure);
    substructuring_ = use;
  }
  /// Whether the last factorization was by substructuring (and solve refines).
  virtual bool substructured() const noexcept { return false; }

  /// The normwise backward error to which a substructured solve is refined against A (see
  /// set_substructures): round-off, four unit round-offs, by default. A Newton iteration needs far
  /// less and may ask for less (GeneralizedAlpha does); a solve whose refinement stalls above it
  /// is redone with A as a whole. Throws spar::Error unless 0 < backward_error < 1.
  void set_refinement_target(double backward_error);
  double refinement_target() const noexcept { return refinement_target_; }

  /// The number of successful analyze calls.
  std::size_t analyses() const noexcept { return analyses_; }
  /// The number of successful factorize calls.
  std::size_t factorizations() const noexcept { return factorizations_; }
  /// The number of solve calls.
  std::size_t solves() const noexcept { return solves_; }

protected:
  explicit LinearSolver(LinearSolverKind kind) : kind_(kind) {}

  /// What a backend's numeric factorization found.
  enum class FactorizationOutcome { succeeded, singular };

  /// The substructures given by set_substructures (empty or one entry per unknown of A).
  const std::vector<int>& substructures() const noexcept { return substructures_; }
  Substructuring substructuring() const noexcept { return substructuring_; }

  /// The backend's symbolic analysis of a square, compressed, structurally nonsingular A. It
  /// discards the backend's previous analysis and factorization.
  virtual void analyze_pattern(const SparseMatrix& A) = 0;
  /// The backend's numeric factorization of A, which has the analyzed pattern.
  virtual FactorizationOutcome factorize_values(const SparseMatrix& A) = 0;
  /// The backend's in-place solve with its last successful factorization.
  virtual void solve_in_place(Eigen::Ref<Eigen::VectorXd> b) = 0;

  /// Throws the spar::Error of a library call that returned an error status (out of memory,
  /// invalid input): names the call and the status.
  [[noreturn]] void throw_library_failure(std::string_view call, int status) const;

  /// A's column starts, as the non-const pointer the SuiteSparse C interfaces take (they do not
  /// write through it).
  static int* column_starts(const SparseMatrix& A) {
    return const_cast<int*>(A.outerIndexPtr());
  }
  /// A's row indices, as the non-const pointer the SuiteSparse C interfaces take.
  static int* row_indices(const SparseMatrix& A) { return const_cast<int*>(A.innerIndexPtr()); }
  /// A's values, as the non-const pointer the SuiteSparse C interfaces take.
  static double* values(const SparseMatrix& A) { return const_cast<double*>(A.valuePtr()); }

private:
  std::string where(std::string_view operation) const;
  void check_square_compressed(const SparseMatrix& A, std::string_view operation) const;

  LinearSolverKind kind_;
  std::vector<int> substructures_;
  Substructuring substructuring_ = Substructuring::when_cheaper;
  double refinement_target_ = round_off_backward_error;
  /// The analyzed pattern, to check that factorize gets the same one.
  std::vector<int> analyzed_column_starts_;
  std::vector<int> analyzed_row_indices_;
  bool analyzed_ = false;
  bool factorized_ = false;
  std::size_t analyses_ = 0;
  std::size_t factorizations_ = 0;
  std::size_t solves_ = 0;
};

/// A new solver of the given kind.
std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind);

}  // namespace spar::solvers
