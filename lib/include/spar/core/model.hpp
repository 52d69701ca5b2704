#pragma once
/// \file
/// A model: nodes (the configuration space), beams, loads and Dirichlet conditions, and the
/// assembly of its internal and external generalized forces and their tangent.

#include <spar/core/beam.hpp>
#include <spar/core/beam_element.hpp>
#include <spar/core/configuration.hpp>
#include <spar/core/loads.hpp>
#include <spar/core/sparse_assembly.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::core {

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

  /// Adds an external load. Throws spar::Error for a node or beam that does not exist.
  void add_load(const Load& load);
  const std::vector<Load>& loads() const { return loads_; }

  /// Fixes the increments of a node's degrees of freedom (clamp = Fix::all). Throws spar::Error
  /// for a node that does not exist.
  void fix(int node, Fix what = Fix::all);
  /// The fixed global dofs, sorted, without duplicates.
  const std::vector<int>& fixed_dofs() const { return fixed_dofs_; }

  /// The dense blocks of the iteration matrix: one per beam element, then one per load whose
  /// tangent is not zero. Built once into a SparsePattern.
  std::vector<PatternBlock> pattern_blocks() const;

private:
  void check_node(int node, const char* where) const;

  Configuration reference_;
  Configuration state_;
  std::vector<GeometricallyExactBeam> beams_;
  std::vector<Load> loads_;
  std::vector<int> fixed_dofs_;
};

/// One contribution to the residual of a model: a generalized force on some nodes and, if asked,
/// its derivative along q ⊕ Δ (local increments).
struct NodalContribution {
  std::vector<int> nodes;
  Eigen::VectorXd force;    ///< 6 per node
  Eigen::MatrixXd tangent;  ///< ∂force(q ⊕ Δ)/∂Δ, or empty
};

/// The internal force of element (b, e) and, if `with_tangent`, its local tangent
/// H + ½ blockdiag(hat(m_I)) (core/beam_element.hpp).
void beam_element_contribution(const Model& model, int b, int e, const Configuration& q,
                               bool with_tangent, NodalContribution& out);

/// The external force of a load at load factor λ and, if `with_tangent`, its derivative along
/// q ⊕ Δ: zero for forces and material moments, ∂(Rᵀ M)/∂Δ = hat(Rᵀ M) for inertial moments.
void load_contribution(const Model& model, const Load& load, const Configuration& q,
                       double load_factor, bool with_tangent, NodalContribution& out);

/// True for loads that need a block of the iteration matrix (pattern_blocks()): moments, whose
/// generalized force depends on the rotation chart even when their local tangent is zero.
bool load_has_tangent(const Load& load);

}  // namespace spar::core
