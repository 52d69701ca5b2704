#include <spar/core/model.hpp>

#include <spar/error.hpp>
#include <spar/lie/log.hpp>

#include <algorithm>
#include <string>

namespace spar::core {

namespace {

void check_finite(const Eigen::Ref<const Eigen::MatrixXd>& values, const std::string& what,
                  const char* where) {
  if (!values.allFinite())
    throw Error(what + " has a NaN or infinite entry", where, "give finite values");
}

}  // namespace

int Model::add_frame(const Eigen::Vector3d& x, const Eigen::Matrix3d& R) {
  const char* where = "core::Model::add_frame";
  check_finite(x, "the frame's position", where);
  lie::check_rotation(R, where);
  ++structure_version_;
  return state_.add_frame(x, R);
}

int Model::add_vector(const Eigen::VectorXd& p) {
  check_finite(p, "the vector block", "core::Model::add_vector");
  ++structure_version_;
  return state_.add_vector(p);
}

int Model::add_element(std::unique_ptr<Element> element) {
  const char* where = "core::Model::add_element";
  if (!element) throw Error("null element", where, "pass an element object");
  for (const int b : element->blocks()) check_block(b, where);
  elements_.push_back(std::move(element));
  ++structure_version_;
  return element_count() - 1;
}

const Element& Model::element(int i) const {
  check_element_index(i, "core::Model::element");
  return *elements_[i];
}

void Model::replace_element(int i, std::unique_ptr<Element> element) {
  const char* where = "core::Model::replace_element";
  check_element_index(i, where);
  if (!element) throw Error("null element", where, "pass an element object");
  for (const int b : element->blocks()) check_block(b, where);
  elements_[i] = std::move(element);
  ++structure_version_;
}

void Model::remove_element(int i) {
  check_element_index(i, "core::Model::remove_element");
  elements_.erase(elements_.begin() + i);
  ++structure_version_;
}

const std::vector<std::shared_ptr<const void>>* Model::parts_of(std::type_index type) const {
  const auto found = parts_.find(type);
  return found == parts_.end() ? nullptr : &found->second;
}

void Model::check_element_index(int i, const char* where) const {
  if (i < 0 || i >= element_count())
    throw Error("element " + std::to_string(i) + " does not exist (the model has " +
                    std::to_string(element_count()) + " elements)",
                where, "use an index below element_count(), as add_element returns them");
}

void Model::check_block(int block, const char* where) const {
  if (block < 0 || block >= block_count())
    throw Error("block " + std::to_string(block) + " does not exist (the model has " +
                    std::to_string(block_count()) + " blocks)",
                where, "use a block of the model, e.g. beam.node(control_point)");
}

void Model::check_frame(int block, const char* where) const {
  check_block(block, where);
  if (!state_.is_frame(block))
    throw Error("block " + std::to_string(block) + " is a vector block, not a frame", where,
                "apply forces, moments and rotation conditions to frame blocks");
}

void Model::set_gravity(const Eigen::Vector3d& g) {
  check_finite(g, "gravity", "core::Model::set_gravity");
  gravity_ = g;
}

void Model::fix(int block, Fix what) {
  const char* where = "core::Model::fix";
  check_block(block, where);
  const Block& b = state_.blocks[block];
  if (what != Fix::all && b.kind != BlockKind::frame)
    throw Error("translations or rotations of vector block " + std::to_string(block), where,
                "fix a vector block with Fix::all");
  const int first = (what == Fix::rotations) ? 3 : 0;
  const int last = (what == Fix::translations) ? 3 : b.size;
  for (int i = first; i < last; ++i) add_fixed_dof(b.offset + i);
}

void Model::fix_coordinates(int block, const std::vector<int>& coordinates) {
  const char* where = "core::Model::fix_coordinates";
  check_block(block, where);
  const Block& b = state_.blocks[block];
  if (b.kind != BlockKind::vector)
    throw Error("block " + std::to_string(block) + " is a frame", where,
                "fix a frame's translations or rotations with fix(block, Fix::translations or Fix::rotations)");
  std::vector<int> sorted = coordinates;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (sorted[i] < 0 || sorted[i] >= b.size)
      throw Error("coordinate " + std::to_string(sorted[i]) + " is outside vector block " + std::to_string(block) +
                      " of " + std::to_string(b.size) + " coordinates",
                  where, "give coordinates 0 … " + std::to_string(b.size - 1));
    if (i > 0 && sorted[i] == sorted[i - 1])
      throw Error("coordinate " + std::to_string(sorted[i]) + " is given twice", where, "give each coordinate once");
  }
  for (const int coordinate : sorted) add_fixed_dof(b.offset + coordinate);
}

