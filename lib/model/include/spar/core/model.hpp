#pragma once
/// \file
/// A model: the configuration (blocks), the elements acting on it, the parts the element
/// families keep with it, Dirichlet conditions and gravity (docs/model.md). The model names no
/// element kind: each family builds its elements with free functions of its own
/// (core::add_beam, core::add_rigid_body, core::add_ancf_beam, core::add_load, …) through
/// add_frame, add_vector, add_element and add_part, and a user's own family does the same. The
/// solvers see only the blocks and the elements.

#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/error.hpp>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <string_view>
#include <typeindex>
#include <unordered_map>
#include <vector>

namespace spar::core {

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

  // Parts of element families -------------------------------------------------------------------

  /// Keeps an object of an element family with the model (a beam's geometry, a rigid body's data)
  /// and returns its index among the model's parts of its type. A family's builder adds it, its
  /// elements may refer to it (it stays where it is for the model's lifetime), and the family's
  /// accessors read it back (core::beam(model, b)). Throws spar::Error for a null part.
  template <class Part>
  int add_part(std::unique_ptr<const Part> part);
  /// The number of parts of type Part.
  template <class Part>
  int part_count() const;
  /// Part i of type Part; throws spar::Error naming `where` for an index that does not exist.
  template <class Part>
  const Part& part(int i, const char* where) const;

  /// Gravity acceleration (inertial frame) acting on every element with mass; read by the
  /// elements at every evaluation, so a change between steps takes effect at the next one.
  void set_gravity(const Eigen::Vector3d& g);
  const Eigen::Vector3d& gravity() const { return gravity_; }

  // Dirichlet conditions ---------------------------------------------------------------------------

  /// Fixes increments of a block (clamp = Fix::all). Throws spar::Error for a block that does not
  /// exist, or translations/rotations of a vector block.
  void fix(int block, Fix what = Fix::all);
  /// Fixes some coordinates of a vector block, given by their indices in the block: an ANCF
  /// node's slope r_x (coordinates 3, 4, 5 of [r, r_x]), a pinned cable end (0, 1, 2). Throws
  /// spar::Error for a block that does not exist, a frame block (fix frames with Fix), or a
  /// coordinate outside the block or given twice; a refused call fixes nothing.
  void fix_coordinates(int block, const std::vector<int>& coordinates);
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

  // Checks for the families' builders -------------------------------------------------------------

  /// Throws spar::Error (naming `where`) unless `block` is a block of the model.
  void check_block(int block, const char* where) const;
  /// Throws spar::Error (naming `where`) unless `block` is a frame block of the model.
  void check_frame(int block, const char* where) const;

private:
  void check_element_index(int i, const char* where) const;
  /// Inserts a global dof into fixed_dofs_ in place, keeping it sorted and free of duplicates.
  void add_fixed_dof(int dof);

  const std::vector<std::shared_ptr<const void>>* parts_of(std::type_index type) const;

  Configuration state_;
  std::vector<std::unique_ptr<Element>> elements_;
  /// The families' parts, one list per type; shared_ptr<const void> keeps each part's deleter.
  std::unordered_map<std::type_index, std::vector<std::shared_ptr<const void>>> parts_;
  std::vector<int> fixed_dofs_;
  Eigen::Vector3d gravity_ = Eigen::Vector3d::Zero();
  long structure_version_ = 0;
};

template <class Part>
int Model::add_part(std::unique_ptr<const Part> part) {
  if (!part) throw Error("null part", "core::Model::add_part", "pass the object to keep");
  std::vector<std::shared_ptr<const void>>& list = parts_[std::type_index(typeid(Part))];
  list.push_back(std::shared_ptr<const Part>(std::move(part)));
  ++structure_version_;
  return static_cast<int>(list.size()) - 1;
}

template <class Part>
int Model::part_count() const {
  const std::vector<std::shared_ptr<const void>>* list = parts_of(std::type_index(typeid(Part)));
  return list ? static_cast<int>(list->size()) : 0;
}

template <class Part>
const Part& Model::part(int i, const char* where) const {
  const int count = part_count<Part>();
  if (i < 0 || i >= count)
    throw Error("part " + std::to_string(i) + " of its kind does not exist (the model has " + std::to_string(count) +
                    ")",
                where, "use an index returned by the family's builder");
  return *static_cast<const Part*>((*parts_of(std::type_index(typeid(Part))))[static_cast<std::size_t>(i)].get());
}

}  // namespace spar::core
