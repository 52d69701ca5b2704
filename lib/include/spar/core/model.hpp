#pragma once
/// \file
/// A model: the configuration (blocks), the elements acting on it, Dirichlet conditions and
/// gravity (docs/model.md). Beams, rigid bodies and loads are built here as elements; a user's own
/// element kind goes in through add_element. The solvers see only the blocks and the elements.

#include <spar/core/beam.hpp>
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/core/inertia.hpp>
#include <spar/core/loads.hpp>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <string_view>
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

/// A factor multiplying a load in time (dynamics); an empty function means 1.
using LoadHistory = std::function<double(double)>;

/// Which increments of a block a Dirichlet condition fixes (translations/rotations: frames only).
enum class Fix { all, translations, rotations };

class Model {
public:
  Model() = default;
  Model(Model&&) = default;
  Model& operator=(Model&&) = default;

  // Blocks ----------------------------------------------------------------------------------------

  /// Appends a frame block (x, R); returns its index. Throws spar::Error if R is not a rotation.
  int add_frame(const Eigen::Vector3d& x, const Eigen::Matrix3d& R);
  /// Appends a vector block with coordinates p; returns its index. Throws for non-finite p.
  int add_vector(const Eigen::VectorXd& p);
  /// The current configuration (what solvers update).
  Configuration& state() { return state_; }
  const Configuration& state() const { return state_; }
  int block_count() const { return state_.block_count(); }
  int dof_count() const { return state_.dof_count(); }

  // Elements --------------------------------------------------------------------------------------

  /// Adds an element on existing blocks; returns its index. Throws spar::Error for a null element
  /// or a block that does not exist.
  int add_element(std::unique_ptr<Element> element);
  int element_count() const { return static_cast<int>(elements_.size()); }
  /// Element i; throws spar::Error for an index that does not exist.
  const Element& element(int i) const;
  /// Replaces element i (a slider crossing into the next element, a re-cut mesh) and marks the
  /// structure changed.
  void replace_element(int i, std::unique_ptr<Element> element);
  /// Removes element i (a piece of a cable that a leaving mass takes with it, a merged element);
  /// the elements after it move down by one index. Marks the structure changed. Throws
  /// spar::Error for an index that does not exist.
  void remove_element(int i);

  /// Adds a beam: its control points become frame blocks, each knot span a
  /// GeometricallyExactBeamElement. Returns the beam's index.
  int add_beam(const BeamParameters& parameters);
  int beam_count() const { return static_cast<int>(beams_.size()); }
  const GeometricallyExactBeam& beam(int b) const;

  /// Adds a rigid body (one frame block at its centre of mass, one RigidBodyElement); returns the
  /// body's index. Throws spar::Error for a non-positive or non-finite mass, an inertia that is
  /// not symmetric positive definite, or a centre of mass that is not finite.
  int add_rigid_body(const RigidBodyParameters& parameters);
  int rigid_body_count() const { return static_cast<int>(rigid_bodies_.size()); }
  const RigidBody& rigid_body(int b) const;

  /// Adds an external load as elements (a distributed load: one per beam element), scaled in
  /// statics by the load factor and in dynamics by `history(t)`. Throws spar::Error for a node or
  /// beam that does not exist, a node that is not a frame, or a non-finite load. A history that is
  /// not finite at an evaluation is a spar::InputError there, in statics at t = 0.
  void add_load(const Load& load, LoadHistory history = {});
  int load_count() const { return load_count_; }

  /// Gravity acceleration (inertial frame) acting on every element with mass; read by the
  /// elements at every evaluation, so a change between steps takes effect at the next one.
  void set_gravity(const Eigen::Vector3d& g);
  const Eigen::Vector3d& gravity() const { return gravity_; }

  // Dirichlet conditions ---------------------------------------------------------------------------

  /// Fixes increments of a block (clamp = Fix::all). Throws spar::Error for a block that does not
  /// exist, or translations/rotations of a vector block.
  void fix(int block, Fix what = Fix::all);
  /// The fixed global dofs, sorted, without duplicates.
  const std::vector<int>& fixed_dofs() const { return fixed_dofs_; }

  // Structure -------------------------------------------------------------------------------------

  /// Increases whenever blocks or elements change; a solver rebuilds its sparse pattern and
  /// symbolic factorization when it sees a new value.
  long structure_version() const { return structure_version_; }
  /// Replaces the configuration by one of another block layout (blocks split or merged) and
  /// marks the structure changed. Elements and Dirichlet conditions must be renumbered by the
  /// caller to the new layout (replace_element, set_fixed_dofs). Throws for non-finite values.
  void replace_state(Configuration state);
  /// Replaces the Dirichlet conditions by global dofs of the current layout.
  void set_fixed_dofs(std::vector<int> dofs);
  /// Throws spar::Error (naming `where`) unless the model can be evaluated as it stands: every
  /// element's blocks and every fixed dof in the configuration, finite coordinates, and every
  /// frame's R a rotation (‖RᵀR − I‖_F ≤ lie::rotation_tolerance, det R > 0). state() and
  /// replace_state let a user write anything there, so the solvers call this where they take the
  /// state (solve_static, modal_analysis, GeneralizedAlpha's constructor, initialize, step and
  /// remap). Costs one pass over the blocks and the elements' block lists.
  void check_consistent(std::string_view where) const;

private:
  void check_block(int block, const char* where) const;
  void check_element_index(int i, const char* where) const;
  void check_frame(int block, const char* where) const;

  Configuration state_;
  std::vector<std::unique_ptr<GeometricallyExactBeam>> beams_;
  std::vector<RigidBody> rigid_bodies_;
  std::vector<std::unique_ptr<Element>> elements_;
  std::vector<int> fixed_dofs_;
  int load_count_ = 0;
  Eigen::Vector3d gravity_ = Eigen::Vector3d::Zero();
  long structure_version_ = 0;
};

}  // namespace spar::core
