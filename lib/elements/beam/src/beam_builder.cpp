#include <spar/elements/beam/beam.hpp>

#include <spar/elements/beam/geometrically_exact_beam_element.hpp>
#include <spar/error.hpp>

#include <memory>
#include <string>

namespace spar::core {

int add_beam(Model& model, const BeamParameters& parameters) {
  const int b = model.add_part(std::make_unique<const GeometricallyExactBeam>(parameters, model.state()));
  const GeometricallyExactBeam& added = beam(model, b);
  for (int e = 0; e < added.element_count(); ++e)
    model.add_element(std::make_unique<GeometricallyExactBeamElement>(added, b, e));
  return b;
}

int beam_count(const Model& model) { return model.part_count<GeometricallyExactBeam>(); }

const GeometricallyExactBeam& beam(const Model& model, int b) {
  if (b < 0 || b >= beam_count(model))
    throw Error("beam " + std::to_string(b) + " does not exist (the model has " + std::to_string(beam_count(model)) +
                    ")",
                "core::beam", "use an index returned by add_beam");
  return model.part<GeometricallyExactBeam>(b, "core::beam");
}

}  // namespace spar::core
