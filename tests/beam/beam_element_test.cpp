// The geometrically exact beam element: its internal force is the gradient of its strain energy,
// its stiffness is the exact symmetric Hessian, and both are objective. Every derivative is checked
// against central finite differences on random large deformations (rotations up to 3 rad).
#include <spar/elements/beam/beam.hpp>
#include <spar/elements/beam/beam_element.hpp>
#include <spar/elements/beam/centerline_sampler.hpp>
#include <spar/iga/circular_arc.hpp>
#include <spar/iga/knot_operations.hpp>
#include <spar/lie/lie.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "beam_fixtures.hpp"
#include "random_rotations.hpp"

using namespace spar;

namespace {

// Central differences with step δ = 1e-6 on O(1) data: truncation δ²/6 |f‴| ~ 1e-13, round-off
// ε |f| / δ ≈ 2.2e-10 relative to the entries. The bound is that round-off with a margin of 10
// for |f| / |f′| ratios above 1 and the summation in each evaluation: 2e-9 (measured ≤ 2.1e-10
// over every check below; a wrong term in a force or tangent is off by ≥ 1e-3).
constexpr double fd_step = 1e-6;
constexpr double fd_tolerance = 2e-9;

/// A large random deformation of a beam: a rigid rotation of up to 3 rad about a random axis,
/// plus per-node displacements of 20 % of the length and rotations of up to 0.6 rad.
core::Configuration deform(const core::Configuration& reference, unsigned seed) {
  test::RandomRotations random(seed);
  const Eigen::Matrix3d Q = lie::exp(random.uniform(0.0, 3.0) * random.axis());
  core::Configuration q = reference;
  for (int k = 0; k < q.block_count(); ++k) {
    q.position[k] = Q * reference.position[k] +
                    0.2 * Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1),
                                          random.uniform(-1, 1));
    q.rotation[k] = Q * reference.rotation[k] * lie::exp(random.uniform(0.0, 0.6) * random.axis());
  }
  return q;
}

/// The configuration q ⊕ Δ restricted to the nodes of element e.
core::Configuration perturbed(const core::GeometricallyExactBeam& beam, int e,
                              const core::Configuration& q, const Eigen::VectorXd& delta) {
  core::Configuration p = q;
  const int first = beam.node(beam.element(e).first_control_point);
  for (int I = 0; I < delta.size() / 6; ++I) {
    p.position[first + I] += delta.segment<3>(6 * I);
    p.rotation[first + I] = lie::right_plus(p.rotation[first + I], delta.segment<3>(6 * I + 3));
  }
  return p;
}

double energy(const core::GeometricallyExactBeam& beam, int e, const core::Configuration& q) {
  core::BeamElementResult r;
  core::evaluate_beam_element(beam, e, q, core::BeamEvaluation::force, r);
  return r.strain_energy;
}

/// The gradient of Π(q ⊕ Δ) with respect to Δ at Δ (not only at 0): per node, the local force
/// pulled back by the tangent of the rotation increment, T(Δφ)ᵀ f.
Eigen::VectorXd chart_gradient(const core::GeometricallyExactBeam& beam, int e,
                               const core::Configuration& q, const Eigen::VectorXd& delta) {
  core::BeamElementResult r;
  core::evaluate_beam_element(beam, e, perturbed(beam, e, q, delta), core::BeamEvaluation::force, r);
  Eigen::VectorXd g = r.internal_force;
  for (int I = 0; I < delta.size() / 6; ++I)
    g.segment<3>(6 * I + 3) =
        lie::tangent(Eigen::Vector3d(delta.segment<3>(6 * I + 3))).transpose() * g.segment<3>(6 * I + 3);
  return g;
}

/// Central differences of f(Δ) at Δ = 0 along each of the n unit vectors: column i is
/// (f(h eᵢ) − f(−h eᵢ)) / 2h.
template <class F>
Eigen::MatrixXd central_differences(int n, F&& f) {
  Eigen::MatrixXd columns(f(Eigen::VectorXd::Zero(n)).size(), n);
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
    d(i) = fd_step;
    columns.col(i) = (f(d) - f(Eigen::VectorXd(-d))) / (2 * fd_step);
  }
  return columns;
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / std::max(b.norm(), 1e-300);
}