// Kept sorted by inserting each dof in place (at the end when blocks are fixed in order): a sort of
// the whole list per call made fixing a member's nodes one by one quadratic, 11 % of a
// 2000-element truss run (issue 29).
void Model::add_fixed_dof(int dof) {
  const auto at = std::lower_bound(fixed_dofs_.begin(), fixed_dofs_.end(), dof);
  if (at == fixed_dofs_.end() || *at != dof) fixed_dofs_.insert(at, dof);
}

void Model::replace_state(Configuration state) {
  const char* where = "core::Model::replace_state";
  check_finite(state.values, "the new configuration", where);
  for (int b = 0; b < state.block_count(); ++b)
    if (state.is_frame(b)) {
      check_finite(state.position[b], "a frame position of the new configuration", where);
      lie::check_rotation(state.rotation[b], where);
    }
  state_ = std::move(state);
  ++structure_version_;
}

namespace {

/// A frame block's R must be a rotation to lie::rotation_tolerance = 1e-9 in ‖RᵀR − I‖_F, the
/// tolerance of add_frame and of lie::log (which the beam elements take of relative rotations, so
/// a looser check here would only move the refusal into an element, as a failed iteration). The
/// solvers' own updates R ← R exp(Δφ) stay far inside it: 10⁷ random updates of 0.01 rad drift
/// by 9e-13 (growing as √N: 4e-15 after 10³, 1e-13 after 10⁵), a thousandth of the tolerance.
/// det R > 0 then tells a rotation from a reflection, whose det is −1 to the same accuracy.
void check_frame_state(const Configuration& q, int b, std::string_view where) {
  const std::string block = "block " + std::to_string(b);
  if (!q.position[b].allFinite())
    throw Error("the position of " + block + " has a NaN or infinite entry", where,
                "write finite positions into Model::state()");
  const Eigen::Matrix3d& R = q.rotation[b];
  if (!R.allFinite())
    throw Error("the rotation of " + block + " has a NaN or infinite entry", where,
                "write rotation matrices into Model::state()");
  const double orthogonality = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
  if (!(orthogonality <= lie::rotation_tolerance))
    throw Error("the rotation of " + block + " is not a rotation: |R^T R - I| = " + significant(orthogonality) +
                    " > " + significant(lie::rotation_tolerance),
                where, "write rotation matrices into Model::state() (re-orthogonalize a computed one)");
  if (!(R.determinant() > 0.0))
    throw Error("the rotation of " + block + " is a reflection (det R = " + significant(R.determinant()) + ")", where,
                "write proper rotations (det R = +1) into Model::state()");
}

}  // namespace

void Model::check_consistent(std::string_view where) const {
  const int blocks = state_.block_count();
  for (int i = 0; i < element_count(); ++i)
    for (const int b : elements_[i]->blocks())
      if (b < 0 || b >= blocks)
        throw Error("element " + std::to_string(i) + " (" + elements_[i]->name() + ") acts on block " +
                        std::to_string(b) + ", which the configuration (" + std::to_string(blocks) +
                        " blocks) does not have",
                    where, "after Model::replace_state, renumber the elements with replace_element");
  for (const int dof : fixed_dofs_)
    if (dof >= dof_count())
      throw Error("fixed dof " + std::to_string(dof) + " is outside the configuration's " +
                      std::to_string(dof_count()) + " dofs",
                  where, "after Model::replace_state, renumber the Dirichlet conditions with set_fixed_dofs");
  if (!state_.values.allFinite())
    throw Error("a vector block of the configuration has a NaN or infinite entry", where,
                "write finite coordinates into Model::state()");
  for (int b = 0; b < blocks; ++b)
    if (state_.is_frame(b)) check_frame_state(state_, b, where);
}

void Model::set_fixed_dofs(std::vector<int> dofs) {
  for (const int dof : dofs)
    if (dof < 0 || dof >= dof_count())
      throw Error("fixed dof " + std::to_string(dof) + " is outside [0, " + std::to_string(dof_count()) + ")",
                  "core::Model::set_fixed_dofs", "give global dofs of the current layout");
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  fixed_dofs_ = std::move(dofs);
}

}  // namespace spar::core
