// The Cardona–Géradin chart about the last converged configuration: the pulled-back tangent of
// the internal forces is symmetric and is the derivative of the pulled-back force.
#include <spar/core/converged_chart.hpp>
#include <spar/elements/beam/geometrically_exact_beam_element.hpp>
#include <spar/core/model.hpp>
#include <spar/lie/lie.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include "beam_fixtures.hpp"
#include "random_rotations.hpp"

using namespace spar;

TEST_CASE("the internal-force tangent in the converged chart is symmetric and exact", "[statics][gebt]") {
  core::Model model;
  core::add_beam(model, {.centerline = test::straight_centerline(1.0, 2, 3), .stiffness = test::generic_stiffness()});
  test::RandomRotations random(21);
  // A converged state q_n with large rotations, and a chart point φ of up to 0.5 rad per node.
  core::Configuration converged = model.state();
  // The chart: a global increment vector whose rotation entries are φ.
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(converged.dof_count());
  for (int k = 0; k < converged.block_count(); ++k) {
    converged.position[k] += 0.1 * Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    converged.rotation[k] = lie::exp(random.uniform(0, 3) * random.axis()) * converged.rotation[k];
    phi.segment<3>(6 * k + 3) = random.uniform(0, 0.5) * random.axis();
  }
  auto at = [&](const Eigen::VectorXd& chart) {  // q_n ⊕ chart
    core::Configuration q = converged;
    q.assign_increment(converged, chart);
    return q;
  };
  // The element's local-increment force and tangent (the element adds the ½ hat(m) term).
  const core::GeometricallyExactBeamElement element(core::beam(model, 0), 0, 1);
  auto evaluate = [&](const core::Configuration& q, const Eigen::VectorXd& chart, bool tangent) {
    core::ElementInput in;
    in.q = &q;
    core::ElementRequest request;
    request.stiffness = tangent;
    core::ElementOutput out;
    out.reset(6 * static_cast<int>(element.blocks().size()), request);
    element.evaluate(in, request, out);
    core::pull_back_to_converged_chart(q, element.blocks(), chart, out.residual,
                                       tangent ? &out.stiffness : nullptr);
    return out;
  };
  const core::ElementOutput c = evaluate(at(phi), phi, true);
  const Eigen::MatrixXd K = c.stiffness;
  CHECK((K - K.transpose()).norm() <= 1e-12 * K.norm());

  // Central differences of the pulled-back force in the chart coordinates (x, φ).
  const double h = 1e-6;
  const int n = static_cast<int>(c.residual.size());
  Eigen::MatrixXd fd(n, n);
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd column = Eigen::VectorXd::Zero(n);
    for (double sign : {1.0, -1.0}) {
      Eigen::VectorXd chart = phi;
      const int node = element.blocks()[i / 6];
      if (i % 6 >= 3) chart(6 * node + i % 6) += sign * h;
      core::Configuration q = at(chart);
      if (i % 6 < 3) q.position[node](i % 6) += sign * h;
      column += sign * evaluate(q, chart, false).residual / (2 * h);
    }
    fd.col(i) = column;
  }
  CHECK((K - fd).norm() <= 1e-6 * K.norm());
}
