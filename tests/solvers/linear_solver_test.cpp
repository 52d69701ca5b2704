// The sparse LU backends on random non-symmetric systems and Laplacians, refactorization on a
// fixed pattern, a system assembled through solvers::SparsePattern with Dirichlet conditions, and
// the errors of the LinearSolver interface. Every test runs for every backend.
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/error.hpp>
#include <spar/solvers/linear_solver.hpp>

#include <catch2/catch.hpp>

#include <random>
#include <vector>

using namespace spar;
using solvers::LinearSolverKind;
using solvers::SparseMatrix;

namespace {

/// Backward-stable LU on a matrix with condition number ≤ ~1e3 leaves a relative residual of a few
/// hundred ulps at most; 1e-12 keeps two orders of margin and still catches a wrong solve.
constexpr double residual_tolerance = 1e-12;

SparseMatrix from_triplets(int size, const std::vector<Eigen::Triplet<double>>& triplets) {
  SparseMatrix A(size, size);
  A.setFromTriplets(triplets.begin(), triplets.end());
  A.makeCompressed();
  return A;
}

/// A random non-symmetric n × n matrix with ~`per_column` off-diagonal entries per column in
/// [-1, 1] and a diagonal that dominates its row and column by 1 (condition number ≲ 2·per_column).
SparseMatrix random_diagonally_dominant(int size, int per_column, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> row(0, size - 1);
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(size), col_sums = row_sums;
  for (int c = 0; c < size; ++c)
    for (int k = 0; k < per_column; ++k) {
      const int r = row(generator);
      if (r == c) continue;
      const double v = value(generator);
      triplets.emplace_back(r, c, v);
      row_sums(r) += std::abs(v);
      col_sums(c) += std::abs(v);
    }
  for (int i = 0; i < size; ++i)
    triplets.emplace_back(i, i, (i % 2 ? -1.0 : 1.0) * (std::max(row_sums(i), col_sums(i)) + 1.0));
  return from_triplets(size, triplets);
}

/// The 5-point Laplacian on an nx × ny grid with Dirichlet boundaries (ny = 1: the 1D one).
SparseMatrix laplacian(int nx, int ny) {
  std::vector<Eigen::Triplet<double>> triplets;
  const auto index = [nx](int i, int j) { return j * nx + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      triplets.emplace_back(index(i, j), index(i, j), ny == 1 ? 2.0 : 4.0);
      if (i > 0) triplets.emplace_back(index(i, j), index(i - 1, j), -1.0);
      if (i + 1 < nx) triplets.emplace_back(index(i, j), index(i + 1, j), -1.0);
      if (j > 0) triplets.emplace_back(index(i, j), index(i, j - 1), -1.0);
      if (j + 1 < ny) triplets.emplace_back(index(i, j), index(i, j + 1), -1.0);
    }
  return from_triplets(nx * ny, triplets);
}

Eigen::VectorXd random_vector(int size, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd v(size);
  for (double& entry : v) entry = value(generator);
  return v;
}

/// ‖b − A x‖ / ‖b‖ after solving A x = b with the solver's current factorization.
double relative_residual(solvers::LinearSolver& solver, const SparseMatrix& A,
                         const Eigen::VectorXd& b) {
  Eigen::VectorXd x = b;
  solver.solve(x);
  return (b - A * x).norm() / b.norm();
}

const std::vector<LinearSolverKind> all_kinds = {LinearSolverKind::klu, LinearSolverKind::umfpack,
                                                 LinearSolverKind::eigen_lu};

}  // namespace

TEST_CASE("linear solver kinds convert to and from their names", "[solvers][linear_solver]") {
  for (LinearSolverKind kind : all_kinds) {
    CHECK(solvers::linear_solver_kind_from_string(solvers::to_string(kind)) == kind);
    CHECK(solvers::make_linear_solver(kind)->kind() == kind);
  }
  CHECK(solvers::linear_solver_kind_from_string("eigen-lu") == LinearSolverKind::eigen_lu);
  CHECK_THROWS_WITH(solvers::linear_solver_kind_from_string("superlu"),
                    Catch::Contains("unknown linear solver \"superlu\"") &&
                        Catch::Contains("\"klu\", \"umfpack\", \"eigen-lu\""));
}

