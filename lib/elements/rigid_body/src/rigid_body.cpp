#include <spar/elements/rigid_body/rigid_body.hpp>

#include <spar/elements/rigid_body/rigid_body_element.hpp>
#include <spar/error.hpp>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <memory>
#include <string>

namespace spar::core {

int add_rigid_body(Model& model, const RigidBodyParameters& p) {
  const char* where = "core::add_rigid_body";
  if (!(p.mass > 0.0) || !std::isfinite(p.mass))
    throw Error("rigid body mass must be positive and finite, got " + significant(p.mass), where,
                "give the mass in kg");
  if (!p.center_of_mass.allFinite())
    throw Error("the centre of mass has a NaN or infinite entry", where, "give finite values");
  if (!p.inertia.allFinite() || (p.inertia - p.inertia.transpose()).norm() > 1e-12 * p.inertia.norm() ||
      !(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(p.inertia).eigenvalues().minCoeff() > 0.0))
    throw Error("rigid body inertia tensor is not symmetric positive definite", where,
                "give the inertia about the centre of mass in the body frame (kg m^2)");
  // A mass distribution has J₁ + J₂ ≥ J₃ for its principal moments (J₁ + J₂ − J₃ = 2∫x₃² dm ≥ 0),
  // equal for a flat body; the margin is round-off of the eigenvalues.
  const Eigen::Vector3d J = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(p.inertia).eigenvalues();
  if (J(0) + J(1) < J(2) * (1.0 - 1e-12))
    throw Error("the principal moments of inertia " + significant(J(0)) + ", " + significant(J(1)) + ", " +
                    significant(J(2)) + " break the triangle inequality J1 + J2 >= J3: no body has them",
                where, "give the inertia of a mass distribution about its centre of mass");
  const int node = model.add_frame(p.center_of_mass, p.rotation);
  const int index = model.add_part(std::make_unique<const RigidBody>(RigidBody{node, p.mass, p.inertia}));
  model.add_element(std::make_unique<RigidBodyElement>(model.part<RigidBody>(index, where), index));
  return index;
}

int rigid_body_count(const Model& model) { return model.part_count<RigidBody>(); }

const RigidBody& rigid_body(const Model& model, int b) {
  if (b < 0 || b >= rigid_body_count(model))
    throw Error("rigid body " + std::to_string(b) + " does not exist", "core::rigid_body",
                "use an index returned by add_rigid_body");
  return model.part<RigidBody>(b, "core::rigid_body");
}

FrameInertia rigid_body_inertia(const RigidBody& body) {
  return FrameInertia(FrameInertia::Coefficients::Ones(1, 1), body.mass, body.inertia);
}

}  // namespace spar::core
