// Substructuring in the KLU backend (solvers/src/substructuring.hpp, docs/dynamics.md D12) on a
// saddle-point system shaped like a frame structure: members (chains of unknowns with a shifted,
// slightly non-symmetric Laplacian: stiffness plus mass) meeting at the nodes of a square grid,
// their end unknowns tied by multipliers, and small couplings between two members' ends where
// they meet (a joint's multiplier tangent) — the entries substructuring leaves out and the
// refinement restores.
#include <spar/error.hpp>
#include <spar/solvers/linear_solver.hpp>

#include <catch2/catch.hpp>

#include "substructuring.hpp"

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace spar;
using solvers::LinearSolverKind;
using solvers::SparseMatrix;

namespace {

struct Frame {
  SparseMatrix A;
  std::vector<int> substructure;  // per unknown: the member, or −1 for a multiplier
};

/// A frame on a grid × grid × grid lattice, every lattice edge a member of `nodes` nodes with 6
/// unknowns each (block-tridiagonal, as a beam's: a chain Laplacian per unknown, free ends, plus
/// `shift` on the diagonal for the mass, plus a little non-symmetric noise when `noisy`), and at
/// every lattice node the members' end nodes tied by 6 multipliers per extra member (a clamp).
/// `coupling` scales the entries between two members' end nodes at a lattice node. With shift 0
/// each member alone is singular (its rigid motion), as in statics: the first member's first node
/// is then held by 6 more multipliers (a support).
Frame lattice_frame(int grid, int nodes, double coupling, double shift, bool noisy = true,
                    unsigned seed = 7) {
  constexpr int d = 6;
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-0.05, 0.05);
  const auto noise = [&] { return noisy ? uniform(generator) : 0.0; };
  std::vector<Eigen::Triplet<double>> t;
  std::vector<int> substructure;
  std::vector<std::vector<int>> ends(static_cast<std::size_t>(grid * grid * grid));  // first unknowns
  const auto lattice = [&](int i, int j, int k) { return (i * grid + j) * grid + k; };
  int member = 0;
  const auto add_member = [&](int from, int to) {
    const int first = static_cast<int>(substructure.size());
    substructure.insert(substructure.end(), static_cast<std::size_t>(nodes * d), member);
    for (int a = 0; a < nodes; ++a)
      for (int r = 0; r < d; ++r)
        for (int b = std::max(0, a - 1); b <= std::min(nodes - 1, a + 1); ++b)
          for (int c = 0; c < d; ++c) {
            const double neighbours = (a > 0) + (a + 1 < nodes);
            const double laplacian = a == b ? neighbours + shift : -1.0;
            t.emplace_back(first + a * d + r, first + b * d + c, (r == c ? laplacian : 0.0) + noise());
          }
    ends[from].push_back(first);
    ends[to].push_back(first + (nodes - 1) * d);
    ++member;
  };
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j)
      for (int k = 0; k < grid; ++k) {
        if (i + 1 < grid) add_member(lattice(i, j, k), lattice(i + 1, j, k));
        if (j + 1 < grid) add_member(lattice(i, j, k), lattice(i, j + 1, k));
        if (k + 1 < grid) add_member(lattice(i, j, k), lattice(i, j, k + 1));
      }
  const auto add_multiplier = [&](std::initializer_list<std::pair<int, double>> terms) {
    const int lambda = static_cast<int>(substructure.size());
    substructure.push_back(-1);
    for (const auto& [u, sign] : terms) {
      t.emplace_back(lambda, u, sign);
      t.emplace_back(u, lambda, sign);
    }
  };
  for (const std::vector<int>& at : ends)
    for (std::size_t m = 1; m < at.size(); ++m)
      for (int r = 0; r < d; ++r) {
        add_multiplier({{at[0] + r, 1.0}, {at[m] + r, -1.0}});
        t.emplace_back(at[0] + r, at[m] + r, coupling * (1.0 + noise()));
        t.emplace_back(at[m] + r, at[0] + r, coupling * (1.0 + noise()));
      }
  if (shift == 0.0)
    for (int r = 0; r < d; ++r) add_multiplier({{r, 1.0}});
  const int n = static_cast<int>(substructure.size());
  Frame f{SparseMatrix(n, n), substructure};
  f.A.setFromTriplets(t.begin(), t.end());
  f.A.makeCompressed();
  return f;
}