TEST_CASE("every backend solves random non-symmetric sparse systems", "[solvers][linear_solver]") {
  const LinearSolverKind kind = GENERATE(from_range(all_kinds));
  INFO("solver " << solvers::to_string(kind));
  auto solver = solvers::make_linear_solver(kind);
  for (unsigned seed : {1u, 2u, 3u}) {
    const SparseMatrix A = random_diagonally_dominant(300, 6, seed);
    solver->analyze(A);
    solver->factorize(A);
    CHECK(relative_residual(*solver, A, random_vector(300, seed + 100)) <= residual_tolerance);
  }
  CHECK(solver->analyses() == 3);
  CHECK(solver->factorizations() == 3);
  CHECK(solver->solves() == 3);
}

TEST_CASE("every backend solves 1D and 2D Laplacians", "[solvers][linear_solver]") {
  // Condition numbers ≈ 4·(n+1)²/π²: 1.7e3 for the 1D n = 200, 2.2e2 for the 2D 30 × 30.
  const LinearSolverKind kind = GENERATE(from_range(all_kinds));
  INFO("solver " << solvers::to_string(kind));
  auto solver = solvers::make_linear_solver(kind);
  for (const SparseMatrix& A : {laplacian(200, 1), laplacian(30, 30)}) {
    solver->analyze(A);
    solver->factorize(A);
    CHECK(relative_residual(*solver, A, random_vector(static_cast<int>(A.rows()), 7)) <=
          residual_tolerance);
  }
}

TEST_CASE("every backend refactorizes new values on the analyzed pattern",
          "[solvers][linear_solver]") {
  const LinearSolverKind kind = GENERATE(from_range(all_kinds));
  INFO("solver " << solvers::to_string(kind));
  auto solver = solvers::make_linear_solver(kind);
  SparseMatrix A = random_diagonally_dominant(200, 5, 42);
  const Eigen::VectorXd b = random_vector(200, 43);
  solver->analyze(A);
  for (unsigned step = 0; step < 4; ++step) {
    // New values, same pattern: scale and perturb every entry.
    const Eigen::VectorXd perturbation = random_vector(static_cast<int>(A.nonZeros()), step);
    for (Eigen::Index k = 0; k < A.nonZeros(); ++k)
      A.valuePtr()[k] *= 1.0 + 0.1 * perturbation(k);
    solver->factorize(A);
    CHECK(relative_residual(*solver, A, b) <= residual_tolerance);
  }
  CHECK(solver->analyses() == 1);
  CHECK(solver->factorizations() == 4);
  CHECK(solver->solves() == 4);

  SECTION("new values that need another pivot order") {
    // Analyzed and first factorized with a dominant diagonal (KLU keeps the diagonal pivots and
    // reuses them in klu_refactor), then with a zero and a tiny diagonal pivot, which need row
    // exchanges; the exact solution of the last system is (1, 1, 1).
    SparseMatrix B = from_triplets(3, {{0, 0, 4.0}, {1, 0, 1.0}, {0, 1, 1.0}, {1, 1, 4.0},
                                       {2, 1, 1.0}, {1, 2, 1.0}, {2, 2, 4.0}});
    solver->analyze(B);
    solver->factorize(B);
    for (double pivot : {0.0, 1e-20}) {
      B.coeffRef(0, 0) = pivot;
      B.coeffRef(1, 1) = pivot;
      solver->factorize(B);
      Eigen::VectorXd x = B * Eigen::Vector3d::Ones();
      solver->solve(x);
      INFO("diagonal pivot " << pivot);
      // Partial pivoting on entries of size 1..4: a few ulps.
      CHECK((x - Eigen::Vector3d::Ones()).norm() <= 1e-15);
    }
  }
}

