#include <spar/elements/loads/load_elements.hpp>

#include <spar/elements/beam/distributed_moment.hpp>
#include <spar/elements/beam/geometrically_exact_beam_element.hpp>
#include <spar/lie/hat.hpp>

#include <cmath>

namespace spar::core {

namespace {

/// Adds −f to the residual (an external force enters the dynamic residual, eq. M4, with a minus
/// sign) and, on an energy request, f to the external force whose work the integrator books.
void add_external_force(const Eigen::Ref<const Eigen::VectorXd>& f, const ElementRequest& request,
                        ElementOutput& out) {
  if (request.residual) out.residual -= f;
  if (request.energy) out.external_force += f;
}

}  // namespace

double load_scale(const ElementInput& in, const std::function<double(double)>& history) {
  if (!history) return in.load_factor;
  // Checked in statics too, which scales by λ alone: a NaN history was accepted there and
  // refused only by the dynamic run that started from the static state.
  const double factor = history(in.time);
  if (!std::isfinite(factor))
    throw InputError("the load history gives " + significant(factor) + " at t = " + significant(in.time),
                "core::add_load (LoadHistory)", "give a history that is finite at every time of the run");
  return in.dynamic() ? in.load_factor * factor : in.load_factor;
}

NodalLoadElement::NodalLoadElement(const Load& load, std::function<double(double)> history,
                                   int load_index)
    : load_(load), history_(std::move(history)), load_index_(load_index) {
  if (const auto* f = std::get_if<NodalForce>(&load_)) blocks_ = {f->node};
  if (const auto* m = std::get_if<NodalMoment>(&load_)) blocks_ = {m->node};
}

void NodalLoadElement::compute(const ElementInput& in, const ElementRequest& request,
                               ElementOutput& out) const {
  const double scale = load_scale(in, history_);
  Eigen::Matrix<double, frame_dofs, 1> f = Eigen::Matrix<double, frame_dofs, 1>::Zero();
  if (const auto* force = std::get_if<NodalForce>(&load_)) {
    f.head<3>() = scale * force->force;
  } else {
    const auto& moment = std::get<NodalMoment>(load_);
    // Virtual work δφᵀ M for a material moment; δφᵀ Rᵀ M for an inertial one (003 eq. 33).
    f.tail<3>() = (moment.frame == MomentFrame::material)
                      ? Eigen::Vector3d(scale * moment.moment)
                      : Eigen::Vector3d(scale * in.q->rotation[moment.node].transpose() * moment.moment);
    // A material moment is constant in local components; an inertial one gives
    // (R exp(Δ))ᵀ M = exp(−Δ) Rᵀ M ≈ RᵀM + hat(RᵀM) Δ, and enters the residual negatively.
    if (request.stiffness && moment.frame == MomentFrame::inertial)
      out.stiffness.bottomRightCorner<3, 3>() -= lie::hat(Eigen::Vector3d(f.tail<3>()));
  }
  add_external_force(f, request, out);
}

DistributedLoadElement::DistributedLoadElement(const Load& load, const GeometricallyExactBeam& beam,
                                               int e, std::function<double(double)> history,
                                               int load_index)
    : load_(load),
      beam_(&beam),
      element_(e),
      history_(std::move(history)),
      load_index_(load_index),
      shape_integrals_(beam_shape_integrals(beam, e)) {
  const int first = beam.node(beam.element(e).first_control_point);
  for (int I = 0; I <= beam.degree(); ++I) blocks_.push_back(first + I);
}

void DistributedLoadElement::compute(const ElementInput& in, const ElementRequest& request,
                                     ElementOutput& out) const {
  const double scale = load_scale(in, history_);
  const int n = frame_dofs * static_cast<int>(blocks_.size());
  if (const auto* force = std::get_if<DistributedForce>(&load_)) {
    // Consistent nodal forces f_I = ∫ N_I q dS (003 eq. 33).
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    for (std::size_t I = 0; I < blocks_.size(); ++I)
      f.segment<3>(frame_dofs * static_cast<Eigen::Index>(I)) =
          scale * shape_integrals_[I] * force->force_per_length;
    add_external_force(f, request, out);
    return;
  }
  const auto& moment = std::get<DistributedMoment>(load_);
  Eigen::VectorXd f;
  Eigen::MatrixXd tangent;
  distributed_moment_contribution(*beam_, element_, *in.q, scale * moment.moment_per_length,
                                  moment.frame, f, request.stiffness ? &tangent : nullptr);
  if (request.stiffness) out.stiffness -= tangent;
  add_external_force(f, request, out);
}

}  // namespace spar::core
