#include "substructuring.hpp"

#include <spar/error.hpp>

#include <camd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace spar::solvers::detail {

namespace {

/// CAMD's constraint sets, eliminated in this order: the substructures' inner unknowns, then
/// their boundaries together with the interface.
constexpr int inner = 0, boundary_and_interface = 1;

}  // namespace

SubstructuredPattern substructured_pattern(const solvers::SparseMatrix& A,
                                           const std::vector<int>& substructure) {
  const int n = static_cast<int>(A.cols());
  // Left out of P: the couplings between two substructures, and the off-diagonal entries of a
  // fixed unknown's row and column (zero in every matrix: factorizing them costs flops for nothing;
  // frame 0 of the truss unit, 144 dofs, adds 18 % to P's flops with them: 1.31 against 1.11 Mflop).
  const auto left_out = [&](int row, int column) {
    if (row == column) return false;
    if (substructure[row] == fixed_unknown || substructure[column] == fixed_unknown) return true;
    return substructure[row] >= 0 && substructure[column] >= 0 &&
           substructure[row] != substructure[column];
  };
  SubstructuredPattern p;
  p.column_starts.reserve(static_cast<std::size_t>(n) + 1);
  p.row_indices.reserve(static_cast<std::size_t>(A.nonZeros()));
  p.source.reserve(static_cast<std::size_t>(A.nonZeros()));
  p.column_starts.push_back(0);
  for (int column = 0; column < n; ++column) {
    for (int k = A.outerIndexPtr()[column]; k < A.outerIndexPtr()[column + 1]; ++k) {
      const int row = A.innerIndexPtr()[k];
      if (left_out(row, column)) {
        ++p.dropped;
        continue;
      }
      p.row_indices.push_back(row);
      p.source.push_back(k);
    }
    p.column_starts.push_back(static_cast<int>(p.row_indices.size()));
  }

  // CAMD orders constraint set 0 before set 1: each substructure's inner unknowns first (static
  // condensation onto its boundary, the unknowns coupled to the interface: fill inside its band
  // only), then the boundaries and the interface together, ordered by minimum degree for their own
  // fill. With the boundary among the inner unknowns, each interface row would fill across its
  // whole substructure. With the boundaries in a set of their own, eliminated before the
  // interface, all the multipliers of a member's joints would become one dense clique of the dual
  // Schur complement; eliminating a joint's multipliers together with the nodes they tie takes
  // 0.64 against 1.11 Mflop on the truss unit, and no more on any example (slider-crank 0.107
  // against 0.109, four-bar 0.075 against 0.085 Mflop).
  std::vector<int> constraint_set(static_cast<std::size_t>(n));
  const auto on_interface = [&](int i) { return substructure[i] == interface_unknown; };
  for (int i = 0; i < n; ++i) constraint_set[i] = on_interface(i) ? boundary_and_interface : inner;
  for (int column = 0; column < n; ++column)
    for (int k = p.column_starts[column]; k < p.column_starts[column + 1]; ++k) {
      const int row = p.row_indices[k];
      if (on_interface(row) && substructure[column] >= 0) constraint_set[column] = boundary_and_interface;
      if (on_interface(column) && substructure[row] >= 0) constraint_set[row] = boundary_and_interface;
    }
  std::array<double, CAMD_CONTROL> control{};
  std::array<double, CAMD_INFO> info{};
  camd_defaults(control.data());
  p.ordering.resize(static_cast<std::size_t>(n));
  const int status = camd_order(n, p.column_starts.data(), p.row_indices.data(), p.ordering.data(),
                                control.data(), info.data(), constraint_set.data());
  if (status != CAMD_OK && status != CAMD_OK_BUT_JUMBLED)
    throw Error("camd_order failed with status " + std::to_string(status),
                "solvers::substructured_pattern", "check the available memory");
  return p;
}

RowOrder row_order(const solvers::SparseMatrix& A) {
  const int n = static_cast<int>(A.rows());
  const int* column_starts = A.outerIndexPtr();
  const int* row_indices = A.innerIndexPtr();
  RowOrder order;
  order.starts.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int k = 0; k < column_starts[A.cols()]; ++k) ++order.starts[static_cast<std::size_t>(row_indices[k]) + 1];
  for (int i = 0; i < n; ++i) order.starts[i + 1] += order.starts[i];
  order.positions.resize(static_cast<std::size_t>(column_starts[A.cols()]));
  order.columns.resize(order.positions.size());
  std::vector<int> next(order.starts.begin(), order.starts.end() - 1);
  for (int column = 0; column < A.cols(); ++column)
    for (int k = column_starts[column]; k < column_starts[column + 1]; ++k) {
      const int slot = next[row_indices[k]]++;
      order.positions[slot] = k;
      order.columns[slot] = column;
    }
  return order;
}

double residual_and_backward_error(const solvers::SparseMatrix& A, const RowOrder& rows,
                                   const Eigen::Ref<const Eigen::VectorXd>& x,
                                   const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::VectorXd& r,
                                   Eigen::VectorXd& row_scale, bool measure_rows) {
  const int n = static_cast<int>(A.rows());
  const double* values = A.valuePtr();
  r.resize(n);
  if (measure_rows) row_scale.resize(n);
  double residual = 0.0, size = 0.0;
  for (int i = 0; i < n; ++i) {
    double r_i = b(i), magnitude_i = std::abs(b(i)), scale_i = 0.0;
    for (int t = rows.starts[i]; t < rows.starts[i + 1]; ++t) {
      const double a = values[rows.positions[t]];
      const double term = a * x(rows.columns[t]);
      r_i -= term;
      magnitude_i += std::abs(term);
      if (measure_rows) scale_i = std::max(scale_i, std::abs(a));
    }
    r(i) = r_i;
    if (measure_rows) row_scale(i) = scale_i;
    if (row_scale(i) == 0.0) continue;  // an empty row: structurally singular, refused earlier
    residual = std::max(residual, std::abs(r_i) / row_scale(i));
    size = std::max(size, magnitude_i / row_scale(i));
  }
  return residual == 0.0 ? 0.0 : residual / size;
}

}  // namespace spar::solvers::detail
