#include <spar/core/element.hpp>
#include <spar/error.hpp>

#include <cmath>

namespace spar::core {

void ElementOutput::reset(int n, const ElementRequest& request) {
  // Sized even when not asked for: an element that computes it anyway writes in bounds.
  residual.setZero(n);
  if (request.stiffness) stiffness.setZero(n, n);
  if (request.damping) damping.setZero(n, n);
  if (request.mass) mass.setZero(n, n);
  energy = {};
  if (request.energy) external_force.setZero(n);
}

namespace {

/// The boundary check of Element::evaluate: the few fields of ElementInput that every element
/// reads, so that no kernel returns NaN for a NaN input or reads past a configuration.
void check_input(const Element& element, const ElementInput& in) {
  const auto refuse = [&element](const std::string& what, const std::string& fix) {
    throw InputError(what, "core::Element::evaluate (" + element.name() + ")", fix);
  };
  if (in.q == nullptr) refuse("ElementInput::q is null", "point it at the model's configuration");
  for (const int b : element.blocks())
    if (b < 0 || b >= in.q->block_count())
      refuse("the element's block " + std::to_string(b) + " is not in the configuration (" +
                 std::to_string(in.q->block_count()) + " blocks)",
             "evaluate the element in the configuration of the model it belongs to");
  if (!std::isfinite(in.load_factor))
    refuse("the load factor is " + significant(in.load_factor), "give a finite ElementInput::load_factor");
  if (!std::isfinite(in.time)) refuse("the time is " + significant(in.time), "give a finite ElementInput::time");
  if (!in.gravity.allFinite())
    refuse("the gravity has a non-finite component", "give a finite ElementInput::gravity");
  if ((in.velocity == nullptr) != (in.acceleration == nullptr))
    refuse("only one of velocity and acceleration is given",
           "give both (a dynamic evaluation) or neither (a static one)");
  const auto dofs = static_cast<Eigen::Index>(in.q->dof_count());
  if (in.velocity != nullptr && (in.velocity->size() != dofs || in.acceleration->size() != dofs))
    refuse("the velocity has " + std::to_string(in.velocity->size()) + " and the acceleration " +
               std::to_string(in.acceleration->size()) + " entries, the configuration " + std::to_string(dofs) +
               " dofs",
           "pass the model's velocity and acceleration in the global tangent layout");
}

}  // namespace

void Element::evaluate(const ElementInput& in, const ElementRequest& request, ElementOutput& out) const {
  check_input(*this, in);
  compute(in, request, out);
}

}  // namespace spar::core
