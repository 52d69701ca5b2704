#include <spar/elements/cable/cable_centerline.hpp>

#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/error.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <algorithm>
#include <string>

namespace spar::core {

CableCenterline::CableCenterline(const Model& model, const std::vector<int>& elements) {
  constexpr const char* where = "core::CableCenterline";
  if (elements.empty()) throw Error("no element", where, "give the cable's elements from one end to the other");
  breakpoints_.push_back(0.0);
  for (const int index : elements) {
    const auto* element = dynamic_cast<const RancfCableElement<3>*>(&model.element(index));
    if (!element)
      throw Error("element " + std::to_string(index) + " (" + model.element(index).name() +
                      ") is not a spatial fixed-length RANCF cable element",
                  where, "give core::RancfCableElement<3> elements");
    const RancfCableParameters& p = element->parameters();
    if (nodes_.empty()) nodes_.push_back(p.node_a);
    if (p.node_a != nodes_.back())
      throw Error("element " + std::to_string(index) + " starts at block " + std::to_string(p.node_a) +
                      ", the previous one ends at block " + std::to_string(nodes_.back()),
                  where, "give the elements in their order along the cable");
    nodes_.push_back(p.node_b);
    lengths_.push_back(p.length);
    breakpoints_.push_back(breakpoints_.back() + p.length);
    weights_.push_back(p.weights);
  }
}

int CableCenterline::segment_at(double zeta) const {
  const auto after = std::upper_bound(breakpoints_.begin() + 1, breakpoints_.end() - 1, zeta);
  return static_cast<int>(after - breakpoints_.begin()) - 1;
}

// r = s₁ r_A + s₂ r_x^A + s₃ r_B + s₄ r_x^B (000 eqs. (7)–(9)); iga::rancf_shape_function_derivatives
// gives d^d/du^d of [s₁, s₂/l, s₃, s₄/l], and d/dζ = (1/l) d/du.
void CableCenterline::compute_basis(double zeta, int order, CurvePoint& p) const {
  const int k = segment_at(zeta);
  const double l = lengths_[k];
  const Eigen::Matrix4d s = iga::rancf_shape_function_derivatives((zeta - breakpoints_[k]) / l, weights_[k]);
  p.segment = k;
  p.first_block = k;
  p.block_count = 2;
  p.coefficient_count = 4;
  p.coefficients[0] = {.block = nodes_[k], .coordinate = 0, .column = 0};
  p.coefficients[1] = {.block = nodes_[k], .coordinate = 3, .column = 3};
  p.coefficients[2] = {.block = nodes_[k + 1], .coordinate = 0, .column = 6};
  p.coefficients[3] = {.block = nodes_[k + 1], .coordinate = 3, .column = 9};
  const Eigen::Vector4d slope_factor(1.0, l, 1.0, l);
  double scale = 1.0;
  for (int d = 0; d <= order; ++d) {
    for (int i = 0; i < 4; ++i) p.shape(d, i) = s(i, d) * slope_factor(i) * scale;
    scale /= l;
  }
}

std::shared_ptr<const Curve> cable_centerline(const Model& model, const std::vector<int>& elements) {
  return std::make_shared<CableCenterline>(model, elements);
}

}  // namespace spar::core
