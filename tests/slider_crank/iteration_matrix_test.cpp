// The assembled dynamic iteration matrix against central differences of the assembled residual,
// on the flexible slider-crank (beams, a rigid body, spherical and prismatic joints, a moment,
// gravity) in a deformed, moving state, in the middle of a step (increment ≠ 0).
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <random>

#include "slider_crank_model.hpp"
#include "system_assembly.hpp"

using namespace spar;

TEST_CASE("the assembled dynamic iteration matrix is the derivative of the assembled residual",
          "[dynamics][slider_crank]") {
  // The Newton unknown is the step's increment ι (q = q_n ⊕ ι); generalized-α ties the velocity
  // and acceleration to it, so with the integrator's coefficients (h = 1e-3, ρ∞ = 0.9)
  //   S = M + (γ′/β′) C + (1/β′)(K + K_λ) T(ι)   on the dof rows and columns,
  //   Bᵀ (λ columns),  B T(ι) (constraint rows),
  // and along a unit e: d/ds r(q_n ⊕ (ι + s e), v + γ′ s e, v̇ + β′ s e) = β′ · (S e) on the
  // dof rows, dΦ(q_n ⊕ (ι + s e))/ds = B T e, dr/dλ = Bᵀ.
  // Central differences with s = 1e-7 m/rad: truncation s² |r‴| ~ 1e-14 and round-off ε |r| / s
  // ~ 2e-9 of the entries; bound 1e-7 relative per block, measured 1.1e-9 (dof block) and 1.3e-10
  // (B T); the multipliers' share K_λ T, isolated as S(λ) − S(0), likewise: measured 1.3e-9. The λ
  // columns are exact up to the rounding of r (linear in λ): 1e-12, measured 1.2e-14.
  examples::SliderCrank mechanism = examples::build_slider_crank(2);
  core::Model& model = mechanism.model;
  std::vector<joints::Constraint*> constraints;
  for (const auto& joint : mechanism.joints) constraints.push_back(joint.get());
  solvers::detail::SystemAssembly assembly(model, constraints, solvers::AssemblyExecution::serial);
  const int n = assembly.dof_count(), m = assembly.multiplier_count();

  std::mt19937 random(1601);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto random_vector = [&](int size, double scale) {
    Eigen::VectorXd x(size);
    for (int i = 0; i < size; ++i) x(i) = scale * uniform(random);
    return x;
  };
  // q_n: the reference moved by up to 1 mm and 0.05 rad per node; ι up to 0.3 (m and rad), v, v̇
  // and λ of the sizes of the example's run.
  Eigen::VectorXd deformation = random_vector(n, 1e-3);
  for (int k = 0; k < n / 6; ++k) deformation.segment<3>(6 * k + 3) *= 50.0;
  core::Configuration start = model.state();
  start.assign_increment(model.state(), deformation);
  const Eigen::VectorXd increment = random_vector(n, 0.3);
  const Eigen::VectorXd velocity = random_vector(n, 2.0), acceleration = random_vector(n, 50.0);
  const Eigen::VectorXd lambda = random_vector(m, 1e3);

  const auto params = solvers::GeneralizedAlphaParameters::from_spectral_radius(0.9);
  const double h = 1e-3;
  const double beta_prime = (1 - params.alpha_m) / (h * h * params.beta * (1 - params.alpha_f));
  const double gamma_prime = params.gamma / (h * params.beta);
  const solvers::detail::MatrixCoefficients coefficients{.mass = 1.0, .damping = gamma_prime / beta_prime,
                                                         .stiffness = 1.0 / beta_prime};

  // Evaluates the assembled residual at q_n ⊕ (ι + s e), v + γ′ s e, v̇ + β′ s e, λ + t f.
  core::Configuration q;
  Eigen::VectorXd v, a;
  const auto residual = [&](const Eigen::VectorXd& de, const Eigen::VectorXd& dlambda) {
    q = start;
    q.assign_increment(start, increment + de);
    v = velocity + gamma_prime * de;
    a = acceleration + beta_prime * de;
    const core::ElementInput in{.q = &q, .velocity = &v, .acceleration = &a, .time = 0.01,
                                .gravity = model.gravity()};
    assembly.evaluate(in, lambda + dlambda, nullptr, solvers::detail::Chart::local_increment, increment + de,
                      false);
    return Eigen::VectorXd(assembly.residual());
  };
  // The matrix at (ι, v, v̇) with the multipliers λ or none.
  const auto matrix = [&](const Eigen::VectorXd& multipliers) {
    q = start;
    q.assign_increment(start, increment);
    const core::ElementInput in{.q = &q, .velocity = &velocity, .acceleration = &acceleration, .time = 0.01,
                                .gravity = model.gravity()};
    assembly.evaluate(in, multipliers, &coefficients, solvers::detail::Chart::local_increment, increment, false);
    return Eigen::MatrixXd(assembly.pattern().matrix());
  };
  const Eigen::MatrixXd S = matrix(lambda), S_without_lambda = matrix(Eigen::VectorXd::Zero(m));
  REQUIRE(S.rows() == n + m);

  const double s = 1e-7;
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(m);
  Eigen::MatrixXd fd(n + m, n + m), fd_lambda_tangent(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
    e(j) = s;
    const Eigen::VectorXd plus = residual(e, none), minus = residual(-e, none);
    const Eigen::VectorXd difference = (plus - minus) / (2 * s);
    fd.col(j).head(n) = difference.head(n) / beta_prime;
    fd.col(j).tail(m) = difference.tail(m);
    // The multipliers' share Bᵀλ alone (the elements' share cancels exactly): K_λ T, tiny beside
    // the elements' K in the full block.
    const Eigen::VectorXd plus_without = residual(e, -lambda), minus_without = residual(-e, -lambda);
    fd_lambda_tangent.col(j) = ((plus - plus_without) - (minus - minus_without)).head(n) / (2 * s) / beta_prime;
  }
  for (int j = 0; j < m; ++j) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(m);
    f(j) = 1.0;  // r is linear in λ: any step is exact
    fd.col(n + j) = (residual(Eigen::VectorXd::Zero(n), f) - residual(Eigen::VectorXd::Zero(n), -f)) / 2.0;
  }
  const auto relative = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).norm() / b.norm();
  };
  const double dynamic = relative(S.topLeftCorner(n, n), fd.topLeftCorner(n, n));
  const double jacobian = relative(S.bottomLeftCorner(m, n), fd.bottomLeftCorner(m, n));
  const double transpose = relative(S.topRightCorner(n, m), fd.topRightCorner(n, m));
  const double lambda_tangent = relative(S.topLeftCorner(n, n) - S_without_lambda.topLeftCorner(n, n), fd_lambda_tangent);
  INFO("relative differences: dof block " << dynamic << ", B T " << jacobian << ", B^T " << transpose
                                          << ", K_lambda T " << lambda_tangent
                                          << "; |S_qq| = " << S.topLeftCorner(n, n).norm());
  CHECK(dynamic <= 1e-7);
  CHECK(jacobian <= 1e-7);
  CHECK(transpose <= 1e-12);
  CHECK(lambda_tangent <= 1e-7);
  CHECK(S.bottomRightCorner(m, m).norm() == 0.0);
}

