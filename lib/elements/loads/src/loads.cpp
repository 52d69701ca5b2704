#include <spar/elements/loads/loads.hpp>

#include <spar/elements/beam/beam.hpp>
#include <spar/elements/loads/load_elements.hpp>
#include <spar/error.hpp>

#include <memory>
#include <string>
#include <utility>

namespace spar::core {

namespace {

void check_finite(const Eigen::Vector3d& value, const std::string& what, const char* where) {
  if (!value.allFinite()) throw Error(what + " has a NaN or infinite entry", where, "give finite values");
}

}  // namespace

int add_load(Model& model, const Load& load, LoadHistory history) {
  const char* where = "core::add_load";
  // Every check comes before the load is kept: a refused load leaves the model as it was.
  if (const auto* f = std::get_if<NodalForce>(&load)) {
    model.check_frame(f->node, where);
    check_finite(f->force, "the force", where);
  } else if (const auto* m = std::get_if<NodalMoment>(&load)) {
    model.check_frame(m->node, where);
    check_finite(m->moment, "the moment", where);
  }
  if (std::holds_alternative<NodalForce>(load) || std::holds_alternative<NodalMoment>(load)) {
    const int index = model.add_part(std::make_unique<const Load>(load));
    model.add_element(std::make_unique<NodalLoadElement>(load, std::move(history), index));
    return index;
  }
  const int b = std::holds_alternative<DistributedForce>(load) ? std::get<DistributedForce>(load).beam
                                                               : std::get<DistributedMoment>(load).beam;
  const GeometricallyExactBeam& carrier = beam(model, b);
  if (const auto* d = std::get_if<DistributedForce>(&load))
    check_finite(d->force_per_length, "the force per length", where);
  if (const auto* d = std::get_if<DistributedMoment>(&load))
    check_finite(d->moment_per_length, "the moment per length", where);
  const int index = model.add_part(std::make_unique<const Load>(load));
  for (int e = 0; e < carrier.element_count(); ++e)
    model.add_element(std::make_unique<DistributedLoadElement>(load, carrier, e, history, index));
  return index;
}

int load_count(const Model& model) { return model.part_count<Load>(); }

}  // namespace spar::core
