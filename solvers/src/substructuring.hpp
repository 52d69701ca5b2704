#pragma once
// Private to spar_solvers: substructuring of a constrained system's iteration matrix
// (docs/dynamics.md D12).
//
// A model of several beams joined by joints has an iteration matrix
//
//     A = [ K   Bᵀ ]      K: the members' inertia and stiffness, block-diagonal by member but for
//         [ B   0  ]         the joints' multiplier tangents ∂(Bᵀλ)/∂q between two members,
//
// whose multipliers, with their zero diagonal, force off-diagonal pivots and whose loops fill the
// LU factors of the whole matrix (the truss unit: ~10⁵ nonzeros for 1 216 unknowns). Dropping the
// entries between two members gives a matrix P that an LU with the members' unknowns first and the
// interface (multipliers, joint-owned coordinates) last factorizes into the members' band factors
// and the dual Schur complement B K⁻¹ Bᵀ — the classical substructuring of structural analysis.
// The dropped entries are λ-sized against the members' stiffness and mass; iterative refinement
// with A itself (x ← x + P⁻¹(b − A x)) restores the solution of A to the solver's refinement
// target in a few sweeps (LinearSolver::refinement_target: round-off by default, 1e-9 for a
// Newton increment), so the Newton iterates are those of an exact factorization.

#include <spar/solvers/sparse_assembly.hpp>
#include <spar/solvers/linear_solver.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::solvers::detail {

/// P's pattern and the order in which to factorize it.
struct SubstructuredPattern {
  /// P's compressed-column pattern: A's entries except those coupling two different substructures
  /// and the off-diagonal ones of fixed unknowns.
  std::vector<int> column_starts, row_indices;
  /// P's k-th value is A's value source[k].
  std::vector<int> source;
  /// A symmetric fill-reducing permutation (new position → unknown): the substructures' inner
  /// unknowns, then their boundaries (coupled to the interface) with the interface, each part
  /// ordered by constrained minimum degree (CAMD) on P + Pᵀ.
  std::vector<int> ordering;
  /// How many of A's entries P leaves out (0: P is A).
  int dropped = 0;
};

/// The substructured pattern of A for `substructure` (one entry per unknown: the substructure it
/// belongs to, ≥ 0, interface_unknown or fixed_unknown), as LinearSolver::analyze has checked it.
SubstructuredPattern substructured_pattern(const solvers::SparseMatrix& A,
                                           const std::vector<int>& substructure);

/// A compressed-column matrix's entries row by row: row i's are positions[starts[i] …
/// starts[i + 1]) of its values, in columns columns[…], in the order of their columns.
struct RowOrder {
  std::vector<int> starts, positions, columns;
};

/// The row order of A's pattern.
RowOrder row_order(const solvers::SparseMatrix& A);

/// r = b − A x, and the normwise backward error of x for the system with every row divided by its
/// largest entry, D = diag(row_scale) (as KLU scales it): ω = ‖D⁻¹r‖∞ / ‖D⁻¹(|A||x| + |b|)‖∞.
/// An LU of A with partial pivoting gives ω of a few unit round-offs; a componentwise measure is
/// not what it guarantees (a row whose few terms are all at the round-off of the others' size
/// would never be met). With `measure_rows`, row_scale(i) = maxⱼ |aᵢⱼ| is measured in the same
/// pass. Row by row (`rows` = row_order(A)): each row's sums are formed in registers, in the
/// order of its columns, the order a pass by columns adds them in, so r and the sums are the same
/// bits, without a scattered update of three vectors per entry.
double residual_and_backward_error(const solvers::SparseMatrix& A, const RowOrder& rows,
                                   const Eigen::Ref<const Eigen::VectorXd>& x,
                                   const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::VectorXd& r,
                                   Eigen::VectorXd& row_scale, bool measure_rows);

}  // namespace spar::solvers::detail