namespace {

/// A saddle-point matrix [K Bᵀ; B 0] shaped like a dynamic iteration matrix: K (n × n) of size
/// `stiffness` with a dominant diagonal, B (m × n, m < n) of size 1 with a full-rank identity part.
SparseMatrix saddle_point(int n, int m, double stiffness, unsigned seed) {
  const SparseMatrix K = random_diagonally_dominant(n, 5, seed);
  std::mt19937 generator(seed + 1);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> column(0, n - 1);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int c = 0; c < n; ++c)
    for (SparseMatrix::InnerIterator it(K, c); it; ++it) triplets.emplace_back(it.row(), c, stiffness * it.value());
  for (int r = 0; r < m; ++r) {
    const auto add = [&](int c, double v) {
      triplets.emplace_back(n + r, c, v);
      triplets.emplace_back(c, n + r, v);
    };
    add(r, 1.0);
    for (int k = 0; k < 3; ++k)
      if (const int c = column(generator); c != r) add(c, 0.3 * value(generator));
  }
  return from_triplets(n + m, triplets);
}

/// The componentwise backward error max_i |b − A x|_i / (|A| |x| + |b|)_i (Oettli–Prager) of the
/// solver's solution of A x = b: row by row, so that the constraint rows of size 1 count as much
/// as the stiffness rows of size 1e8 (a normwise measure would see only the latter).
double backward_error(solvers::LinearSolver& solver, const SparseMatrix& A, const Eigen::VectorXd& b) {
  Eigen::VectorXd x = b;
  solver.solve(x);
  Eigen::VectorXd bound = b.cwiseAbs();
  for (int c = 0; c < A.cols(); ++c)
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) bound(it.row()) += std::abs(it.value() * x(c));
  return ((b - A * x).cwiseAbs().array() / bound.array()).maxCoeff();
}

}  // namespace

// KLU chooses its pivots on the row-scaled matrix but refactorizes unscaled (klu_solver.cpp,
// factorize_with): rows of 1e8 (stiffness over βh²) beside rows of 1 (the constraints) must
// solve as accurately as with a fresh pivoting factorization of the same values.
TEST_CASE("refactorizations of a badly row-scaled saddle-point matrix are as accurate as fresh ones",
          "[solvers][linear_solver]") {
  const LinearSolverKind kind = GENERATE(from_range(all_kinds));
  INFO("solver " << solvers::to_string(kind));
  SparseMatrix A = saddle_point(150, 40, 1e8, 7);
  const Eigen::VectorXd b = random_vector(190, 8);
  auto refactorizing = solvers::make_linear_solver(kind);
  refactorizing->analyze(A);
  refactorizing->factorize(A);
  for (unsigned step = 0; step < 5; ++step) {
    const Eigen::VectorXd perturbation = random_vector(static_cast<int>(A.nonZeros()), 20 + step);
    for (Eigen::Index k = 0; k < A.nonZeros(); ++k) A.valuePtr()[k] *= 1.0 + 0.2 * perturbation(k);
    refactorizing->factorize(A);
    auto fresh = solvers::make_linear_solver(kind);
    fresh->analyze(A);
    fresh->factorize(A);
    const double fresh_error = backward_error(*fresh, A, b);
    INFO("step " << step << ": fresh backward error " << fresh_error);
    // Row by row a fresh LU leaves 1e-14…3e-13 here with UMFPACK and Eigen, 2e-9…6e-9 with KLU
    // (its threshold pivoting grows on the constraint rows; refactorized unscaled: 1e-10…3e-10).
    // The refactorization, whose pivot order is that of the first values, must not lose more than
    // a small factor against it; stale or wrong factors leave errors of order 1.
    CHECK(backward_error(*refactorizing, A, b) <= 10.0 * std::max(fresh_error, 1e-15));
  }
}

