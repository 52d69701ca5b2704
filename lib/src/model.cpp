#include <spar/core/model.hpp>
#include <spar/core/distributed_moment.hpp>
#include <spar/error.hpp>
#include <spar/lie/hat.hpp>
#include <spar/lie/log.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <string>

namespace spar::core {

namespace {

/// The 6k global dofs of k consecutive nodes starting at `first`.
std::vector<int> node_dofs(int first, int count) {
  std::vector<int> dofs;
  for (int i = 0; i < dofs_per_node * count; ++i) dofs.push_back(dofs_per_node * first + i);
  return dofs;
}

}  // namespace

int Model::add_beam(const BeamParameters& parameters) {
  const int first_new = reference_.node_count();
  beams_.emplace_back(parameters, reference_);
  for (int k = first_new; k < reference_.node_count(); ++k)
    state_.add_node(reference_.position[k], reference_.rotation[k]);
  return beam_count() - 1;
}

const GeometricallyExactBeam& Model::beam(int b) const {
  if (b < 0 || b >= beam_count())
    throw Error("beam " + std::to_string(b) + " does not exist (the model has " +
                    std::to_string(beam_count()) + ")",
                "core::Model::beam", "use an index returned by add_beam");
  return beams_[b];
}

void Model::check_node(int node, const char* where) const {
  if (node < 0 || node >= node_count())
    throw Error("node " + std::to_string(node) + " does not exist (the model has " +
                    std::to_string(node_count()) + " nodes)",
                where, "use a node of a beam, e.g. beam.node(control_point)");
}

int Model::add_rigid_body(const RigidBodyParameters& p) {
  const char* where = "core::Model::add_rigid_body";
  if (!(p.mass > 0.0) || !std::isfinite(p.mass))
    throw Error("rigid body mass must be positive, got " + std::to_string(p.mass), where,
                "give the mass in kg");
  if (!p.inertia.allFinite() || (p.inertia - p.inertia.transpose()).norm() > 1e-12 * p.inertia.norm() ||
      !(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(p.inertia).eigenvalues().minCoeff() > 0.0))
    throw Error("rigid body inertia tensor is not symmetric positive definite", where,
                "give the inertia about the centre of mass in the body frame (kg m^2)");
  lie::check_rotation(p.rotation, where);
  const int node = reference_.add_node(p.center_of_mass, p.rotation);
  state_.add_node(p.center_of_mass, p.rotation);
  rigid_bodies_.push_back({node, p.mass, p.inertia});
  return rigid_body_count() - 1;
}

const RigidBody& Model::rigid_body(int b) const {
  if (b < 0 || b >= rigid_body_count())
    throw Error("rigid body " + std::to_string(b) + " does not exist", "core::Model::rigid_body",
                "use an index returned by add_rigid_body");
  return rigid_bodies_[b];
}

double Model::load_factor(int load, double t) const {
  return load_histories_[load] ? load_histories_[load](t) : 1.0;
}

Eigen::VectorXd Model::gravity_force() const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dof_count());
  for (int b = 0; b < beam_count(); ++b) {
    NodalContribution c;
    const double rho_a = beams_[b].inertia().mass_per_length;
    load_contribution(*this, DistributedForce{.beam = b, .force_per_length = rho_a * gravity_},
                      state_, 1.0, false, c);
    for (std::size_t I = 0; I < c.nodes.size(); ++I)
      f.segment<dofs_per_node>(dofs_per_node * c.nodes[I]) += c.force.segment<dofs_per_node>(dofs_per_node * I);
  }
  for (const RigidBody& body : rigid_bodies_)
    f.segment<3>(dofs_per_node * body.node) += body.mass * gravity_;
  return f;
}

double Model::gravity_potential(const Configuration& q) const {
  const Eigen::VectorXd f = gravity_force();
  double potential = 0.0;
  for (int k = 0; k < q.node_count(); ++k) potential -= f.segment<3>(dofs_per_node * k).dot(q.position[k]);
  return potential;
}

void Model::add_load(const Load& load, LoadHistory history) {
  if (const auto* f = std::get_if<NodalForce>(&load)) check_node(f->node, "core::Model::add_load");
  if (const auto* m = std::get_if<NodalMoment>(&load)) check_node(m->node, "core::Model::add_load");
  if (const auto* d = std::get_if<DistributedForce>(&load)) beam(d->beam);
  if (const auto* d = std::get_if<DistributedMoment>(&load)) beam(d->beam);
  loads_.push_back(load);
  load_histories_.push_back(std::move(history));
}

void Model::fix(int node, Fix what) {
  check_node(node, "core::Model::fix");
  const int first = (what == Fix::rotations) ? 3 : 0;
  const int last = (what == Fix::translations) ? 3 : 6;
  for (int i = first; i < last; ++i) fixed_dofs_.push_back(dofs_per_node * node + i);
  std::sort(fixed_dofs_.begin(), fixed_dofs_.end());
  fixed_dofs_.erase(std::unique(fixed_dofs_.begin(), fixed_dofs_.end()), fixed_dofs_.end());
}

