// The sliding cable with length control (000 §5, docs/rancf.md): a suspended beam with a sliding
// lumped mass (000 §6.2's setup): events keep the element lengths in [0.5, 1.5] L_std and the node
// count constant, energy is conserved between events (ρ∞ = 1), and each event changes the energy
// only by the merge.
#include <spar/elements/cable/sliding_cable.hpp>
#include <spar/joints/sliding_node_slopes.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

using namespace spar;

namespace {

struct SlidingRun {
  int events = 0;
  double min_ratio = 1e9, max_ratio = 0.0;  ///< element lengths / L_std after the first event
  double max_drift_between_events = 0.0;    ///< |E − E(last event)| / max kinetic energy
  double max_jump = 0.0;                    ///< |ΔE| across one event / max kinetic energy
  double slider = 0.0;                      ///< final material coordinate of the slider
  double max_kinetic = 0.0;
  double first_event_time = 0.0, drift_before = 0.0;
  double kink = 0.0;                        ///< the largest angle between the slider's two slopes (rad)
};

/// `slopes`: a node block per side of the slider coupled by 000 eq. (40); none: one block.
SlidingRun run_suspended(bool rational, int elements, double h, double t_end,
                         std::optional<joints::SlopeCondition> slopes = std::nullopt) {
  // 000 §6.1/6.2: L = 1 m, r = 0.01 m, ρ = 7200 kg/m³, E = 20 MPa; both ends pinned; 5 kg at
  // 0.1 m, at rest.
  const double r = 0.01, E = 20e6, rho = 7200;
  const double A = std::numbers::pi * r * r, I = std::numbers::pi * r * r * r * r / 4;
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = 1.0, .elements = elements,
                                      .section = {.axial_stiffness = E * A, .bending_stiffness = E * I,
                                                  .mass_per_length = rho * A},
                                      .slider_position = 0.1, .slider_mass = 5.0, .rational = rational,
                                      .two_sided_slider = slopes.has_value()});
  model.set_gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  const core::Configuration& q = model.state();
  std::vector<std::unique_ptr<joints::Constraint>> constraints;
  if (slopes)
    constraints.push_back(std::make_unique<joints::SlidingNodeSlopes>(
        cable.chain()[cable.slider()], cable.right_slider_node(), 2, *slopes, q));
  std::vector<int> fixed = cable.fixed_dofs(q);
  for (int end : {cable.chain().front(), cable.chain().back()})
    for (int i = 0; i < 2; ++i) fixed.push_back(q.blocks[end].offset + i);
  std::sort(fixed.begin(), fixed.end());
  model.set_fixed_dofs(fixed);
  solvers::GeneralizedAlpha integrator(model, std::move(constraints),
                                       {.time_step = h, .spectral_radius = 1.0, .tolerance = 1e-16,
                                        .residual_tolerance = 1e-9});
  integrator.initialize();
  SlidingRun run;
  double reference = integrator.energies().total();
  std::vector<double> drifts;
  const long steps = std::lround(t_end / h);
  for (long n = 0; n < steps; ++n) {
    integrator.step();
    const solvers::Energies energies = integrator.energies();
    run.max_kinetic = std::max(run.max_kinetic, energies.kinetic);
    if (slopes) {
      const Eigen::Vector2d left = q.vector(cable.chain()[cable.slider()]).tail<2>();
      const Eigen::Vector2d right = q.vector(cable.right_slider_node()).tail<2>();
      run.kink = std::max(run.kink, std::atan2(std::abs(left.x() * right.y() - left.y() * right.x()), left.dot(right)));
    }
    drifts.push_back(std::fabs(energies.total() - reference));
    Eigen::MatrixXd P;
    if (run.events == 0) run.drift_before = drifts.back();
    if (const auto event = cable.control_length(model, integrator.time(), P)) {
      if (run.events == 0) run.first_event_time = integrator.time();
      integrator.remap(P);
      integrator.initialize();  // consistent v̇ and a for the new system (docs/rancf.md)
      const double after = integrator.energies().total();
      run.max_jump = std::max(run.max_jump, std::fabs(after - energies.total()));
      reference = after;
      ++run.events;
    }
    // Every element after the first event, but the two next to the slider while it is next to
    // an end element (no node left to delete on that side).
    const int slider = cable.slider(), last = static_cast<int>(cable.chain().size()) - 1;
    if (run.events > 0)
      for (int k = 0; k < elements; ++k) {
        if ((k == slider - 1 || k == slider) && (slider - 1 == 0 || slider + 1 == last)) continue;
        const double ratio = cable.element_length(model.state(), k) / cable.standard_length();
        run.min_ratio = std::min(run.min_ratio, ratio);
        run.max_ratio = std::max(run.max_ratio, ratio);
      }
  }
  for (double d : drifts) run.max_drift_between_events = std::max(run.max_drift_between_events, d);
  run.max_drift_between_events /= run.max_kinetic;
  run.max_jump /= run.max_kinetic;
  run.slider = model.state().vector(cable.materials()[cable.slider()])(0);
  return run;
}

}  // namespace

