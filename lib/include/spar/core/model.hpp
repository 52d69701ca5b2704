#pragma once
/// \file
/// A model: nodes (the configuration space), beams, loads and Dirichlet conditions, and the
/// assembly of its internal and external generalized forces and their tangent.

#include <spar/core/beam.hpp>
#include <spar/core/beam_element.hpp>
#include <spar/core/configuration.hpp>
#include <spar/core/inertia.hpp>
#include <spar/core/loads.hpp>
#include <spar/core/sparse_assembly.hpp>

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace spar::core {

/// A rigid body to add: its centre of mass and orientation at t = 0, mass, and inertia tensor
/// about the centre of mass in the body frame. Joints attach to points given relative to the
/// centre of mass (the node), so a body whose reference point is not its centre of mass is
/// described by offsetting its attachment points.
struct RigidBodyParameters {
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// One dense block of a model's iteration matrix: a beam element, a rigid body, or a load whose
/// generalized force depends on the configuration.
struct ModelBlock {
  enum class Kind { beam_element, rigid_body, load };
  Kind kind = Kind::beam_element;
  int index = 0;    ///< beam, rigid body or load index
  int element = 0;  ///< element of the beam (beam_element, and load for distributed moments)
};

/// A factor multiplying a load in time (dynamics); an empty function means 1.
using LoadHistory = std::function<double(double)>;

/// Which of a node's six degrees of freedom a Dirichlet condition fixes.
enum class Fix { all, translations, rotations };

class Model {
public:
  /// Adds a beam; its control points become nodes of the model. Returns the beam's index.
  int add_beam(const BeamParameters& parameters);
  int beam_count() const { return static_cast<int>(beams_.size()); }
  const GeometricallyExactBeam& beam(int b) const;

  /// The reference configuration (as built) and the current one (what solvers update).
  const Configuration& reference() const { return reference_; }
  Configuration& state() { return state_; }
  const Configuration& state() const { return state_; }
  int node_count() const { return reference_.node_count(); }
  int dof_count() const { return reference_.dof_count(); }

  /// Adds a rigid body (one node at its centre of mass); returns the body's index. Throws
  /// spar::Error for a non-positive mass or an inertia that is not symmetric positive definite.
  int add_rigid_body(const RigidBodyParameters& parameters);
  int rigid_body_count() const { return static_cast<int>(rigid_bodies_.size()); }
  const RigidBody& rigid_body(int b) const;

  /// Adds an external load, scaled in dynamics by `history(t)`. Throws spar::Error for a node or
  /// beam that does not exist.
  void add_load(const Load& load, LoadHistory history = {});
  const std::vector<Load>& loads() const { return loads_; }
  /// The load's factor at time t (1 without a history).
  double load_factor(int load, double t) const;

  /// Gravity acceleration (inertial frame) acting on every beam and rigid body.
  void set_gravity(const Eigen::Vector3d& g) { gravity_ = g; }
  const Eigen::Vector3d& gravity() const { return gravity_; }
  /// The generalized gravity force (constant, 6 per node): ∫ ρA N_I g dS on beam nodes, m g on
  /// rigid bodies.
  Eigen::VectorXd gravity_force() const;
  /// The gravity potential −Σ f_g · x in configuration q.
  double gravity_potential(const Configuration& q) const;

  /// Fixes the increments of a node's degrees of freedom (clamp = Fix::all). Throws spar::Error
  /// for a node that does not exist.
  void fix(int node, Fix what = Fix::all);
  /// The fixed global dofs, sorted, without duplicates.
  const std::vector<int>& fixed_dofs() const { return fixed_dofs_; }

  /// The dense blocks of the iteration matrix: every beam element, every rigid body, then every
  /// load whose tangent is not zero (load_has_tangent).
  std::vector<ModelBlock> blocks() const;
  /// The global dofs of each block of blocks(), in the same order, for a SparsePattern.
  std::vector<PatternBlock> pattern_blocks() const;

private:
  void check_node(int node, const char* where) const;

  Configuration reference_;
  Configuration state_;
  std::vector<GeometricallyExactBeam> beams_;
  std::vector<RigidBody> rigid_bodies_;
  std::vector<Load> loads_;
  std::vector<LoadHistory> load_histories_;
  std::vector<int> fixed_dofs_;
  Eigen::Vector3d gravity_ = Eigen::Vector3d::Zero();
};

/// One contribution to the residual of a model: a generalized force on some nodes and, if asked,
/// its derivative along q ⊕ Δ (local increments).
struct NodalContribution {
  std::vector<int> nodes;
  Eigen::VectorXd force;    ///< 6 per node
  Eigen::MatrixXd tangent;  ///< ∂force(q ⊕ Δ)/∂Δ, or empty
  double energy = 0.0;      ///< the strain energy behind an internal force (0 for loads)
};

/// The internal force of element (b, e) and, if `with_tangent`, its local tangent
/// H + ½ blockdiag(hat(m_I)) (core/beam_element.hpp).
void beam_element_contribution(const Model& model, int b, int e, const Configuration& q,
                               bool with_tangent, NodalContribution& out);

/// The external force of a load at load factor λ and, if `with_tangent`, its derivative along
/// q ⊕ Δ: zero for forces and material moments, ∂(Rᵀ M)/∂Δ = hat(Rᵀ M) for inertial moments.
/// A distributed moment contributes element by element: `element` selects which.
void load_contribution(const Model& model, const Load& load, const Configuration& q,
                       double load_factor, bool with_tangent, NodalContribution& out,
                       int element = 0);

/// True for loads that need blocks of the iteration matrix (pattern_blocks()): moments, whose
/// generalized force depends on the rotation chart even when their local tangent is zero.
/// Distributed moments have one block per element of their beam.
bool load_has_tangent(const Load& load);

}  // namespace spar::core
