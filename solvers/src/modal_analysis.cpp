#include <spar/solvers/modal_analysis.hpp>

#include <spar/error.hpp>

#include "system_assembly.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace spar::solvers {

Eigen::VectorXd Modes::frequencies() const { return angular_frequencies / (2 * std::numbers::pi); }

Modes modal_analysis(core::Model& model, const std::vector<joints::Constraint*>& constraints,
                     const ModalOptions& options, const Eigen::VectorXd& multipliers) {
  const char* where = "solvers::modal_analysis";
  if (options.modes < 1) throw Error("modes must be at least 1", where, "ask for one mode or more");
  model.check_consistent(where);
  detail::SystemAssembly assembly(model, constraints, options.assembly);
  const int n = assembly.dof_count(), m = assembly.multiplier_count();
  if (multipliers.size() != 0 && multipliers.size() != m)
    throw Error("multipliers has " + std::to_string(multipliers.size()) + " entries for " + std::to_string(m) +
                    " constraint equations",
                where, "give the constraints' multipliers (e.g. StaticReport::multipliers) or none");
  const Eigen::VectorXd lambda = multipliers.size() ? multipliers : Eigen::VectorXd::Zero(m);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  core::ElementInput in;
  in.q = &model.state();
  in.velocity = &zero;
  in.acceleration = &zero;
  in.gravity = model.gravity();
  // K (+ K_λ) and B, then M, each read off the assembled [· Bᵀ; B 0] at a zero increment.
  const detail::MatrixCoefficients stiffness{.mass = 0.0, .damping = 0.0, .stiffness = 1.0};
  assembly.evaluate(in, lambda, &stiffness, detail::Chart::local_increment, zero, false);
  const Eigen::MatrixXd KB = Eigen::MatrixXd(assembly.pattern().matrix());
  const detail::MatrixCoefficients mass{.mass = 1.0, .damping = 0.0, .stiffness = 0.0};
  assembly.evaluate(in, lambda, &mass, detail::Chart::local_increment, zero, false);
  const Eigen::MatrixXd MB = Eigen::MatrixXd(assembly.pattern().matrix());

  // The free dofs, and an orthonormal basis N of B's null space among them.
  std::vector<char> fixed(n, 0);
  for (int dof : model.fixed_dofs()) fixed[dof] = 1;
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (!fixed[i]) free.push_back(i);
  const int f = static_cast<int>(free.size());
  Eigen::MatrixXd K(f, f), M(f, f), B(m, f);
  for (int j = 0; j < f; ++j) {
    for (int i = 0; i < f; ++i) {
      K(i, j) = KB(free[i], free[j]);
      M(i, j) = MB(free[i], free[j]);
    }
    for (int r = 0; r < m; ++r) B(r, j) = KB(n + r, free[j]);
  }
  Eigen::MatrixXd N = Eigen::MatrixXd::Identity(f, f);
  if (m > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(B.transpose());
    qr.setThreshold(1e-12);
    const Eigen::MatrixXd Q = qr.householderQ();
    N = Q.rightCols(f - qr.rank());
  }
  const Eigen::MatrixXd Kr = N.transpose() * (0.5 * (K + K.transpose())) * N;
  const Eigen::MatrixXd Mr = N.transpose() * (0.5 * (M + M.transpose())) * N;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(Kr, Mr, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (solver.info() != Eigen::Success)
    throw Error("the mass matrix is not positive definite on the constrained freedoms", where,
                "give every free freedom a mass (a beam's SectionInertia, a body's inertia) or constrain it");
  const int count = std::min<int>(options.modes, static_cast<int>(N.cols()));
  Modes modes;
  modes.angular_frequencies.resize(count);
  modes.shapes = Eigen::MatrixXd::Zero(n, count);
  for (int k = 0; k < count; ++k) {
    const double eigenvalue = solver.eigenvalues()(k);
    modes.angular_frequencies(k) = std::copysign(std::sqrt(std::abs(eigenvalue)), eigenvalue);
    const Eigen::VectorXd shape = N * solver.eigenvectors().col(k);
    for (int i = 0; i < f; ++i) modes.shapes(free[i], k) = shape(i);
  }
  return modes;
}

}  // namespace spar::solvers
