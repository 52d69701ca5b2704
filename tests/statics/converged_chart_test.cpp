// The Cardona–Géradin chart about the last converged configuration: the pulled-back tangent of
// the internal forces is symmetric and is the derivative of the pulled-back force.
#include <spar/core/converged_chart.hpp>
#include <spar/core/model.hpp>
#include <spar/lie/lie.hpp>

#include <catch2/catch.hpp>

#include "beam_fixtures.hpp"
#include "random_rotations.hpp"

using namespace spar;

TEST_CASE("the internal-force tangent in the converged chart is symmetric and exact", "[statics][gebt]") {
  core::Model model;
  model.add_beam({.centerline = test::straight_centerline(1.0, 2, 3), .stiffness = test::generic_stiffness()});
  test::RandomRotations random(21);
  // A converged state q_n with large rotations, and a chart point φ of up to 0.5 rad per node.
  core::Configuration converged = model.reference();
  std::vector<Eigen::Vector3d> phi(converged.node_count());
  for (int k = 0; k < converged.node_count(); ++k) {
    converged.position[k] += 0.1 * Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    converged.rotation[k] = lie::exp(random.uniform(0, 3) * random.axis()) * converged.rotation[k];
    phi[k] = random.uniform(0, 0.5) * random.axis();
  }
  auto at = [&](const std::vector<Eigen::Vector3d>& chart) {
    core::Configuration q = converged;
    for (int k = 0; k < q.node_count(); ++k) q.rotation[k] = lie::right_plus(converged.rotation[k], chart[k]);
    return q;
  };
  core::NodalContribution c;
  core::beam_element_contribution(model, 0, 1, at(phi), true, c);
  core::pull_back_to_converged_chart(phi, c);
  const Eigen::MatrixXd K = c.tangent;
  CHECK((K - K.transpose()).norm() <= 1e-12 * K.norm());

  // Central differences of the pulled-back force in the chart coordinates (x, φ).
  const double h = 1e-6;
  const int n = static_cast<int>(c.force.size());
  Eigen::MatrixXd fd(n, n);
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd column = Eigen::VectorXd::Zero(n);
    for (double sign : {1.0, -1.0}) {
      std::vector<Eigen::Vector3d> chart = phi;
      core::Configuration q = converged;
      const int node = c.nodes[i / 6];
      if (i % 6 < 3)
        q.position[node](i % 6) += sign * h;
      else
        chart[node](i % 6 - 3) += sign * h;
      for (int k = 0; k < q.node_count(); ++k) q.rotation[k] = lie::right_plus(converged.rotation[k], chart[k]);
      core::NodalContribution p;
      core::beam_element_contribution(model, 0, 1, q, false, p);
      core::pull_back_to_converged_chart(chart, p);
      column += sign * p.force / (2 * h);
    }
    fd.col(i) = column;
  }
  CHECK((K - fd).norm() <= 1e-6 * K.norm());
}