/// Calls check(beam, e, q, description) for every element of two-element beams of degree 1 … 5
/// in three random large deformations each (seeds first_seed, +1, +2). The kernel has fixed-size
/// code for 2, 3 and 4 control points (degree 1 … 3) and dynamic-size code beyond: both are run.
template <class Check>
void for_each_deformed_element(unsigned first_seed, Check&& check) {
  for (int degree = 1; degree <= 5; ++degree) {
    core::Configuration reference;
    const core::GeometricallyExactBeam beam(
        {.centerline = test::straight_centerline(1.3, 2, degree), .stiffness = test::generic_stiffness()},
        reference);
    for (unsigned seed = first_seed; seed < first_seed + 3; ++seed) {
      const core::Configuration q = deform(reference, seed);
      for (int e = 0; e < beam.element_count(); ++e) {
        INFO("p = " << degree << ", seed " << seed << ", element " << e);
        check(beam, e, q);
      }
    }
  }
}

}  // namespace

TEST_CASE("beam internal force is the gradient of the strain energy", "[gebt]") {
  for_each_deformed_element(1u, [](const core::GeometricallyExactBeam& beam, int e, const core::Configuration& q) {
    core::BeamElementResult r;
    core::evaluate_beam_element(beam, e, q, core::BeamEvaluation::force, r);
    const Eigen::MatrixXd fd = central_differences(
        static_cast<int>(r.internal_force.size()), [&](const Eigen::VectorXd& d) {
          return Eigen::VectorXd::Constant(1, energy(beam, e, perturbed(beam, e, q, d)));
        });
    CHECK(relative(r.internal_force, fd.transpose()) <= fd_tolerance);
  });
}

TEST_CASE("beam stiffness is the exact symmetric Hessian in the exponential chart", "[gebt]") {
  for_each_deformed_element(4u, [](const core::GeometricallyExactBeam& beam, int e, const core::Configuration& q) {
    core::BeamElementResult r;
    core::evaluate_beam_element(beam, e, q, core::BeamEvaluation::force_and_stiffness, r);
    const Eigen::MatrixXd fd = central_differences(
        static_cast<int>(r.internal_force.size()),
        [&](const Eigen::VectorXd& d) { return chart_gradient(beam, e, q, d); });
    const Eigen::MatrixXd K = r.stiffness;
    CHECK(relative(K, K.transpose()) <= 1e-13);
    CHECK(relative(K, fd) <= fd_tolerance);
  });
}

TEST_CASE("the translation-only stiffness is the full stiffness without its rotation blocks",
          "[gebt]") {
  // 003's frozen strategy replaces the rotation–rotation blocks by those of t = 0, so the kernel
  // skips them; every other entry (translation rows and columns) must be the full stiffness's,
  // to round-off (the same products, summed in the same order up to the skipped terms).
  for_each_deformed_element(9u, [](const core::GeometricallyExactBeam& beam, int e, const core::Configuration& q) {
    core::BeamElementResult full, translation;
    core::evaluate_beam_element(beam, e, q, core::BeamEvaluation::force_and_stiffness, full);
    core::evaluate_beam_element(beam, e, q, core::BeamEvaluation::force_and_translation_stiffness,
                                translation);
    Eigen::MatrixXd expected = full.stiffness;
    const Eigen::Index k = expected.rows() / 6;
    for (Eigen::Index I = 0; I < k; ++I)
      for (Eigen::Index J = 0; J < k; ++J) expected.block<3, 3>(6 * I + 3, 6 * J + 3).setZero();
    CHECK(relative(Eigen::MatrixXd(translation.stiffness), expected) <= 1e-13);
    CHECK(relative(Eigen::VectorXd(translation.internal_force), Eigen::VectorXd(full.internal_force)) == 0.0);
  });
}

TEST_CASE("the local tangent is the derivative of the internal force along q + Delta", "[gebt]") {
  // ∂f(q ⊕ Δ)/∂Δ = H + ½ blockdiag(hat(m_I)): the matrix a Newton iteration with right-trivialized
  // updates needs, checked against central differences of the raw internal force.
  core::Configuration reference;
  const core::GeometricallyExactBeam beam(
      {.centerline = test::straight_centerline(1.0, 2, 3), .stiffness = test::generic_stiffness()},
      reference);
  const core::Configuration q = deform(reference, 7);
  core::BeamElementResult r;
  core::evaluate_beam_element(beam, 1, q, core::BeamEvaluation::force_and_stiffness, r);
  Eigen::MatrixXd K = r.stiffness;
  core::add_local_tangent_correction(r.internal_force, K);
  const Eigen::MatrixXd fd = central_differences(
      static_cast<int>(r.internal_force.size()), [&](const Eigen::VectorXd& d) {
        core::BeamElementResult perturbed_result;
        core::evaluate_beam_element(beam, 1, perturbed(beam, 1, q, d), core::BeamEvaluation::force,
                                    perturbed_result);
        return Eigen::VectorXd(perturbed_result.internal_force);
      });
  CHECK(relative(K, fd) <= fd_tolerance);
}

