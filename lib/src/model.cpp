#include <spar/core/model.hpp>
#include <spar/error.hpp>
#include <spar/lie/hat.hpp>

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

void Model::add_load(const Load& load) {
  if (const auto* f = std::get_if<NodalForce>(&load)) check_node(f->node, "core::Model::add_load");
  if (const auto* m = std::get_if<NodalMoment>(&load)) check_node(m->node, "core::Model::add_load");
  if (const auto* d = std::get_if<DistributedForce>(&load)) beam(d->beam);
  loads_.push_back(load);
}

void Model::fix(int node, Fix what) {
  check_node(node, "core::Model::fix");
  const int first = (what == Fix::rotations) ? 3 : 0;
  const int last = (what == Fix::translations) ? 3 : 6;
  for (int i = first; i < last; ++i) fixed_dofs_.push_back(dofs_per_node * node + i);
  std::sort(fixed_dofs_.begin(), fixed_dofs_.end());
  fixed_dofs_.erase(std::unique(fixed_dofs_.begin(), fixed_dofs_.end()), fixed_dofs_.end());
}

std::vector<PatternBlock> Model::pattern_blocks() const {
  std::vector<PatternBlock> blocks;
  for (const GeometricallyExactBeam& beam : beams_)
    for (int e = 0; e < beam.element_count(); ++e)
      blocks.push_back(PatternBlock::element(
          node_dofs(beam.node(beam.element(e).first_control_point), beam.degree() + 1)));
  for (const Load& load : loads_)
    if (load_has_tangent(load))
      blocks.push_back(PatternBlock::element(node_dofs(std::get<NodalMoment>(load).node, 1)));
  return blocks;
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
  if (!with_tangent) return;
  out.tangent = result.stiffness;
  add_local_tangent_correction(out.force, out.tangent);
}

bool load_has_tangent(const Load& load) { return std::holds_alternative<NodalMoment>(load); }

void load_contribution(const Model& model, const Load& load, const Configuration& q,
                       double load_factor, bool with_tangent, NodalContribution& out) {
  out.tangent.resize(0, 0);
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
