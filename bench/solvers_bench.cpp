// The sparse linear-algebra layer on a system shaped like a beam model:
// - numeric factorization + solve with KLU, UMFPACK and Eigen's SparseLU of the iteration matrix
//   of a cubic B-spline beam (400 nodes × 6 dofs, each node coupled to its ±3 neighbours) clamped
//   at one end and pinned at the other through 9 Lagrange-multiplier rows (a saddle point matrix);
// - serial against parallel assembly of 200 dense 24 × 24 element blocks into a SparsePattern.
// Run: bench_solvers --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/solvers/linear_solver.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

namespace {

using spar::solvers::PatternBlock;

constexpr int frame_dofs = 6;
constexpr int nodes_per_element = 4;  // cubic B-spline
constexpr int element_dofs = frame_dofs * nodes_per_element;

/// A beam of `elements` cubic elements (element e on nodes e..e+3) and, with `supports`, a clamp
/// (6 multiplier rows on node 0) and a pin (3 rows on the translations of the last node). Each
/// multiplier row fixes one dof: its block couples that dof and the multiplier, [0 1; 1 0].
struct BeamSystem {
  int size;
  std::vector<PatternBlock> blocks;
};
BeamSystem beam_system(int elements, bool supports) {
  const int nodes = elements + nodes_per_element - 1;
  const int node_dofs = frame_dofs * nodes;
  BeamSystem system{supports ? node_dofs + 9 : node_dofs, {}};
  for (int e = 0; e < elements; ++e) {
    std::vector<int> dofs;
    for (int dof = frame_dofs * e; dof < frame_dofs * (e + nodes_per_element); ++dof)
      dofs.push_back(dof);
    system.blocks.push_back(PatternBlock::element(dofs));
  }
  if (!supports) return system;
  for (int k = 0; k < 6; ++k) system.blocks.push_back(PatternBlock::element({k, node_dofs + k}));
  for (int k = 0; k < 3; ++k)
    system.blocks.push_back(PatternBlock::element({node_dofs - frame_dofs + k, node_dofs + 6 + k}));
  return system;
}

/// A synthetic element kernel with the cost profile of a beam element: K = Σ_g w_g B_gᵀ C B_g
/// over 4 Gauss points, B_g 6 × 24 (strain-displacement), C 6 × 6 (section stiffness), plus a
/// small non-symmetric part (the follower-load and geometric terms of an iteration matrix).
class ElementKernel {
public:
  ElementKernel() {
    std::mt19937 generator(5);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    const auto fill = [&](Eigen::MatrixXd& M) {
      for (double& entry : M.reshaped()) entry = value(generator);
    };
    for (Eigen::MatrixXd& B : strain_displacement_) {
      B.resize(6, element_dofs);
      fill(B);
    }
    Eigen::MatrixXd C(6, 6);
    fill(C);
    section_stiffness_ = C * C.transpose() + 6.0 * Eigen::MatrixXd::Identity(6, 6);
    non_symmetric_.resize(element_dofs, element_dofs);
    fill(non_symmetric_);
    non_symmetric_ *= 0.01;
  }

  /// The element matrix of element `e` (scaled by e so that every block differs).
  void operator()(int e, Eigen::MatrixXd& K) const {
    const double scale = 1.0 + 1e-3 * e;
    for (const Eigen::MatrixXd& B : strain_displacement_)
      K.noalias() += (scale * 0.25) * B.transpose() * (section_stiffness_ * B);
    K += non_symmetric_;
    K.diagonal().array() += 1.0;
  }

private:
  std::array<Eigen::MatrixXd, 4> strain_displacement_;
  Eigen::MatrixXd section_stiffness_;
  Eigen::MatrixXd non_symmetric_;
};

/// The assembled iteration matrix of a beam of `elements` elements.
spar::solvers::SparseMatrix beam_matrix(int elements) {
  const BeamSystem system = beam_system(elements, true);
  spar::solvers::SparsePattern pattern(system.size, system.blocks);
  const ElementKernel kernel;
  pattern.assemble([&](int block_id, Eigen::MatrixXd& K) {
    if (block_id < elements)
      kernel(block_id, K);
    else
      K << 0.0, 1.0, 1.0, 0.0;  // a constraint Jacobian row (the dof with coefficient 1) and Bᵀ
  });
  return pattern.matrix();
}

void factorize_and_solve(benchmark::State& state, spar::solvers::LinearSolverKind kind) {
  // 400 nodes: 397 cubic elements.
  const spar::solvers::SparseMatrix A = beam_matrix(397);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  Eigen::VectorXd x(A.rows());
  auto solver = spar::solvers::make_linear_solver(kind);
  solver->analyze(A);
  solver->factorize(A);  // the first (pivoting) factorization happens once per run, as in Newton
  for (auto _ : state) {
    solver->factorize(A);
    x = b;
    solver->solve(x);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["dofs"] = static_cast<double>(A.rows());
  state.counters["nonzeros"] = static_cast<double>(A.nonZeros());
}
BENCHMARK_CAPTURE(factorize_and_solve, klu, spar::solvers::LinearSolverKind::klu)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(factorize_and_solve, umfpack, spar::solvers::LinearSolverKind::umfpack)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(factorize_and_solve, eigen_lu, spar::solvers::LinearSolverKind::eigen_lu)
    ->Unit(benchmark::kMicrosecond);

void assemble(benchmark::State& state, spar::solvers::AssemblyExecution execution) {
  // 200 elements of 24 × 24, no constraints.
  const BeamSystem system = beam_system(200, false);
  spar::solvers::SparsePattern pattern(system.size, system.blocks);
  const ElementKernel kernel;
  const spar::solvers::BlockCompute compute = [&](int block_id, Eigen::MatrixXd& K) {
    kernel(block_id, K);
  };
  for (auto _ : state) {
    pattern.assemble(compute, execution);
    benchmark::DoNotOptimize(pattern.matrix().valuePtr());
  }
}
BENCHMARK_CAPTURE(assemble, serial, spar::solvers::AssemblyExecution::serial)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(assemble, parallel, spar::solvers::AssemblyExecution::parallel)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

void scatter_only(benchmark::State& state, spar::solvers::AssemblyExecution execution) {
  // The assembly overhead alone (scatter; in parallel the block store and the gather): the
  // block is a constant.
  const BeamSystem system = beam_system(200, false);
  spar::solvers::SparsePattern pattern(system.size, system.blocks);
  const spar::solvers::BlockCompute compute = [](int, Eigen::MatrixXd& K) { K.setConstant(1.0); };
  for (auto _ : state) {
    pattern.assemble(compute, execution);
    benchmark::DoNotOptimize(pattern.matrix().valuePtr());
  }
}
BENCHMARK_CAPTURE(scatter_only, serial, spar::solvers::AssemblyExecution::serial)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(scatter_only, parallel, spar::solvers::AssemblyExecution::parallel)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
