#include <spar/core/element.hpp>
#include <spar/error.hpp>

#include <cmath>
#include <string>

namespace spar::core {

void ElementOutput::reset(int n, const ElementRequest& request) {
  // Sized even when not asked for: an element that computes it anyway writes in bounds.
  residual.setZero(n);
  if (request.stiffness) stiffness.setZero(n, n);
  if (request.damping) damping.setZero(n, n);
  if (request.mass) mass.setZero(n, n);
  energy = {};
  if (request.energy) {
    external_force.setZero(n);
    dissipative_force.setZero(n);
  }
}

namespace {

/// Refuses a NaN or infinite entry of the global tangent-layout vector `values` at the element's
/// blocks (a NaN velocity made 12 of a beam element's 24 residual entries NaN). A plain
/// spar::Error, not an InputError: inside a solver these values come from the iteration (an
/// increment that overflowed), which a shorter step may avoid.
void check_finite_entries(const Element& element, const Configuration& q, const Eigen::VectorXd& values,
                          const char* name) {
  for (const int b : element.blocks())
    for (int i = q.blocks[b].offset; i < q.blocks[b].offset + q.blocks[b].size; ++i)
      if (!std::isfinite(values(i)))
        throw Error(std::string("the ") + name + " has a non-finite entry (" + significant(values(i)) +
                             ") at dof " + std::to_string(i),
                         "core::Element::evaluate (" + element.name() + ")",
                         std::string("give a finite ElementInput::") + name);
}

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
  if (in.velocity != nullptr) {
    // Only the element's own entries: what it reads, at the cost of its size, not the model's.
    check_finite_entries(element, *in.q, *in.velocity, "velocity");
    check_finite_entries(element, *in.q, *in.acceleration, "acceleration");
  }
}

/// The output must be sized as ElementOutput::reset sizes it for the element and the request:
/// the kernels write into it without bounds checks.
void check_output(const Element& element, const Configuration& q, const ElementRequest& request,
                  const ElementOutput& out) {
  const Eigen::Index n = block_dof_count(q, element.blocks());
  const auto square = [n](const Eigen::MatrixXd& m) { return m.rows() == n && m.cols() == n; };
  const auto size = [](const Eigen::MatrixXd& m) { return std::to_string(m.rows()) + "x" + std::to_string(m.cols()); };
  std::string wrong;
  if (out.residual.size() != n) wrong = "a residual of " + std::to_string(out.residual.size()) + " entries";
  else if (request.stiffness && !square(out.stiffness)) wrong = "a stiffness of " + size(out.stiffness);
  else if (request.damping && !square(out.damping)) wrong = "a damping of " + size(out.damping);
  else if (request.mass && !square(out.mass)) wrong = "a mass of " + size(out.mass);
  else if (request.energy && out.external_force.size() != n)
    wrong = "an external force of " + std::to_string(out.external_force.size()) + " entries";
  else if (request.energy && out.dissipative_force.size() != n)
    wrong = "a dissipative force of " + std::to_string(out.dissipative_force.size()) + " entries";
  if (!wrong.empty())
    throw InputError("the output holds " + wrong + " for the element's " + std::to_string(n) + " dofs",
                     "core::Element::evaluate (" + element.name() + ")",
                     "call ElementOutput::reset(dofs, request) before evaluate");
}

}  // namespace

void Element::evaluate(const ElementInput& in, const ElementRequest& request, ElementOutput& out) const {
  check_input(*this, in);
  check_output(*this, *in.q, request, out);
  compute(in, request, out);
}

}  // namespace spar::core
