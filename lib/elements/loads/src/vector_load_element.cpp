#include <spar/elements/loads/vector_load_element.hpp>

#include <spar/elements/loads/load_elements.hpp>
#include <spar/error.hpp>

namespace spar::core {

VectorLoadElement::VectorLoadElement(const Configuration& q, int block, Eigen::VectorXd force,
                                     std::function<double(double)> history, int load_index)
    : blocks_{block}, force_(std::move(force)), history_(std::move(history)), load_index_(load_index) {
  const char* where = "core::VectorLoadElement";
  if (block < 0 || block >= q.block_count() || q.is_frame(block))
    throw Error("block " + std::to_string(block) + " is not a vector block", where,
                "put a force on a frame block with core::NodalForce");
  if (force_.size() != q.blocks[block].size)
    throw Error("the force has " + std::to_string(force_.size()) + " entries, the block " +
                    std::to_string(q.blocks[block].size), where, "give one entry per coordinate");
  if (!force_.allFinite()) throw Error("the force is not finite", where, "check the load");
}

void VectorLoadElement::compute(const ElementInput& in, const ElementRequest& request,
                                ElementOutput& out) const {
  const double scale = load_scale(in, history_);
  if (request.residual) out.residual -= scale * force_;
  if (request.energy) out.external_force += scale * force_;  // its work: docs/dynamics.md D8
}

}  // namespace spar::core
