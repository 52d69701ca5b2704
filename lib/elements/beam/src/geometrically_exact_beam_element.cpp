#include <spar/elements/beam/geometrically_exact_beam_element.hpp>

#include <spar/elements/beam/beam_element.hpp>
#include <spar/elements/beam/beam_inertia.hpp>

#include <Eigen/LU>

#include <cmath>

namespace spar::core {

std::vector<double> beam_shape_integrals(const GeometricallyExactBeam& beam, int e) {
  std::vector<double> integrals(static_cast<std::size_t>(beam.degree() + 1), 0.0);
  for (const BeamGaussPoint& gp : beam.element(e).gauss_points) {
    if (gp.part != 0) continue;  // the full rule (two points for p = 1)
    for (int I = 0; I <= beam.degree(); ++I) integrals[I] += gp.weight * gp.shape[I];
  }
  return integrals;
}

GeometricallyExactBeamElement::GeometricallyExactBeamElement(const GeometricallyExactBeam& beam,
                                                             int beam_index, int e)
    : beam_(&beam), beam_index_(beam_index), element_(e), shape_integrals_(beam_shape_integrals(beam, e)),
      inertia_(beam_element_inertia(beam, e)) {
  const int first = beam.node(beam.element(e).first_control_point);
  for (int I = 0; I <= beam.degree(); ++I) blocks_.push_back(first + I);
}

std::string GeometricallyExactBeamElement::name() const {
  return "beam " + std::to_string(beam_index_) + ", element " + std::to_string(element_);
}

std::string GeometricallyExactBeamElement::mass_defect() const {
  const SectionInertia& inertia = beam_->inertia();
  if (inertia.mass_per_length > 0.0 && std::abs(inertia.rotary.determinant()) > 0.0) return {};
  return "beam " + std::to_string(beam_index_) +
         " has no section inertia (zero mass per length or a singular rotary inertia): its freedoms "
         "have no mass; give the beam BeamParameters::inertia, e.g. "
         "core::SectionInertia::from(material, section)";
}

void GeometricallyExactBeamElement::compute(const ElementInput& in, const ElementRequest& request,
                                            ElementOutput& out) const {
  const Configuration& q = *in.q;
  const int k = static_cast<int>(blocks_.size());
  const int n = frame_dofs * k;

  // Strain energy: force and the exact stiffness along q ⊕ Δ (docs/beam.md B1–B12).
  BeamElementResult internal;
  const BeamEvaluation what = !request.residual && !request.stiffness ? BeamEvaluation::energy
                              : !request.stiffness             ? BeamEvaluation::force
                              : request.skip_rotation_blocks ? BeamEvaluation::force_and_translation_stiffness
                                                             : BeamEvaluation::force_and_stiffness;
  evaluate_beam_element(*beam_, element_, q, what, internal);
  if (request.residual) out.residual += internal.internal_force;
  if (request.stiffness) {
    out.stiffness += internal.stiffness;
    add_local_tangent_correction(internal.internal_force, out.stiffness);
  }
  out.energy.strain = internal.strain_energy;

  // Gravity: f_I = λ ρA g ∫ N_I dS, a dead load with potential −Σ f_I · x_I (x is linear in x_I).
  const double rho_a = beam_->inertia().mass_per_length;
  if (rho_a != 0.0 && in.gravity.squaredNorm() != 0.0)
    for (int I = 0; I < k; ++I) {
      const Eigen::Vector3d f = in.load_factor * rho_a * shape_integrals_[I] * in.gravity;
      if (request.residual) out.residual.segment<3>(frame_dofs * I) -= f;
      if (request.energy) out.energy.gravity -= f.dot(q.position[blocks_[I]]);
    }

  // Inertia (003 eqs. 30–32): M v̇ + f_gyr(v), M constant, C = ∂f_gyr/∂v.
  if (!in.dynamic()) return;
  // The element's frames are consecutive blocks: their velocities are one segment of the global
  // vector (gathered only if a change of the model's layout has split them).
  const Eigen::Index first = q.blocks[blocks_.front()].offset;
  bool contiguous = true;
  for (int I = 1; I < k; ++I) contiguous = contiguous && q.blocks[blocks_[I]].offset == first + frame_dofs * I;
  ElementVector v(n), a(n);
  if (contiguous) {
    v = in.velocity->segment(first, n);
    a = in.acceleration->segment(first, n);
  } else {
    gather(q, blocks_, *in.velocity, v);
    gather(q, blocks_, *in.acceleration, a);
  }
  if (request.residual) inertia_.add_force(v, a, out.residual);
  if (request.mass) inertia_.add_mass(out.mass);
  if (request.damping) inertia_.add_gyroscopic_tangent(v, out.damping);
  if (request.energy) out.energy.kinetic = inertia_.kinetic_energy(v);
}

}  // namespace spar::core