TEST_CASE("suspended beam with a sliding mass: length control and energy", "[rancf][sliding]") {
  // 6 elements (000 §6.2 uses 3: then the slider is next to an end element after the first event
  // and no length is controlled any more), 1 s: the mass slides from 0.1 m past the middle.
  for (bool rational : {true, false}) {
    const SlidingRun coarse = run_suspended(rational, 6, 1e-3, 1.0);
    const SlidingRun fine = run_suspended(rational, 6, 5e-4, 1.0);
    INFO((rational ? "ALE-RANCF" : "ALE-ANCF") << ": " << fine.events << " events, lengths in ["
         << fine.min_ratio << ", " << fine.max_ratio << "] L_std, drift between events "
         << coarse.max_drift_between_events << " (h = 1e-3), " << fine.max_drift_between_events
         << " (h = 5e-4), largest jump " << coarse.max_jump << ", " << fine.max_jump
         << ", slider at " << fine.slider << ", max kinetic " << fine.max_kinetic);
    CHECK(fine.events >= 2);
    CHECK(fine.events == coarse.events);
    // Lengths: the trigger fires at the first step past 1.5 L_std, so the overshoot is at most
    // one step of the slider (≤ 3 m/s · 5e-4 s = 1.5e-3 m = 0.01 L_std).
    CHECK(fine.min_ratio >= 0.5 - 0.01);
    CHECK(fine.max_ratio <= 1.5 + 0.01);
    // Between events the system is Lagrangian: drift O(h²), ratio 4 — but the events fire at the
    // first step past the threshold, so their times (and the states merged) shift by up to one
    // step between the runs; measured ratios 2.9 to 3.7, checked ≥ 2.5 (first order would be 2).
    CHECK(fine.max_drift_between_events <= coarse.max_drift_between_events / 2.5);
    CHECK(fine.max_drift_between_events <= 5e-4);
    // The jump at an event is the merge's (and the velocity interpolation's at H), not the
    // integrator's: measured 1.7e-2 to 2.7e-2 of the largest kinetic energy at both step sizes
    // (docs/rancf.md); 5e-2 flags a regression.
    CHECK(fine.max_jump <= 5e-2);
    CHECK(coarse.max_jump <= 5e-2);
  }
}

