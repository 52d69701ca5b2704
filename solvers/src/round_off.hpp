#pragma once
// Private to spar_solvers: the residual level below which round-off, not convergence, decides.

#include <spar/core/configuration.hpp>
#include <spar/solvers/sparse_assembly.hpp>

#include <algorithm>
#include <limits>

namespace spar::solvers::detail {

/// The residual an exact solution carries from round-off alone: the iteration matrix times a
/// perturbation of the positions by 64 ulps of the model's size, 64 ε max|A_ii| max(1, |x|).
/// Without it a small load on a stiff structure (EA ε ≫ load) could never converge.
inline double residual_round_off_floor(const solvers::SparseMatrix& A, const core::Configuration& q) {
  double length = 1.0;
  for (const Eigen::Vector3d& x : q.position) length = std::max(length, x.norm());
  return 64 * std::numeric_limits<double>::epsilon() * A.diagonal().cwiseAbs().maxCoeff() * length;
}

}  // namespace spar::solvers::detail