TEST_CASE("a system assembled by SparsePattern with Dirichlet conditions solves",
          "[solvers][linear_solver][core]") {
  // A bar of 50 two-node elements with stiffness [1 −1; −1 1] is singular (a rigid translation);
  // fixing dof 0 makes it the 1D Laplacian, with the exact solution x_i = i of the rhs e_n.
  const LinearSolverKind kind = GENERATE(from_range(all_kinds));
  INFO("solver " << solvers::to_string(kind));
  const int size = 51;
  std::vector<solvers::PatternBlock> blocks;
  for (int e = 0; e + 1 < size; ++e) blocks.push_back(solvers::PatternBlock::element({e, e + 1}));
  solvers::SparsePattern pattern(size, blocks);
  Eigen::Matrix2d K;
  K << 1.0, -1.0, -1.0, 1.0;
  pattern.assemble([&](int, Eigen::MatrixXd& K_block) { K_block = K; });
  Eigen::VectorXd x = Eigen::VectorXd::Zero(size);
  x(size - 1) = 1.0;
  pattern.apply_dirichlet({0}, x);

  auto solver = solvers::make_linear_solver(kind);
  solver->analyze(pattern.matrix());
  solver->factorize(pattern.matrix());
  solver->solve(x);
  // Integer-valued solution up to 50, cond ≈ 1e3: a relative error of 1e-13 leaves margin.
  CHECK((x - Eigen::VectorXd::LinSpaced(size, 0.0, size - 1.0)).norm() <= 1e-13 * x.norm());
}

TEST_CASE("linear solvers report singular matrices and misuse", "[solvers][linear_solver]") {
  const LinearSolverKind kind = GENERATE(from_range(all_kinds));
  INFO("solver " << solvers::to_string(kind));
  auto solver = solvers::make_linear_solver(kind);
  const SparseMatrix A = laplacian(4, 1);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(4);

  SECTION("factorize or solve before analyze") {
    CHECK_THROWS_WITH(solver->factorize(A), Catch::Contains("factorize called before analyze"));
    CHECK_THROWS_WITH(solver->solve(b), Catch::Contains("solve called before analyze"));
  }
  SECTION("solve before factorize") {
    solver->analyze(A);
    CHECK_THROWS_WITH(solver->solve(b), Catch::Contains("without a successful factorization"));
  }
  SECTION("size mismatch") {
    solver->analyze(A);
    CHECK_THROWS_WITH(solver->factorize(laplacian(5, 1)),
                      Catch::Contains("size mismatch: matrix is 5 × 5, the analyzed one 4 × 4"));
    solver->factorize(A);
    Eigen::VectorXd b_long = Eigen::VectorXd::Ones(5);
    CHECK_THROWS_WITH(solver->solve(b_long),
                      Catch::Contains("size mismatch: right-hand side has 5 entries"));
  }
  SECTION("changed pattern") {
    solver->analyze(A);
    SparseMatrix B = A;
    B.insert(0, 3) = 1.0;
    B.makeCompressed();
    CHECK_THROWS_WITH(solver->factorize(B), Catch::Contains("sparsity pattern differs"));
  }
  SECTION("not square, not compressed") {
    CHECK_THROWS_WITH(solver->analyze(SparseMatrix(3, 4)), Catch::Contains("3 × 4, not square"));
    SparseMatrix B = A;
    B.insert(0, 3) = 1.0;
    CHECK_THROWS_WITH(solver->analyze(B), Catch::Contains("not in compressed form"));
  }
  SECTION("structurally singular") {
    // Column 2 has no entry at all.
    const SparseMatrix S = from_triplets(3, {{0, 0, 1.0}, {1, 1, 1.0}, {2, 1, 1.0}, {0, 1, 1.0}});
    CHECK_THROWS_WITH(solver->analyze(S),
                      Catch::Contains("structurally singular iteration matrix (structural rank 2 "
                                      "of 3") &&
                          Catch::Contains("redundant constraint"));
    CHECK(solver->analyses() == 0);
  }
  SECTION("numerically singular") {
    // Row 2 is stored but all its values are zero: structurally regular, numerically singular.
    SparseMatrix S = A;
    for (int c = 1; c < 4; ++c) S.coeffRef(2, c) = 0.0;
    solver->analyze(S);
    CHECK_THROWS_WITH(solver->factorize(S),
                      Catch::Contains("singular iteration matrix — check for a redundant "
                                      "constraint or an unconstrained rigid-body mode"));
    CHECK(solver->factorizations() == 0);
    CHECK_THROWS_WITH(solver->solve(b), Catch::Contains("without a successful factorization"));
    // A regular matrix of the same pattern factorizes after the failure.
    solver->factorize(A);
    CHECK(relative_residual(*solver, A, b) <= residual_tolerance);
  }
}
