#include <spar/elements/rigid_body/point_mass_element.hpp>

#include <spar/error.hpp>

#include <cmath>

namespace spar::core {

PointMassElement::PointMassElement(const PointMassParameters& parameters)
    : parameters_(parameters), blocks_{parameters.block} {
  constexpr const char* where = "core::PointMassElement";
  if (parameters_.block < 0) throw Error("no block given", where, "give the node's vector block");
  if (parameters_.dimension != 2 && parameters_.dimension != 3)
    throw Error("dimension " + std::to_string(parameters_.dimension), where, "use 2 or 3");
  if (!(parameters_.mass > 0.0) || !std::isfinite(parameters_.mass))
    throw Error("mass " + std::to_string(parameters_.mass) + " is not positive", where, "give m > 0");
}

void PointMassElement::compute(const ElementInput& in, const ElementRequest& request,
                               ElementOutput& out) const {
  const Configuration& q = *in.q;
  const int b = blocks_[0], d = parameters_.dimension;
  if (q.is_frame(b) || q.blocks[b].size < d)
    throw Error("block " + std::to_string(b) + " is not a vector block of ≥ " + std::to_string(d) +
                    " entries",
                parameters_.name, "put the point mass on a node's vector block");
  const double m = parameters_.mass;
  // Weight m g: potential −m g·r, residual −m g.
  // (Entry by entry: d is 2 or 3, which GCC cannot see through a head(d) of a 3-vector.)
  const Eigen::Vector3d weight = in.load_factor * m * in.gravity;
  for (int i = 0; i < d; ++i) {
    if (request.residual) out.residual(i) -= weight(i);
    if (request.energy) out.energy.gravity -= weight(i) * q.vector(b)(i);
  }
  if (!in.dynamic()) return;
  const int offset = q.blocks[b].offset;
  if (request.residual) out.residual.head(d) += m * in.acceleration->segment(offset, d);
  if (request.mass) out.mass.topLeftCorner(d, d).diagonal().array() += m;
  if (request.energy) out.energy.kinetic = 0.5 * m * in.velocity->segment(offset, d).squaredNorm();
}

}  // namespace spar::core
