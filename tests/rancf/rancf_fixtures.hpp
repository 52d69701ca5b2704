#pragma once
// Shared fixtures of the RANCF tests: one element's blocks in a configuration, a deformed random
// state, an evaluation helper and the elements' derivative check (core::check_element).
#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/core/check_element.hpp>
#include <spar/core/model.hpp>

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <memory>
#include <random>
#include <vector>

namespace spar::test {

/// One element's configuration: node A [r, r_x], node B [r, r_x], and (ALE) x_A, x_B scalars.
struct RancfState {
  core::Configuration q;
  Eigen::VectorXd v, a;
  core::RancfCableParameters parameters;
};

inline core::RancfSection rancf_test_section() {
  // EA/EI = 1e3: axial and bending forces of comparable size for the O(0.1) strains below;
  // c = 0.05 s makes the Kelvin–Voigt forces a few % to 10 % of the elastic ones at these rates.
  return {.axial_stiffness = 1e3, .bending_stiffness = 1.0, .mass_per_length = 2.0,
          .damping_coefficient = 0.05};
}

/// A deformed element of length ≈ 0.8 with random perturbations of size 0.1, random velocities
/// and accelerations; `weights` on the element, x_A = 0.3, x_B = 1.1 (plus 0.05 noise).
template <int Dim>
RancfState random_rancf_state(unsigned seed, const Eigen::Vector4d& weights, bool ale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  const auto random_vector = [&](int n) {
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x(i) = noise(rng);
    return x;
  };
  RancfState s;
  const double l = 0.8;
  Eigen::VectorXd node_a = random_vector(2 * Dim), node_b = random_vector(2 * Dim);
  node_a(Dim) += 1.0;                 // r_x^A ≈ e_1
  node_b(0) += l;                     // r_B ≈ l e_1
  node_b(Dim) += 1.0;                 // r_x^B ≈ e_1
  node_b(Dim + 1) += 0.3;             // bent
  s.parameters.node_a = s.q.add_vector(node_a);
  s.parameters.node_b = s.q.add_vector(node_b);
  s.parameters.length = l;
  if (ale) {
    const double x_a = 0.3 + 0.5 * noise(rng);
    s.parameters.material_a = s.q.add_vector(Eigen::VectorXd::Constant(1, x_a));
    s.parameters.material_b = s.q.add_vector(Eigen::VectorXd::Constant(1, x_a + l + 0.5 * noise(rng)));
  }
  s.parameters.section = rancf_test_section();
  s.parameters.weights = weights;
  s.v = 5.0 * random_vector(s.q.dof_count());
  s.a = 50.0 * random_vector(s.q.dof_count());
  return s;
}

/// Evaluates everything at (q, v, a); statics when v is null.
inline core::ElementOutput evaluate_all(const core::Element& element, const core::Configuration& q,
                                        const Eigen::VectorXd* v, const Eigen::VectorXd* a,
                                        const Eigen::Vector3d& gravity) {
  core::ElementInput in;
  in.q = &q;
  in.velocity = v;
  in.acceleration = a;
  in.gravity = gravity;
  const core::ElementRequest request{.residual = true, .stiffness = true, .damping = v != nullptr,
                                     .mass = v != nullptr, .energy = true};
  core::ElementOutput out;
  out.reset(core::block_dof_count(q, element.blocks()), request);
  element.evaluate(in, request, out);
  return out;
}

// The elements' derivatives against central differences of their residual (core::check_element),
// with h = 1e-6 on O(1) coordinates: truncation h² |r'''| ~ 1e-12 relative and round-off ε |r|/h ~
// 1e-10 relative (the residual's terms are up to 1e2 times the largest Jacobian entry over the
// entries' scale), so 1e-7 relative to the largest entry of each difference leaves a wide margin;
// a wrong term is O(1). The residual is exactly quadratic in v and linear in v̇, so central
// differences in them have no truncation error at all: a large step keeps the round-off ε |r|/h
// small.
inline constexpr core::ElementCheckOptions rancf_check_options{
    .step = 1e-6, .rate_step = 1e-2, .tolerance = 1e-7, .scale_floor = 0.0};

/// CHECKs the element's stiffness at the state `s` — statics unless `dynamic` — and in dynamics its
/// damping and mass, with core::check_element; with `potential` (statics) also its residual
/// against the gradient of its strain and gravity energy.
inline void check_rancf_derivatives(const core::Element& element, const RancfState& s, const Eigen::Vector3d& gravity,
                                    bool dynamic, bool potential = false) {
  core::ElementInput in{.q = &s.q, .gravity = gravity};
  if (dynamic) {
    in.velocity = &s.v;
    in.acceleration = &s.a;
  }
  core::ElementCheckOptions options = rancf_check_options;
  options.potential = potential;
  const core::DerivativeCheck check = core::check_element(element, in, options);
  INFO(check.description());
  CHECK(check.passed());
}

/// A straight cable along +X of `elements` equal elements (unit weights: a straight line with
/// r_x = e_1 is stress-free only when the parameterization is by arc length), fixed-length RANCF
/// or ALE-RANCF (material coordinates as scalar blocks, x_i = i L/elements).
struct RancfCable {
  core::Model model;
  std::vector<int> nodes;      ///< [r, r_x] blocks
  std::vector<int> materials;  ///< x blocks (ALE only)
};

template <int Dim>
RancfCable make_straight_cable(int elements, double length, const core::RancfSection& section, bool ale) {
  RancfCable c;
  const double h = length / elements;
  for (int i = 0; i <= elements; ++i) {
    Eigen::VectorXd node = Eigen::VectorXd::Zero(2 * Dim);
    node(0) = i * h;
    node(Dim) = 1.0;
    c.nodes.push_back(c.model.add_vector(node));
    if (ale) c.materials.push_back(c.model.add_vector(Eigen::VectorXd::Constant(1, i * h)));
  }
  for (int i = 0; i < elements; ++i) {
    core::RancfCableParameters p{.node_a = c.nodes[i], .node_b = c.nodes[i + 1], .length = h,
                                 .section = section, .name = "cable element " + std::to_string(i)};
    if (ale) {
      p.material_a = c.materials[i];
      p.material_b = c.materials[i + 1];
      c.model.add_element(std::make_unique<core::AleRancfCableElement<Dim>>(p));
    } else {
      c.model.add_element(std::make_unique<core::RancfCableElement<Dim>>(p));
    }
  }
  return c;
}

/// A dead force λ F on the position entries of a vector block [r, r_x] (statics).
template <int Dim>
class NodeForce final : public core::Element {
public:
  NodeForce(int node, const Eigen::Matrix<double, Dim, 1>& force) : blocks_{node}, force_(force) {}
  const std::vector<int>& blocks() const override { return blocks_; }
  void compute(const core::ElementInput& in, const core::ElementRequest& request,
               core::ElementOutput& out) const override {
    if (request.residual) out.residual.template head<Dim>() -= in.load_factor * force_;
  }
  std::string name() const override { return "tip force"; }

private:
  std::vector<int> blocks_;
  Eigen::Matrix<double, Dim, 1> force_;
};

}  // namespace spar::test
