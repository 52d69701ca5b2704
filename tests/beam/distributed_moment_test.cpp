// Distributed moments on beams: the local tangent against central differences of the force along
// q ⊕ Δ (follower and dead), and a cantilever under a uniform moment against the exact solution.
#include <spar/elements/beam/distributed_moment.hpp>
#include <spar/lie/lie.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "beam_fixtures.hpp"
#include "cantilever.hpp"
#include "random_rotations.hpp"

using namespace spar;

TEST_CASE("distributed moment tangents are the derivative of its force", "[gebt][loads]") {
  core::Configuration reference;
  const core::GeometricallyExactBeam beam(
      {.centerline = test::straight_centerline(1.2, 2, 3), .stiffness = test::generic_stiffness()}, reference);
  test::RandomRotations random(41);
  core::Configuration q = reference;
  const Eigen::Matrix3d Q = lie::exp(2.5 * random.axis());
  for (int k = 0; k < q.block_count(); ++k) {
    q.position[k] = Q * q.position[k];
    q.rotation[k] = Q * q.rotation[k] * lie::exp(random.uniform(0.0, 0.7) * random.axis());
  }
  const Eigen::Vector3d m(0.7, -1.1, 0.4);
  for (core::MomentFrame frame : {core::MomentFrame::material, core::MomentFrame::inertial}) {
    Eigen::VectorXd force;
    Eigen::MatrixXd tangent;
    core::distributed_moment_contribution(beam, 1, q, m, frame, force, &tangent);
    const int first = beam.node(beam.element(1).first_control_point);
    const int n = static_cast<int>(force.size());
    Eigen::MatrixXd fd(n, n);
    // Central differences, step 1e-6 on O(1) data: error ~1e-10 relative.
    for (int i = 0; i < n; ++i) {
      Eigen::VectorXd column = Eigen::VectorXd::Zero(n);
      for (double sign : {1.0, -1.0}) {
        core::Configuration p = q;
        const int node = first + i / 6;
        if (i % 6 < 3)
          p.position[node](i % 6) += sign * 1e-6;
        else
          p.rotation[node] = lie::right_plus(p.rotation[node], Eigen::Vector3d(sign * 1e-6 * Eigen::Vector3d::Unit(i % 6 - 3)));
        Eigen::VectorXd perturbed;
        core::distributed_moment_contribution(beam, 1, p, m, frame, perturbed, nullptr);
        column += sign * perturbed / 2e-6;
      }
      fd.col(i) = column;
    }
    INFO((frame == core::MomentFrame::material ? "material" : "inertial"));
    CHECK((tangent - fd).norm() <= 1e-7 * tangent.norm());
  }
}

TEST_CASE("a cantilever under a uniform distributed moment bends as M(s) = m (L - s)",
          "[gebt][loads][validation]") {
  // Moment equilibrium M′ + m = 0 with no forces: κ₃(s) = m (L − s)/EI, so the tip section turns
  // by m L²/(2 EI) (here 1.5 rad) — the same for a follower and a dead moment about Z in plane.
  // The rotation field is exact (quadratic); the positions are not polynomials, and their
  // interpolation error reaches the rotations through the shear strain: 3.2e-6 rad with 16
  // elements, below 1e-6 with 32.
  for (core::MomentFrame frame : {core::MomentFrame::material, core::MomentFrame::inertial}) {
    auto c = test::make_cantilever(32, 3);
    const double EI = 1e4, L = 1.0, m = 3.0 * EI / (L * L);
    core::add_load(c.model, core::DistributedMoment{.beam = c.beam, .moment_per_length = Eigen::Vector3d(0, 0, m),
                                             .frame = frame});
    solvers::solve_static(c.model, {.load_steps = 4});
    const Eigen::Vector3d tip_axis = c.model.state().rotation[c.tip].col(0);
    const double angle = std::atan2(tip_axis.y(), tip_axis.x());
    INFO("tip rotation " << angle << ", exact " << m * L * L / (2 * EI));
    CHECK(std::fabs(angle - m * L * L / (2 * EI)) <= 1e-6);
  }
}