TEST_CASE("straight and curved beams are stress-free in their reference configuration", "[gebt]") {
  core::Configuration reference;
  const core::GeometricallyExactBeam straight(
      {.centerline = test::straight_centerline(2.0, 3, 2), .stiffness = test::generic_stiffness()},
      reference);
  for (int e = 0; e < straight.element_count(); ++e) {
    core::BeamElementResult r;
    core::evaluate_beam_element(straight, e, reference, core::BeamEvaluation::force, r);
    CHECK(r.strain_energy == 0.0);
    CHECK(r.internal_force.norm() == 0.0);
  }
}

TEST_CASE("a rigid-body motion produces no strain and no internal force", "[gebt]") {
  core::Configuration reference;
  const core::GeometricallyExactBeam beam(
      {.centerline = test::straight_centerline(1.0, 3, 3), .stiffness = test::generic_stiffness()},
      reference);
  test::RandomRotations random(8);
  const Eigen::Matrix3d Q = lie::exp(2.9 * random.axis());
  const Eigen::Vector3d c(0.4, -2.0, 1.5);
  core::Configuration moved = reference;
  for (int k = 0; k < moved.block_count(); ++k) {
    moved.position[k] = Q * reference.position[k] + c;
    moved.rotation[k] = Q * reference.rotation[k];
  }
  for (int e = 0; e < beam.element_count(); ++e) {
    core::BeamElementResult r;
    core::evaluate_beam_element(beam, e, moved, core::BeamEvaluation::force, r);
    // Stiffness entries are O(1) and strains O(eps): the force is round-off.
    CHECK(r.internal_force.norm() <= 1e-14);
  }
}

TEST_CASE("strains and energy are objective under a superposed rigid rotation", "[gebt]") {
  core::Configuration reference;
  const core::GeometricallyExactBeam beam(
      {.centerline = test::straight_centerline(1.0, 3, 3), .stiffness = test::generic_stiffness()},
      reference);
  const core::Configuration q = deform(reference, 9);
  test::RandomRotations random(10);
  const Eigen::Matrix3d Q = lie::exp(2.5 * random.axis());
  core::Configuration rotated = q;
  for (int k = 0; k < q.block_count(); ++k) {
    rotated.position[k] = Q * q.position[k] + Eigen::Vector3d(1.0, 2.0, 3.0);
    rotated.rotation[k] = Q * q.rotation[k];
  }
  for (int e = 0; e < beam.element_count(); ++e) {
    core::BeamElementResult a, b;
    core::evaluate_beam_element(beam, e, q, core::BeamEvaluation::force_and_stiffness, a);
    core::evaluate_beam_element(beam, e, rotated, core::BeamEvaluation::force_and_stiffness, b);
    CHECK(std::fabs(a.strain_energy - b.strain_energy) <= 1e-14 * a.strain_energy);
    for (std::size_t g = 0; g < beam.element(e).gauss_points.size(); ++g) {
      const core::BeamStrains sa = core::beam_strains(beam, e, static_cast<int>(g), q);
      const core::BeamStrains sb = core::beam_strains(beam, e, static_cast<int>(g), rotated);
      CHECK((sa.translational - sb.translational).norm() <= 1e-14);
      CHECK((sa.curvature - sb.curvature).norm() <= 1e-14);
    }
    // Material rotational forces are invariant; translational forces rotate with Q.
    for (int I = 0; I < beam.degree() + 1; ++I) {
      CHECK((Q * a.internal_force.segment<3>(6 * I) - b.internal_force.segment<3>(6 * I)).norm() <= 1e-13);
      CHECK((a.internal_force.segment<3>(6 * I + 3) - b.internal_force.segment<3>(6 * I + 3)).norm() <= 1e-13);
    }
  }
}

