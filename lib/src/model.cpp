#include <spar/core/model.hpp>

#include <spar/core/elements/geometrically_exact_beam_element.hpp>
#include <spar/core/elements/load_elements.hpp>
#include <spar/core/elements/rigid_body_element.hpp>
#include <spar/error.hpp>
#include <spar/lie/log.hpp>

#include <Eigen/Eigenvalues>

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

int Model::add_beam(const BeamParameters& parameters) {
  beams_.push_back(std::make_unique<GeometricallyExactBeam>(parameters, state_));
  ++structure_version_;
  const int b = beam_count() - 1;
  for (int e = 0; e < beams_[b]->element_count(); ++e)
    add_element(std::make_unique<GeometricallyExactBeamElement>(*beams_[b], b, e));
  return b;
}

const GeometricallyExactBeam& Model::beam(int b) const {
  if (b < 0 || b >= beam_count())
    throw Error("beam " + std::to_string(b) + " does not exist (the model has " +
                    std::to_string(beam_count()) + ")",
                "core::Model::beam", "use an index returned by add_beam");
  return *beams_[b];
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

int Model::add_rigid_body(const RigidBodyParameters& p) {
  const char* where = "core::Model::add_rigid_body";
  if (!(p.mass > 0.0) || !std::isfinite(p.mass))
    throw Error("rigid body mass must be positive and finite, got " + significant(p.mass), where,
                "give the mass in kg");
  check_finite(p.center_of_mass, "the centre of mass", where);
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
  const int node = add_frame(p.center_of_mass, p.rotation);
  rigid_bodies_.push_back({node, p.mass, p.inertia});
  const int index = rigid_body_count() - 1;
  add_element(std::make_unique<RigidBodyElement>(rigid_bodies_.back(), index));
  return index;
}

const RigidBody& Model::rigid_body(int b) const {
  if (b < 0 || b >= rigid_body_count())
    throw Error("rigid body " + std::to_string(b) + " does not exist", "core::Model::rigid_body",
                "use an index returned by add_rigid_body");
  return rigid_bodies_[b];
}

void Model::add_load(const Load& load, LoadHistory history) {
  const char* where = "core::Model::add_load";
  // The load is counted only once it is accepted: a refused load leaves the model as it was.
  const int index = load_count_;
  if (const auto* f = std::get_if<NodalForce>(&load)) {
    check_frame(f->node, where);
    check_finite(f->force, "the force", where);
  } else if (const auto* m = std::get_if<NodalMoment>(&load)) {
    check_frame(m->node, where);
    check_finite(m->moment, "the moment", where);
  }
  if (std::holds_alternative<NodalForce>(load) || std::holds_alternative<NodalMoment>(load)) {
    ++load_count_;
    add_element(std::make_unique<NodalLoadElement>(load, std::move(history), index));
    return;
  }
  const int b = std::holds_alternative<DistributedForce>(load) ? std::get<DistributedForce>(load).beam
                                                               : std::get<DistributedMoment>(load).beam;
  const GeometricallyExactBeam& carrier = beam(b);
  if (const auto* d = std::get_if<DistributedForce>(&load))
    check_finite(d->force_per_length, "the force per length", where);
  if (const auto* d = std::get_if<DistributedMoment>(&load))
    check_finite(d->moment_per_length, "the moment per length", where);
  ++load_count_;
  for (int e = 0; e < carrier.element_count(); ++e)
    add_element(std::make_unique<DistributedLoadElement>(load, carrier, e, history, index));
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
  // Kept sorted by inserting each dof in place (at the end when blocks are fixed in order): a sort
  // of the whole list per call made fixing a member's nodes one by one quadratic, 11 % of a
  // 2000-element truss run (issue 29).
  for (int i = first; i < last; ++i) {
    const int dof = b.offset + i;
    const auto at = std::lower_bound(fixed_dofs_.begin(), fixed_dofs_.end(), dof);
    if (at == fixed_dofs_.end() || *at != dof) fixed_dofs_.insert(at, dof);
  }
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
