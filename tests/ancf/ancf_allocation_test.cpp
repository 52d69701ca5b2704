// The ANCF element kernels and the ANCF joint allocate nothing once their outputs are sized: every
// global operator new of this executable is counted (tests/support/allocation_counter.cpp).
#include <spar/elements/ancf/ancf_beam.hpp>
#include <spar/elements/ancf/ancf_points.hpp>
#include <spar/joints/point_joint.hpp>

#include <catch2/catch.hpp>

#include "allocation_counter.hpp"

using namespace spar;

TEST_CASE("ANCF element evaluation and joint do not allocate", "[ancf][allocation]") {
  for (const auto kind : {core::AncfElementKind::standard_24, core::AncfElementKind::higher_order_30})
    for (const auto method : {core::AncfForceMethod::gerstmayr, core::AncfForceMethod::invariant}) {
      core::Model model;
      model.set_gravity(Eigen::Vector3d(0, 0, -9.81));
      const core::AncfBeam beam = core::add_ancf_beam(
          model, {.elements = 1, .kind = kind, .method = method, .remedy = core::AncfLockingRemedy::uniaxial_bending,
                  .material = {.young_modulus = 1e3, .poisson_ratio = 0.3, .density = 1},
                  .section = core::SectionIntegrals::circle(0.05)});
      const core::Element& element = model.element(beam.elements[0]);
      const Eigen::VectorXd velocity = Eigen::VectorXd::Constant(model.dof_count(), 0.1);
      const Eigen::VectorXd acceleration = Eigen::VectorXd::Constant(model.dof_count(), 0.2);
      const core::ElementInput in{.q = &model.state(), .velocity = &velocity, .acceleration = &acceleration,
                                  .gravity = model.gravity()};
      const core::ElementRequest all{.residual = true, .stiffness = true, .damping = true, .mass = true, .energy = true};
      const int n = core::block_dof_count(model.state(), element.blocks());
      core::ElementOutput out;
      out.reset(n, all);
      const joints::PointJoint joint(core::ancf_element_point(beam, 0, 0.3), Eigen::Vector3d::Zero(),
                                             model.state());
      Eigen::Vector3d phi;
      Eigen::MatrixXd B(3, core::block_dof_count(model.state(), joint.blocks()));
      const auto evaluate = [&] {
        out.reset(n, all);
        element.evaluate(in, all, out);
        joint.value(model.state(), 0.0, phi);
        joint.jacobian(model.state(), 0.0, B);
      };
      // A first call outside the count: Eigen's matrix products ask OpenMP for its thread count,
      // and clang's OpenMP runtime (libomp) allocates once when it starts on that first query.
      evaluate();
      const long before = test::allocation_count();
      evaluate();
      CHECK(test::allocation_count() == before);
    }
}