TEST_CASE("a curved beam of NURBS arcs is stress-free in its reference and under rigid motion",
          "[gebt]") {
  // A quarter circle of radius 2 (rational quadratic, non-unit weights) refined to 6 elements.
  const iga::NurbsCurve<3> arc = iga::h_refine(iga::quarter_circle<3>(2.0), 6).curve;
  core::Configuration reference;
  const core::GeometricallyExactBeam beam({.centerline = arc, .stiffness = test::generic_stiffness()},
                                          reference);
  test::RandomRotations random(12);
  const Eigen::Matrix3d Q = lie::exp(2.0 * random.axis());
  core::Configuration moved = reference;
  for (int k = 0; k < moved.block_count(); ++k) {
    moved.position[k] = Q * reference.position[k] + Eigen::Vector3d(-1.0, 0.5, 2.0);
    moved.rotation[k] = Q * reference.rotation[k];
  }
  for (int e = 0; e < beam.element_count(); ++e) {
    core::BeamElementResult at_rest, after_motion;
    core::evaluate_beam_element(beam, e, reference, core::BeamEvaluation::force, at_rest);
    core::evaluate_beam_element(beam, e, moved, core::BeamEvaluation::force, after_motion);
    CHECK(at_rest.internal_force.norm() == 0.0);
    CHECK(after_motion.internal_force.norm() <= 1e-14);
  }
  // The section frame follows the arc: A₁ is tangent to the circle at the ends.
  CHECK((beam.rotation_at(reference, 0.0).col(0) - Eigen::Vector3d::UnitY()).norm() <= 1e-14);
  CHECK((beam.rotation_at(reference, 1.0).col(0) + Eigen::Vector3d::UnitX()).norm() <= 1e-14);
}

TEST_CASE("the curved beam's stiffness is the exact Hessian", "[gebt]") {
  const iga::NurbsCurve<3> arc = iga::h_refine(iga::quarter_circle<3>(1.5), 3).curve;
  core::Configuration reference;
  const core::GeometricallyExactBeam beam({.centerline = arc, .stiffness = test::generic_stiffness()},
                                          reference);
  const core::Configuration q = deform(reference, 13);
  core::BeamElementResult r;
  core::evaluate_beam_element(beam, 1, q, core::BeamEvaluation::force_and_stiffness, r);
  const Eigen::MatrixXd fd = central_differences(
      static_cast<int>(r.internal_force.size()),
      [&](const Eigen::VectorXd& d) { return chart_gradient(beam, 1, q, d); });
  CHECK(relative(Eigen::MatrixXd(r.stiffness), fd) <= fd_tolerance);
}

TEST_CASE("sample_centerline samples the knot range evenly", "[gebt]") {
  core::Configuration reference;
  const core::GeometricallyExactBeam beam(
      {.centerline = test::straight_centerline(2.0, 3, 2), .stiffness = test::generic_stiffness()}, reference);
  const Eigen::MatrixXd samples = beam.sample_centerline(reference, 5);
  REQUIRE(samples.rows() == 5);
  for (int i = 0; i < 5; ++i)
    CHECK((samples.row(i).transpose() - Eigen::Vector3d(0.5 * i, 0.0, 0.0)).norm() <= 1e-15);
  CHECK_THROWS_WITH(beam.sample_centerline(reference, 1), Catch::Contains("at least 2 points"));
}

TEST_CASE("a centerline sampler gives position_at and the velocity field at its points", "[gebt]") {
  // A curved (rational quadratic) beam in a deformed state: the sampler's rows are position_at at the evenly
  // spaced parameters (the same sums, bit for bit), and its velocities are Σ N_I ẋ_I, the same
  // combination of the nodes' velocities (checked against position_at of a configuration whose
  // positions are those velocities).
  core::Configuration reference;
  const core::GeometricallyExactBeam beam(
      {.centerline = iga::circular_arc(iga::CircularArc<3>{.radius = 1.0, .sweep = 1.5}), .stiffness = test::generic_stiffness()},
      reference);
  const core::Configuration q = deform(reference, 5);
  const core::CenterlineSampler points(beam, 9);
  REQUIRE(points.size() == 9);
  Eigen::VectorXd velocity(q.dof_count());
  for (int i = 0; i < velocity.size(); ++i) velocity(i) = std::sin(1.0 + i);
  core::Configuration rates = q;
  for (int I = 0; I < beam.control_point_count(); ++I)
    rates.position[beam.node(I)] = velocity.segment<3>(q.blocks[beam.node(I)].offset);
  const Eigen::MatrixXd x = points.positions(q), v = points.velocities(q, velocity);
  const iga::KnotVector& U = beam.reference_centerline().knots();
  for (int i = 0; i < 9; ++i) {
    const double u = U.first() + (U.last() - U.first()) * i / 8;
    CHECK(x.row(i).transpose() == beam.position_at(q, u));
    CHECK(v.row(i).transpose() == beam.position_at(rates, u));
  }
  CHECK_THROWS_WITH(core::CenterlineSampler(beam, 1), Catch::Contains("at least 2 points"));
  CHECK_THROWS_WITH(points.velocities(q, Eigen::VectorXd::Zero(3)), Catch::Contains("the velocity has 3 entries"));
  CHECK_THROWS_WITH(points.positions(core::Configuration{}), Catch::Contains("frame nodes"));
}
