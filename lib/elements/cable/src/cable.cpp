#include <spar/elements/cable/cable.hpp>

#include <spar/error.hpp>

#include <memory>
#include <string>

namespace spar::core {

template <int Dim>
Cable add_cable(Model& model, const CableParameters& p) {
  const char* where = "core::add_cable";
  if (p.elements < 1)
    throw Error("a cable of " + std::to_string(p.elements) + " elements", where, "give at least one element");
  if (!p.start.allFinite() || !p.end.allFinite())
    throw Error("an end point of the cable has a NaN or infinite entry", where, "give finite end points");
  if (Dim == 2 && (p.start.z() != 0.0 || p.end.z() != 0.0))
    throw Error("a planar cable (Dim = 2) with end points off the X-Y plane", where,
                "give z = 0 for both end points, or build a spatial cable (Dim = 3)");
  const Eigen::Vector3d span = p.end - p.start;
  const double length = span.norm();
  if (!(length > 0.0)) throw Error("the cable's end points coincide", where, "give two distinct end points");
  // Every element is checked before the model changes: a refused cable leaves it as it was.
  const double h = length / p.elements;
  const RancfCableParameters element{.length = h, .section = p.section, .quadrature_points = p.quadrature_points};
  RancfCableParameters probe = element;  // placeholder blocks: only the values are checked here
  probe.node_a = 0;
  probe.node_b = 1;
  const RancfCableElement<Dim> checked(probe);

  Cable cable;
  cable.element_length = h;
  const Eigen::Vector3d direction = span / length;
  for (int i = 0; i <= p.elements; ++i) {
    Eigen::VectorXd node(2 * Dim);
    const Eigen::Vector3d r = p.start + (static_cast<double>(i) / p.elements) * span;
    node << r.head<Dim>(), direction.head<Dim>();
    cable.nodes.push_back(model.add_vector(node));
    if (p.ale) cable.materials.push_back(model.add_vector(Eigen::VectorXd::Constant(1, i * h)));
  }
  for (int i = 0; i < p.elements; ++i) {
    RancfCableParameters e = element;
    e.node_a = cable.nodes[i];
    e.node_b = cable.nodes[i + 1];
    e.name = p.name + " element " + std::to_string(i);
    if (p.ale) {
      e.material_a = cable.materials[i];
      e.material_b = cable.materials[i + 1];
      cable.elements.push_back(model.add_element(std::make_unique<AleRancfCableElement<Dim>>(e)));
    } else {
      cable.elements.push_back(model.add_element(std::make_unique<RancfCableElement<Dim>>(e)));
    }
  }
  return cable;
}

template Cable add_cable<2>(Model&, const CableParameters&);
template Cable add_cable<3>(Model&, const CableParameters&);

}  // namespace spar::core