/// ‖A x − b‖∞ / (‖A‖∞ ‖x‖∞): a backward-stable solve leaves a few ulps.
double relative_residual(const SparseMatrix& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  double norm_A = 0.0;
  for (int i = 0; i < A.rows(); ++i) norm_A = std::max(norm_A, A.row(i).cwiseAbs().sum());
  return (A * x - b).lpNorm<Eigen::Infinity>() / (norm_A * x.lpNorm<Eigen::Infinity>());
}

/// The reference solution: Eigen's SparseLU (COLAMD, partial pivoting by size).
Eigen::VectorXd eigen_lu(const SparseMatrix& A, const Eigen::VectorXd& b) {
  Eigen::SparseLU<SparseMatrix> lu(A);
  return lu.solve(b);
}

Eigen::VectorXd solve_with(solvers::LinearSolver& solver, const SparseMatrix& A, const Eigen::VectorXd& b) {
  solver.analyze(A);
  solver.factorize(A);
  Eigen::VectorXd x = b;
  solver.solve(x);
  return x;
}

}  // namespace

TEST_CASE("substructuring: a frame of 60 members is factorized by members and solved to round-off",
          "[solvers][substructuring]") {
  const Frame frame = lattice_frame(3, 6, 1e-3, 2.0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(frame.A.rows(), -1.0, 2.0);
  const Eigen::VectorXd reference = eigen_lu(frame.A, b);
  auto whole = solvers::make_linear_solver(LinearSolverKind::klu);
  const Eigen::VectorXd whole_solution = solve_with(*whole, frame.A, b);
  CHECK_FALSE(whole->substructured());

  // By default KLU substructures only where that saves flops (the truss unit: tests/
  // truss_deployment); on this lattice the whole matrix is cheaper (2.0 against 2.4 Mflop).
  auto by_default = solvers::make_linear_solver(LinearSolverKind::klu);
  by_default->set_substructures(frame.substructure);
  const Eigen::VectorXd whole_again = solve_with(*by_default, frame.A, b);
  CHECK_FALSE(by_default->substructured());
  CHECK((whole_again - whole_solution).lpNorm<Eigen::Infinity>() == 0.0);

  auto solver = solvers::make_linear_solver(LinearSolverKind::klu);
  solver->set_substructures(frame.substructure, solvers::Substructuring::always);
  const Eigen::VectorXd x = solve_with(*solver, frame.A, b);
  REQUIRE(solver->substructured());
  // Refined against A: a residual of round-off size although P leaves out entries of 1e-3
  // against a diagonal of 3 to 4 (unrefined: ~1e-3 relative error), and the solution of Eigen's
  // SparseLU (threshold 1: pivots by size) to ~1e-14 (measured 6e-15). KLU's LU of the whole
  // saddle-point matrix, with its threshold 1e-3, is the less accurate here: residual 2e-9.
  CHECK(relative_residual(frame.A, x, b) <= 1e-15);
  CHECK((x - reference).lpNorm<Eigen::Infinity>() <= 1e-13 * reference.lpNorm<Eigen::Infinity>());

  // New values on the same pattern: refactorized by members again.
  SparseMatrix B = frame.A;
  for (int k = 0; k < B.nonZeros(); ++k) B.valuePtr()[k] *= 1.0 + 1e-2 * std::sin(k);
  solver->factorize(B);
  Eigen::VectorXd y = b;
  solver->solve(y);
  CHECK(solver->substructured());
  CHECK(relative_residual(B, y, b) <= 1e-15);
}

TEST_CASE("substructuring: a solve is refined to the backward error asked for, round-off by default",
          "[solvers][substructuring]") {
  // Couplings of 1e-3 against a diagonal of 3 to 4: P's solve alone is ~1e-3 off, and each sweep
  // gains about that much. A Newton iteration asks for 1e-9 (GeneralizedAlpha): the sweeps stop
  // there, short of round-off.
  const Frame frame = lattice_frame(3, 6, 1e-3, 2.0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(frame.A.rows(), -1.0, 2.0);
  const Eigen::VectorXd reference = eigen_lu(frame.A, b);
  const auto solve_to = [&](double target) {
    auto solver = solvers::make_linear_solver(LinearSolverKind::klu);
    solver->set_substructures(frame.substructure, solvers::Substructuring::always);
    if (target > 0.0) solver->set_refinement_target(target);
    const Eigen::VectorXd x = solve_with(*solver, frame.A, b);
    REQUIRE(solver->substructured());
    return x;
  };
  const Eigen::VectorXd round_off = solve_to(0.0), newton = solve_to(1e-9);
  const double scale = reference.lpNorm<Eigen::Infinity>();
  CHECK(relative_residual(frame.A, round_off, b) <= 1e-15);
  CHECK((round_off - reference).lpNorm<Eigen::Infinity>() <= 1e-13 * scale);
  // Refined to 1e-9, and no further: not the round-off solution.
  CHECK(relative_residual(frame.A, newton, b) <= 1e-9);
  CHECK((newton - reference).lpNorm<Eigen::Infinity>() <= 1e-8 * scale);
  CHECK((newton - reference).lpNorm<Eigen::Infinity>() > 1e-13 * scale);

  auto solver = solvers::make_linear_solver(LinearSolverKind::klu);
  CHECK(solver->refinement_target() == solvers::round_off_backward_error);
  for (const double bad : {0.0, -1e-9, 1.0, std::nan("")})
    CHECK_THROWS_WITH(solver->set_refinement_target(bad), Catch::Contains("refinement target") &&
                                                               Catch::Contains("not in (0, 1)"));
}

TEST_CASE("substructuring: couplings too strong to refine fall back to the whole matrix",
          "[solvers][substructuring]") {
  // Couplings twice the members' smallest eigenvalue (the mass shift): P⁻¹A is far from the
  // identity and the refinement does not contract; the backend then factorizes A as a whole and
  // solves it as well as the whole matrix's own LU does.
  const Frame frame = lattice_frame(3, 6, 4.0, 2.0);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(frame.A.rows());
  auto solver = solvers::make_linear_solver(LinearSolverKind::klu);
  solver->set_substructures(frame.substructure, solvers::Substructuring::always);
  solver->analyze(frame.A);
  Eigen::VectorXd x;
  // Each failure costs the matrix its substructured factorization; P is tried again with the next
  // matrix (a failure may be one bad Newton iterate), and given up after three in a row.
  for (int attempt = 1; attempt <= 4; ++attempt) {
    INFO("factorization " << attempt);
    solver->factorize(frame.A);
    CHECK(solver->substructured() == (attempt <= 3));
    x = b;
    solver->solve(x);
    CHECK_FALSE(solver->substructured());
  }
  auto whole = solvers::make_linear_solver(LinearSolverKind::klu);
  const double whole_residual = relative_residual(frame.A, solve_with(*whole, frame.A, b), b);
  CHECK(relative_residual(frame.A, x, b) <= 2.0 * whole_residual);
}

TEST_CASE("substructuring: members without mass, held only by the joints, solve by substructuring too",
          "[solvers][substructuring]") {
  // No shift: each member's Laplacian is singular (its rigid motion), as in statics; P is regular
  // all the same (the clamps' multipliers tie the members, a support holds the first), and KLU's
  // pivoting takes a multiplier's row where a member runs out of pivots.
  const Frame frame = lattice_frame(2, 4, 1e-3, 0.0, false);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(frame.A.rows(), 1.0, 3.0);
  auto solver = solvers::make_linear_solver(LinearSolverKind::klu);
  solver->set_substructures(frame.substructure, solvers::Substructuring::always);
  const Eigen::VectorXd x = solve_with(*solver, frame.A, b);
  CHECK(solver->substructured());
  CHECK(relative_residual(frame.A, x, b) <= 1e-15);
}

TEST_CASE("substructuring: a P that is singular where A is not falls back to the whole matrix",
          "[solvers][substructuring]") {
  // Unknown 1 (substructure 0) has no diagonal term; only its coupling to unknown 2 (substructure
  // 1), which P leaves out, makes A = [1 0 0; 0 0 1; 0 1 1] regular.
  const auto matrix = [](double diagonal) {
    SparseMatrix A(3, 3);
    const std::vector<Eigen::Triplet<double>> t{{0, 0, 1.0}, {1, 1, diagonal}, {1, 2, 1.0}, {2, 1, 1.0}, {2, 2, 1.0}};
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    return A;
  };
  const Eigen::Vector3d b(1.0, 2.0, 3.0);
  for (const bool singular_first : {true, false}) {
    INFO((singular_first ? "P singular at the pattern's first factorization" : "P singular at a refactorization"));
    auto solver = solvers::make_linear_solver(LinearSolverKind::klu);
    solver->set_substructures({0, 0, 1}, solvers::Substructuring::always);
    solver->analyze(matrix(0.0));
    if (!singular_first) {
      solver->factorize(matrix(2.0));
      CHECK(solver->substructured());
    }
    solver->factorize(matrix(0.0));
    CHECK_FALSE(solver->substructured());
    Eigen::VectorXd x = b;
    solver->solve(x);
    CHECK((matrix(0.0) * x - b).lpNorm<Eigen::Infinity>() <= 1e-15);
  }
}

TEST_CASE("substructuring: fixed unknowns are solved as the identity rows they are",
          "[solvers][substructuring]") {
  // A fixed dof after the Dirichlet conditions (solvers::SparsePattern::apply_dirichlet): its row and
  // column keep their pattern, with zeros, and a 1 on the diagonal. P leaves those zeros out.
  Frame frame = lattice_frame(3, 6, 1e-3, 2.0);
  const int first_node = 6;
  for (int column = 0; column < frame.A.cols(); ++column)
    for (SparseMatrix::InnerIterator entry(frame.A, column); entry; ++entry)
      if (entry.row() < first_node || column < first_node)
        entry.valueRef() = entry.row() == column ? 1.0 : 0.0;
  for (int i = 0; i < first_node; ++i) frame.substructure[i] = solvers::fixed_unknown;
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(frame.A.rows(), -1.0, 2.0);
  b.head(first_node).setZero();
  auto solver = solvers::make_linear_solver(LinearSolverKind::klu);
  solver->set_substructures(frame.substructure, solvers::Substructuring::always);
  const Eigen::VectorXd x = solve_with(*solver, frame.A, b);
  CHECK(solver->substructured());
  CHECK(x.head(first_node).lpNorm<Eigen::Infinity>() == 0.0);
  CHECK(relative_residual(frame.A, x, b) <= 1e-15);
  const Eigen::VectorXd reference = eigen_lu(frame.A, b);
  CHECK((x - reference).lpNorm<Eigen::Infinity>() <= 1e-13 * reference.lpNorm<Eigen::Infinity>());
}

TEST_CASE("substructuring: whatever the couplings, a solve is as good as the whole matrix's",
          "[solvers][substructuring]") {
  // 40 random frames, couplings from 1e-6 to 10 times the mass shift and shifts from 0 (statics)
  // to 3: by substructures where the refinement reaches round-off, else as a whole — the answer
  // never worse than KLU's LU of the whole matrix (and never an error: every A here is regular).
  std::mt19937 generator(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int by_substructures = 0;
  for (int k = 0; k < 40; ++k) {
    const double shift = k % 4 == 0 ? 0.0 : 3.0 * unit(generator);
    const double coupling = std::pow(10.0, -6.0 + 7.0 * unit(generator)) * std::max(shift, 1.0);
    const Frame frame = lattice_frame(2, 3, coupling, shift, true, 100 + k);
    Eigen::VectorXd b(frame.A.rows());
    for (int i = 0; i < b.size(); ++i) b(i) = unit(generator) - 0.5;
    INFO("frame " << k << ": coupling " << coupling << ", shift " << shift);
    auto whole = solvers::make_linear_solver(LinearSolverKind::klu);
    const double whole_residual = relative_residual(frame.A, solve_with(*whole, frame.A, b), b);
    auto solver = solvers::make_linear_solver(LinearSolverKind::klu);
    solver->set_substructures(frame.substructure, solvers::Substructuring::always);
    const Eigen::VectorXd x = solve_with(*solver, frame.A, b);
    by_substructures += solver->substructured();
    // A refined solve: a backward error of a few ulps; a whole one: KLU's own.
    CHECK(relative_residual(frame.A, x, b) <= std::max(1e-15, 2.0 * whole_residual));
  }
  // Both ways taken (measured: 24 of 40 by substructures).
  CHECK(by_substructures > 0);
  CHECK(by_substructures < 40);
}

TEST_CASE("substructuring: substructures of the wrong size or an unknown id are refused at analyze", "[solvers][substructuring]") {
  const Frame frame = lattice_frame(2, 3, 1e-3, 0.5);
  for (LinearSolverKind kind : {LinearSolverKind::klu, LinearSolverKind::umfpack}) {
    auto solver = solvers::make_linear_solver(kind);
    solver->set_substructures(std::vector<int>(3, 0));
    CHECK_THROWS_AS(solver->analyze(frame.A), Error);
    std::vector<int> invalid = frame.substructure;
    invalid[2] = -3;
    solver->set_substructures(invalid);
    CHECK_THROWS_AS(solver->analyze(frame.A), Error);
    solver->set_substructures({});
    CHECK_NOTHROW(solver->analyze(frame.A));
  }
}

TEST_CASE("substructuring: the refinement's residual row by row is the column-wise one, bit for bit",
          "[solvers][substructuring]") {
  // residual_and_backward_error sums each row in registers in the order of its columns, the order
  // in which a pass over A's columns adds the terms: r, the rows' scales and ω (from |A||x| + |b|)
  // are the same bits as the scattered column-wise updates give.
  const Frame frame = lattice_frame(2, 4, 0.3, 1.0);
  const SparseMatrix& A = frame.A;
  const int n = static_cast<int>(A.rows());
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd x(n), b(n);
  for (int i = 0; i < n; ++i) {
    x(i) = uniform(generator);
    b(i) = uniform(generator);
  }
  // The column-wise pass the row-wise one replaced: r, the rows' scales and ω.
  struct ColumnWise {
    Eigen::VectorXd r, scale;
    double omega;
  };
  const auto column_wise = [&](const Eigen::VectorXd& x_in) {
    Eigen::VectorXd r = b, magnitude = b.cwiseAbs(), scale = Eigen::VectorXd::Zero(n);
    for (int column = 0; column < n; ++column)
      for (SparseMatrix::InnerIterator it(A, column); it; ++it) {
        r(it.row()) -= it.value() * x_in(column);
        magnitude(it.row()) += std::abs(it.value() * x_in(column));
        scale(it.row()) = std::max(scale(it.row()), std::abs(it.value()));
      }
    double residual = 0.0, size = 0.0;
    for (int i = 0; i < n; ++i) {
      residual = std::max(residual, std::abs(r(i)) / scale(i));
      size = std::max(size, magnitude(i) / scale(i));
    }
    return ColumnWise{r, scale, residual / size};
  };

  const solvers::detail::RowOrder rows = solvers::detail::row_order(A);
  REQUIRE(rows.starts.back() == A.nonZeros());
  for (int i = 0; i < n; ++i)
    for (int t = rows.starts[i]; t + 1 < rows.starts[i + 1]; ++t) REQUIRE(rows.columns[t] < rows.columns[t + 1]);
  Eigen::VectorXd r, scale;
  const ColumnWise first = column_wise(x);
  const double omega = solvers::detail::residual_and_backward_error(A, rows, x, b, r, scale, true);
  CHECK(r == first.r);
  CHECK(scale == first.scale);
  CHECK(omega == first.omega);
  // With the scales kept from the first pass (a later sweep on the same matrix).
  x *= 0.5;
  const ColumnWise second = column_wise(x);
  const double again = solvers::detail::residual_and_backward_error(A, rows, x, b, r, scale, false);
  CHECK(scale == first.scale);
  CHECK(r == second.r);
  CHECK(again == second.omega);
  CHECK(again > 0.0);
}