TEST_CASE("falling beam: the mass leaves the free end between 0.55 and 0.7 s", "[rancf][sliding][validation]") {
  // 000 §6.1 with 20 elements (examples/falling_beam): the paper finds the separation between
  // 0.6 and 0.7 s; ours is 0.594 … 0.613 s for h = 2.5e-4 … 1e-3 (the release fires when the end
  // element is shorter than SlidingCable::release_length: 0.1 L_std or four steps of travel).
  const double r = 0.01, E = 20e6, rho = 7200, h = 1e-3;
  const double A = std::numbers::pi * r * r, I = std::numbers::pi * r * r * r * r / 4;
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = 1.0, .elements = 20,
                                      .section = {.axial_stiffness = E * A, .bending_stiffness = E * I,
                                                  .mass_per_length = rho * A},
                                      .slider_position = 0.1, .slider_mass = 0.8, .detachable = true});
  model.set_gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  const auto set_fixed = [&]() {
    std::vector<int> fixed = cable.fixed_dofs(model.state());
    for (int i = 0; i < 4; ++i) fixed.push_back(model.state().blocks[cable.chain().front()].offset + i);
    std::sort(fixed.begin(), fixed.end());
    model.set_fixed_dofs(fixed);
  };
  set_fixed();
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = h, .spectral_radius = 1.0, .tolerance = 1e-16,
                                                   .residual_tolerance = 1e-9});
  integrator.set_velocity(cable.chain()[cable.slider()], Eigen::Vector4d(0.4, 0.0, 0.0, 0.0));
  integrator.set_velocity(cable.materials()[cable.slider()], Eigen::VectorXd::Constant(1, 0.4));
  integrator.initialize();
  double separation = -1.0;
  Eigen::Vector2d mass_velocity;
  while (integrator.time() < 0.7) {
    integrator.step();
    Eigen::MatrixXd P;
    if (cable.control_length(model, integrator.time(), P)) {
      integrator.remap(P);
      integrator.initialize();
    }
    if (cable.released()) continue;
    const core::Configuration& q = model.state();
    const double rate = integrator.velocity()(q.blocks[cable.materials()[cable.slider()]].offset);
    if (cable.near_end(q, static_cast<int>(cable.chain().size()) - 1,
                       cable.release_length(h, rate))) {
      mass_velocity = integrator.velocity().segment<2>(q.blocks[cable.chain()[cable.slider()]].offset);
      cable.release(model, P);
      set_fixed();
      integrator.remap(P);
      integrator.initialize();
      separation = integrator.time();
      // The particle leaves with the sliding node's velocity.
      const Eigen::Vector2d v = integrator.velocity().segment<2>(model.state().blocks[cable.particle()].offset);
      CHECK((v - mass_velocity).norm() <= 1e-14 * mass_velocity.norm());
    }
  }
  INFO("separation at " << separation << " s");
  CHECK(separation > 0.55);
  CHECK(separation < 0.7);
  CHECK(cable.chain().size() == 20u);  // one node left with the mass's end element
}

TEST_CASE("a two-sided sliding node: continuous slopes as one node, discontinuous ones a hinge",
          "[rancf][sliding]") {
  // 000 eqs. (39)–(40). With the continuous condition the two node blocks move as one: the same
  // events and the slider where the one-block cable has it (to the Newton tolerance, amplified by
  // 1 s of motion). With the discontinuous one the cable kinks at the 5 kg mass, the energy is
  // still conserved between events as O(h²), and the length control works the same way.
  const SlidingRun one = run_suspended(true, 6, 1e-3, 1.0);
  const SlidingRun two = run_suspended(true, 6, 1e-3, 1.0, joints::SlopeCondition::continuous);
  INFO("one block: " << one.events << " events, slider " << one.slider << "; two: " << two.events << ", "
       << two.slider << ", kink " << two.kink);
  CHECK(two.events == one.events);
  CHECK(std::abs(two.slider - one.slider) <= 1e-6);
  CHECK(two.kink <= 1e-9);
  const SlidingRun coarse = run_suspended(true, 6, 1e-3, 1.0, joints::SlopeCondition::discontinuous);
  const SlidingRun fine = run_suspended(true, 6, 5e-4, 1.0, joints::SlopeCondition::discontinuous);
  INFO("hinge: " << fine.events << " events, kink " << fine.kink << " rad, drift between events "
       << coarse.max_drift_between_events << ", " << fine.max_drift_between_events << ", slider " << fine.slider
       << ", lengths [" << fine.min_ratio << ", " << fine.max_ratio << "]");
  CHECK(fine.events >= 2);
  CHECK(fine.kink > 0.05);
  CHECK(fine.max_drift_between_events <= coarse.max_drift_between_events / 2.5);
  CHECK(fine.min_ratio >= 0.5 - 0.01);
  CHECK(fine.max_ratio <= 1.5 + 0.01);
}
