#include <spar/elements/ancf/ancf_beam.hpp>

#include <spar/elements/ancf/ancf_beam_element.hpp>
#include <spar/elements/loads/vector_load_element.hpp>
#include <spar/error.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <memory>

namespace spar::core {

namespace {

template <int transverse>
void add_elements(Model& model, const AncfBeamParameters& p, double l, AncfBeam& beam) {
  // Equal elements share one set of tables (001 §6: "the invariants can be shared for elements
  // with equal dimensions").
  const auto tables =
      std::make_shared<const AncfElementTables<transverse>>(l, p.material, p.section, p.method, p.remedy, p.shear_factor);
  for (int e = 0; e < p.elements; ++e) {
    std::vector<int> blocks{beam.nodes[e], beam.nodes[e + 1]};
    if constexpr (transverse == 3) {
      beam.element_blocks.push_back(model.add_vector(Eigen::VectorXd::Zero(6)));
      blocks.push_back(beam.element_blocks.back());
    }
    beam.elements.push_back(model.add_element(std::make_unique<AncfBeamElement<transverse>>(
        std::move(blocks), tables, model.state(), model.element_count())));
  }
}

/// Throws spar::Error unless `node` is a vector block of 12 coordinates (r, r_x, r_y, r_z), the
/// kind of block add_ancf_beam makes a node of.
void check_ancf_node(const Configuration& q, int node, const char* where) {
  if (node < 0 || node >= q.block_count() || q.is_frame(node) || q.blocks[node].size != 12)
    throw Error("block " + std::to_string(node) + " is not an ANCF node", where, "give a node of core::add_ancf_beam");
}

}  // namespace

AncfBeam add_ancf_beam(Model& model, const AncfBeamParameters& p) {
  const char* where = "core::add_ancf_beam";
  if (p.elements < 1)
    throw Error("the beam has " + std::to_string(p.elements) + " elements", where, "give at least one");
  const Eigen::Vector3d axis = p.end - p.start;
  const double length = axis.norm();
  if (!(length > 0.0)) throw Error("start and end coincide", where, "give a beam of positive length");
  const Eigen::Vector3d t = axis / length;
  Eigen::Vector3d y = p.y_direction - p.y_direction.dot(t) * t;
  if (!(y.norm() > 1e-8 * p.y_direction.norm()))
    throw Error("the y direction is parallel to the beam", where, "give a y direction across the beam");
  y.normalize();
  const Eigen::Vector3d z = t.cross(y);
  // Checked before any block is added (the element tables would refuse the material only after
  // the nodes were in the model); a default SectionIntegrals has every integral zero.
  p.material.validate();
  check_ancf_shear_factor(p.shear_factor, where);
  if (!(p.section.area() > 0.0))
    throw Error("the section has an area of " + significant(p.section.area()), where,
                "give AncfBeamParameters::section, e.g. SectionIntegrals::circle(radius)");

  AncfBeam beam;
  beam.kind = p.kind;
  beam.element_length = length / p.elements;
  for (int k = 0; k <= p.elements; ++k) {
    Eigen::VectorXd node(12);
    node << p.start + (length * k / p.elements) * t, t, y, z;
    beam.nodes.push_back(model.add_vector(node));
  }
  if (p.kind == AncfElementKind::standard_24) add_elements<2>(model, p, beam.element_length, beam);
  else add_elements<3>(model, p, beam.element_length, beam);
  return beam;
}

Eigen::Vector3d ancf_node_position(const Configuration& q, int node) {
  check_ancf_node(q, node, "core::ancf_node_position");
  return q.vector(node).head<3>();
}

Eigen::MatrixXd sample_ancf_centerline(const Configuration& q, const AncfBeam& beam, int samples) {
  if (samples < 2 || beam.nodes.size() < 2)
    throw Error("need at least 2 samples of a beam with an element", "core::sample_ancf_centerline",
                "ask for 2 or more samples");
  const int elements = static_cast<int>(beam.nodes.size()) - 1;
  Eigen::MatrixXd points(samples, 3);
  for (int i = 0; i < samples; ++i) {
    const double s = static_cast<double>(i) * elements / (samples - 1);
    const int e = std::min(static_cast<int>(s), elements - 1);
    // r₀ = S1 r_A + S2 r_x,A + S5 r_B + S6 r_x,B (the axial functions are those of both kinds).
    const auto S = AncfShapeFunctions<2>::axial(s - e, beam.element_length);
    const auto A = q.vector(beam.nodes[e]), B = q.vector(beam.nodes[e + 1]);
    points.row(i) = (S[0] * A.head<3>() + S[1] * A.segment<3>(3) + S[2] * B.head<3>() + S[3] * B.segment<3>(3)).transpose();
  }
  return points;
}

int add_ancf_nodal_force(Model& model, int node, const Eigen::Vector3d& force, LoadHistory history) {
  check_ancf_node(model.state(), node, "core::add_ancf_nodal_force");
  Eigen::VectorXd f = Eigen::VectorXd::Zero(12);
  f.head<3>() = force;
  return model.add_element(std::make_unique<VectorLoadElement>(model.state(), node, std::move(f),
                                                                std::move(history), model.element_count()));
}

}  // namespace spar::core
