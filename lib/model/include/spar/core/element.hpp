#pragma once
/// \file
/// The Element interface: everything the solvers know of a beam element, a rigid body, a load or
/// gravity (docs/model.md, "Elements"). A new element kind is one class implementing it; no
/// solver changes.
///
/// An element acts on a list of blocks of the configuration (core/configuration.hpp). Its local
/// vectors and matrices are ordered block after block, each block's increments in the block's own
/// order (6 for a frame: Δx, Δφ; n for a vector). On request it returns its part of the dynamic
/// residual
///     r = M(q) v̇ + f_qv(q, v) + f_int(q, v) − f_ext(q, t)                      (eq. M4)
/// (inertia only when the evaluation is dynamic) and the derivatives the iteration matrix needs:
///     stiffness K = ∂r(q ⊕ Δ, v, v̇)/∂Δ at Δ = 0 (local increments, eq. M5),
///     damping   C = ∂r/∂v,
///     mass      M = ∂r/∂v̇.
/// A configuration-dependent mass matrix contributes ∂(M(q) v̇)/∂q to K. On an energy request an
/// element also reports its energies and the external force of its non-potential loads.

#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::core {

/// What to compute (deal.II-style update flags): the hot path asks only for what it uses.
struct ElementRequest {
  bool residual = true;
  bool stiffness = false;
  bool damping = false;
  bool mass = false;
  /// Kinetic energy, gravity potential and external force (the strain energy comes with the
  /// residual of elements that have one, at no cost).
  bool energy = false;
  /// The caller keeps the rotation–rotation blocks of every frame block (003's frozen iteration
  /// matrix) and overwrites them: an element may leave them out of K, C and M to save time.
  bool skip_rotation_blocks = false;
};

/// The state an element is evaluated in.
struct ElementInput {
  const Configuration* q = nullptr;
  /// Global tangent-layout velocity and acceleration; both nullptr in statics.
  const Eigen::VectorXd* velocity = nullptr;
  const Eigen::VectorXd* acceleration = nullptr;
  double time = 0.0;
  /// The factor on every external load and on gravity: the load factor λ in statics, 1 in
  /// dynamics (where a load's own history(t) scales it).
  double load_factor = 1.0;
  /// The gravity acceleration (inertial frame) of the model.
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();

  bool dynamic() const { return velocity != nullptr; }
};

/// Energies of one element (J).
struct ElementEnergy {
  double kinetic = 0.0;
  double strain = 0.0;
  double gravity = 0.0;  ///< gravity potential −∫ ρ g · x
};

/// What an element returns; owned by the caller and reused across calls, so a kernel that resizes
/// to the same size every time allocates nothing after the first call.
struct ElementOutput {
  Eigen::VectorXd residual;
  Eigen::MatrixXd stiffness;
  Eigen::MatrixXd damping;
  Eigen::MatrixXd mass;
  ElementEnergy energy;
  /// With `energy`: the external generalized force f_ext of the element's loads (its part of −r),
  /// which report no potential in `energy`: the integrator books their work (docs/dynamics.md D8).
  /// reset() sizes and zeroes it on an energy request only: on any other it keeps what an earlier
  /// call left (or is empty), and an element writes it only when `energy` is asked for.
  Eigen::VectorXd external_force;
  /// With `energy`, for an element that has_dissipation(): its dissipative generalized force f_d
  /// (a damper, the Kelvin–Voigt stresses of a cable), the part of r whose power v·f_d ≥ 0 leaves
  /// the motion as heat. The integrator books its work as the physical dissipation, apart from
  /// its own numerical dissipation (docs/dynamics.md D8). Sized and zeroed like external_force.
  Eigen::VectorXd dissipative_force;

  /// Sizes and zeroes what `request` asks for (and the residual always), for an element with n
  /// local dofs.
  void reset(int n, const ElementRequest& request);
};

class Element {
public:
  virtual ~Element() = default;

  /// The blocks the element couples, in the order of its local vectors.
  virtual const std::vector<int>& blocks() const = 0;
  /// Fills `out` (already reset to the element's size for `request`) at `in`, after checking
  /// `in` and `out` at this boundary (a spar::InputError names the element and the field): a
  /// configuration that holds the element's blocks, a finite time, load factor and gravity, a
  /// velocity and acceleration, when given, of the configuration's size, and an output sized by
  /// ElementOutput::reset for the element's dofs and `request`. A velocity or acceleration with
  /// a non-finite entry at the element's blocks is a spar::Error, as is a configuration the
  /// element cannot evaluate (e.g. a beam section turned by π): the solvers treat those as a
  /// failed iteration. The checks cost a pass over the element's blocks, not the model's.
  void evaluate(const ElementInput& in, const ElementRequest& request, ElementOutput& out) const;
  /// A short name for messages ("beam 1, element 3").
  virtual std::string name() const = 0;
  /// True for an element whose residual holds an external force without a potential (a load):
  /// ElementOutput::external_force on an energy request. The integrator books that force's work
  /// at every step, and when its Newton test needs nothing else of the elements (the dynamic
  /// residual untested) it evaluates these elements alone (docs/dynamics.md D8). An element that
  /// returns an external force must say so here, or its work is missing from such runs' balance.
  virtual bool has_external_force() const { return false; }
  /// In dynamics: why this element leaves some of its freedoms without mass, and how to give
  /// them mass (a beam whose section has no inertia), in words for an error message; empty when
  /// every freedom it couples has mass from it. GeneralizedAlpha adds these words to the error of
  /// a singular iteration matrix, so a family names its own defect and the integrator none.
  virtual std::string mass_defect() const { return {}; }
  /// True for an element with dissipative forces (ElementOutput::dissipative_force on an energy
  /// request). The integrator evaluates these elements at every step to book their work; an
  /// element that dissipates without saying so has its heat counted as numerical dissipation.
  virtual bool has_dissipation() const { return false; }
  /// False for an element whose static forces derive from no potential (a moment load: no
  /// potential gives its work on 3D rotations). solve_static then does not judge stability by the
  /// energy (StaticReport::unstable_directions = −1, docs/errors.md).
  virtual bool has_potential() const { return true; }

private:
  /// The element's own computation behind evaluate(), which has checked `in` (the
  /// non-virtual-interface idiom: every element kind gets the same checks, no kernel repeats them).
  virtual void compute(const ElementInput& in, const ElementRequest& request,
                       ElementOutput& out) const = 0;
};

}  // namespace spar::core