TEST_CASE("the assembly's substructures: one per body, the multipliers and fixed dofs apart",
          "[dynamics][slider_crank][substructuring]") {
  // Rod I, Rod II and the slider are three bodies (blocks joined by elements); the joints'
  // multipliers are the interface (docs/dynamics.md D12).
  examples::SliderCrank mechanism = examples::build_slider_crank(2);
  core::Model& model = mechanism.model;
  const int fixed_block = core::beam(model, mechanism.crank).node(0);
  model.fix(fixed_block);  // a fixed node: its dofs are marked apart, whatever body holds them
  std::vector<joints::Constraint*> constraints;
  for (const auto& joint : mechanism.joints) constraints.push_back(joint.get());
  solvers::detail::SystemAssembly assembly(model, constraints, solvers::AssemblyExecution::serial);
  const std::vector<int>& substructure = assembly.substructures();
  REQUIRE(static_cast<int>(substructure.size()) == assembly.size());
  const core::Configuration& q = model.state();
  const auto id = [&](int block) { return substructure[q.blocks[block].offset]; };
  const core::GeometricallyExactBeam& crank = core::beam(model, mechanism.crank);
  const core::GeometricallyExactBeam& coupler = core::beam(model, mechanism.coupler);
  const int crank_id = id(crank.node(1)), coupler_id = id(coupler.node(0));
  CHECK(crank_id >= 0);
  CHECK(coupler_id >= 0);
  CHECK(id(mechanism.slider_node) >= 0);
  CHECK(crank_id != coupler_id);
  CHECK(id(mechanism.slider_node) != crank_id);
  CHECK(id(mechanism.slider_node) != coupler_id);
  for (int i = 1; i < crank.control_point_count(); ++i) {
    const auto& block = q.blocks[crank.node(i)];
    for (int k = 0; k < block.size; ++k) CHECK(substructure[block.offset + k] == crank_id);
  }
  for (int i = 0; i < coupler.control_point_count(); ++i) CHECK(id(coupler.node(i)) == coupler_id);
  for (int k = 0; k < 6; ++k) CHECK(substructure[q.blocks[fixed_block].offset + k] == solvers::fixed_unknown);
  for (int i = assembly.dof_count(); i < assembly.size(); ++i) CHECK(substructure[i] == solvers::interface_unknown);
}
