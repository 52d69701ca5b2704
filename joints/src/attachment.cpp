#include <spar/error.hpp>
#include <spar/joints/attachment.hpp>

#include <cmath>
#include <string>

namespace spar::joints {

void check_node(int node, const core::Configuration& q0, std::string_view where) {
  if (node < -1 || node >= q0.block_count())
    throw Error("node " + std::to_string(node) + " does not exist (the configuration has " +
                    std::to_string(q0.block_count()) + " blocks)",
                where, "attach to a node index in [0, block count) or to the ground with node = -1");
  if (node >= 0 && !q0.is_frame(node))
    throw Error("block " + std::to_string(node) + " is a vector block, not a frame (x, R)", where,
                "attach this joint to a frame block (a beam control point or a rigid body)");
}

const Eigen::Vector3d& finite_point(const Eigen::Vector3d& point, std::string_view name, std::string_view where) {
  if (!point.allFinite())
    throw Error("the " + std::string(name) + " has a NaN or infinite coordinate", where,
                "give finite coordinates in metres");
  return point;
}

Attachment attach_at(int node, const Eigen::Vector3d& point, const core::Configuration& q0) {
  check_node(node, q0, "joints::attach_at");
  finite_point(point, "attachment point", "joints::attach_at");
  if (node < 0) return {.node = -1, .offset = point};
  return {.node = node, .offset = q0.rotation[node].transpose() * (point - q0.position[node])};
}

JointFrames joint_frames(const Attachment& a, const Attachment& b, const core::Configuration& q0,
                         std::string_view where) {
  check_node(a.node, q0, where);
  check_node(b.node, q0, where);
  finite_point(a.offset, "offset of attachment a", where);
  finite_point(b.offset, "offset of attachment b", where);
  if (a.on_ground() && b.on_ground())
    throw Error("both attachments are on the ground", where,
                "attach at least one side to a node (node >= 0)");
  if (a.node == b.node)
    throw Error("both attachments are on the same node " + std::to_string(a.node), where,
                "a joint connects two different nodes, or a node and the ground (node = -1)");
  JointFrames frames;
  if (!a.on_ground()) {
    frames.a = {.node = a.node, .column = 0};
    frames.nodes.push_back(a.node);
  }
  if (!b.on_ground()) {
    frames.b = {.node = b.node, .column = core::frame_dofs * static_cast<int>(frames.nodes.size())};
    frames.nodes.push_back(b.node);
  }
  return frames;
}

JointFrame single_node_frame(int node, const core::Configuration& q0, std::string_view where) {
  check_node(node, q0, where);
  if (node < 0)
    throw Error(
        "the joint's attachment is on the ground", where,
        "attach it to a node (node >= 0): the ground cannot move along a line or be driven");
  return {.node = node, .column = 0};
}

Eigen::Vector3d unit_vector(const Eigen::Vector3d& direction, std::string_view name,
                            std::string_view where) {
  const double length = direction.norm();
  if (!std::isfinite(length) || length == 0.0)
    throw Error("the " + std::string(name) + " is zero or not finite", where,
                "give a non-zero " + std::string(name) + " in the inertial frame");
  return direction / length;
}

}  // namespace spar::joints