std::vector<ModelBlock> Model::blocks() const {
  std::vector<ModelBlock> blocks;
  for (int b = 0; b < beam_count(); ++b)
    for (int e = 0; e < beams_[b].element_count(); ++e)
      blocks.push_back({ModelBlock::Kind::beam_element, b, e});
  for (int r = 0; r < rigid_body_count(); ++r) blocks.push_back({ModelBlock::Kind::rigid_body, r, 0});
  for (int l = 0; l < static_cast<int>(loads_.size()); ++l)
    if (const auto* m = std::get_if<DistributedMoment>(&loads_[l]))
      for (int e = 0; e < beams_[m->beam].element_count(); ++e)
        blocks.push_back({ModelBlock::Kind::load, l, e});
    else if (load_has_tangent(loads_[l]))
      blocks.push_back({ModelBlock::Kind::load, l, 0});
  return blocks;
}

std::vector<PatternBlock> Model::pattern_blocks() const {
  std::vector<PatternBlock> pattern;
  for (const ModelBlock& block : blocks()) {
    switch (block.kind) {
      case ModelBlock::Kind::beam_element: {
        const GeometricallyExactBeam& beam = beams_[block.index];
        pattern.push_back(PatternBlock::element(
            node_dofs(beam.node(beam.element(block.element).first_control_point), beam.degree() + 1)));
        break;
      }
      case ModelBlock::Kind::rigid_body:
        pattern.push_back(PatternBlock::element(node_dofs(rigid_bodies_[block.index].node, 1)));
        break;
      case ModelBlock::Kind::load:
        if (const auto* m = std::get_if<DistributedMoment>(&loads_[block.index])) {
          const GeometricallyExactBeam& beam = beams_[m->beam];
          pattern.push_back(PatternBlock::element(
              node_dofs(beam.node(beam.element(block.element).first_control_point), beam.degree() + 1)));
        } else {
          pattern.push_back(PatternBlock::element(node_dofs(std::get<NodalMoment>(loads_[block.index]).node, 1)));
        }
        break;
    }
  }
  return pattern;
}

void beam_element_contribution(const Model& model, int b, int e, const Configuration& q,
                               bool with_tangent, NodalContribution& out) {
  const GeometricallyExactBeam& beam = model.beam(b);
  BeamElementResult result;
  evaluate_beam_element(beam, e, q,
                        with_tangent ? BeamEvaluation::force_and_stiffness : BeamEvaluation::force,
                        result);
  const int first = beam.node(beam.element(e).first_control_point);
  out.nodes.resize(beam.degree() + 1);
  for (int I = 0; I <= beam.degree(); ++I) out.nodes[I] = first + I;
  out.force = result.internal_force;
  out.energy = result.strain_energy;
  if (!with_tangent) return;
  out.tangent = result.stiffness;
  add_local_tangent_correction(out.force, out.tangent);
}

bool load_has_tangent(const Load& load) {
  return std::holds_alternative<NodalMoment>(load) || std::holds_alternative<DistributedMoment>(load);
}

void load_contribution(const Model& model, const Load& load, const Configuration& q,
                       double load_factor, bool with_tangent, NodalContribution& out, int element) {
  out.tangent.resize(0, 0);
  out.energy = 0.0;
  if (const auto* m = std::get_if<DistributedMoment>(&load)) {
    distributed_moment_contribution(model.beam(m->beam), element, q,
                                    load_factor * m->moment_per_length, m->frame, with_tangent, out);
    return;
  }
  if (const auto* f = std::get_if<NodalForce>(&load)) {
    out.nodes = {f->node};
    out.force = Eigen::VectorXd::Zero(dofs_per_node);
    out.force.head<3>() = load_factor * f->force;
  } else if (const auto* m = std::get_if<NodalMoment>(&load)) {
    out.nodes = {m->node};
    out.force = Eigen::VectorXd::Zero(dofs_per_node);
    // Virtual work δφᵀ M for a material moment; δφᵀ Rᵀ M for an inertial one (003 eq. 33).
    const Eigen::Vector3d local = (m->frame == MomentFrame::material)
                                      ? Eigen::Vector3d(load_factor * m->moment)
                                      : Eigen::Vector3d(load_factor * q.rotation[m->node].transpose() * m->moment);
    out.force.tail<3>() = local;
    if (with_tangent) {
      // A material moment is constant in local components; an inertial one gives
      // (R exp(Δ))ᵀ M = exp(−Δ) Rᵀ M ≈ RᵀM + hat(RᵀM) Δ.
      out.tangent = Eigen::MatrixXd::Zero(dofs_per_node, dofs_per_node);
      if (m->frame == MomentFrame::inertial) out.tangent.bottomRightCorner<3, 3>() = lie::hat(local);
    }
  } else {
    // Consistent nodal forces f_I = ∫ N_I q dS (003 eq. 33), with the beam's Gauss points of
    // part 0 (for p = 1 the two-point rule, exact for these integrands on a straight beam).
    const auto& d = std::get<DistributedForce>(load);
    const GeometricallyExactBeam& beam = model.beam(d.beam);
    out.nodes.resize(beam.control_point_count());
    for (int I = 0; I < beam.control_point_count(); ++I) out.nodes[I] = beam.node(I);
    out.force = Eigen::VectorXd::Zero(dofs_per_node * beam.control_point_count());
    for (int e = 0; e < beam.element_count(); ++e) {
      const BeamElement& element = beam.element(e);
      for (const BeamGaussPoint& gp : element.gauss_points) {
        if (gp.part != 0) continue;
        for (int I = 0; I <= beam.degree(); ++I)
          out.force.segment<3>(dofs_per_node * (element.first_control_point + I)) +=
              load_factor * gp.weight * gp.shape[I] * d.force_per_length;
      }
    }
  }
}

}  // namespace spar::core
