// Every load kind in dynamics, against independent references: the mean of the undamped
// (ρ∞ = 1) oscillation of a cantilever under a small step load is its linear static deflection
// (Euler–Bernoulli with shear); a free beam or rigid body changes its linear momentum by ∫F dt
// and its angular momentum by ∫M dt. Before the loads became elements, dynamics dropped
// NodalForce and DistributedForce silently: every test here would have failed.
#include <spar/error.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "cantilever.hpp"
#include "momentum.hpp"

using namespace spar;

namespace {

constexpr double L = 1.0, EI = 1e4, EA = 1e8, GA = 4e7;

/// Steel (ρ = 7850 kg/m³, E = 2.1e11 Pa) with the stiffnesses of test::cantilever_stiffness():
/// ρA = ρ EA/E, ρI = ρ EI/E about both bending axes, 2ρI in torsion.
core::SectionInertia steel_inertia() {
  const double rho_over_E = 7850 / 2.1e11;
  core::SectionInertia inertia;
  inertia.mass_per_length = rho_over_E * EA;
  inertia.rotary = Eigen::Vector3d(2, 1, 1).asDiagonal() * (rho_over_E * EI);
  return inertia;
}

struct Beam {
  core::Model model;
  int beam = 0, root = 0, tip = 0;
};

/// The test::make_cantilever beam (L = 1, cubic elements) with steel inertia, clamped or free.
Beam steel_beam(int elements, bool clamped) {
  Beam b;
  b.beam = core::add_beam(b.model, {.centerline = test::straight_centerline(L, elements, 3),
                             .stiffness = test::cantilever_stiffness(), .inertia = steel_inertia()});
  b.root = core::beam(b.model, b.beam).node(0);
  b.tip = core::beam(b.model, b.beam).node(core::beam(b.model, b.beam).control_point_count() - 1);
  if (clamped) b.model.fix(b.root);
  return b;
}

/// A load kind applied to a beam, with its linear static tip deflection (along Y) for a clamped
/// root: Euler–Bernoulli plus the shear term (Timoshenko), exact for the linear rod.
struct LoadCase {
  std::string name;
  std::function<void(Beam&)> apply;
  double linear_tip_deflection;
};

std::vector<LoadCase> small_loads() {
  // Loads 1e-3 of those of the statics tests: rotations ~1e-3 rad, so the geometric
  // nonlinearity and the difference between follower and dead moments are ~1e-6 relative.
  const double F = 1e-3 * EI / (L * L), q = 1e-3 * EI / (L * L * L), M = 1e-3 * EI / L, m = 1e-3 * EI / (L * L);
  const double rhoA = steel_inertia().mass_per_length, g = q / rhoA;
  std::vector<LoadCase> cases = {
      {"nodal force", [F](Beam& b) { core::add_load(b.model, core::NodalForce{b.tip, Eigen::Vector3d(0, F, 0)}); },
       F * L * L * L / (3 * EI) + F * L / GA},
      {"distributed force",
       [q](Beam& b) { core::add_load(b.model, core::DistributedForce{b.beam, Eigen::Vector3d(0, q, 0)}); },
       q * std::pow(L, 4) / (8 * EI) + q * L * L / (2 * GA)},
      {"gravity", [g](Beam& b) { b.model.set_gravity(Eigen::Vector3d(0, g, 0)); },
       q * std::pow(L, 4) / (8 * EI) + q * L * L / (2 * GA)}};
  for (core::MomentFrame frame : {core::MomentFrame::material, core::MomentFrame::inertial}) {
    const std::string which = frame == core::MomentFrame::material ? " (material)" : " (inertial)";
    cases.push_back({"nodal moment" + which,
                     [M, frame](Beam& b) { core::add_load(b.model, core::NodalMoment{b.tip, Eigen::Vector3d(0, 0, M), frame}); },
                     M * L * L / (2 * EI)});
    cases.push_back({"distributed moment" + which,
                     [m, frame](Beam& b) {
                       core::add_load(b.model, core::DistributedMoment{b.beam, Eigen::Vector3d(0, 0, m), frame});
                     },
                     m * std::pow(L, 3) / (3 * EI)});
  }
  return cases;
}

}  // namespace

TEST_CASE("dynamics: a step load makes a cantilever oscillate about its static deflection",
          "[loads][dynamics][validation]") {
  // Undamped (ρ∞ = 1) from rest under a suddenly applied constant load, each mode oscillates as
  // (1 − cos ω_k t) about its share of the static deflection, so the time mean of the tip over
  // whole periods of the first mode is the static deflection. Error budget: the first mode
  // averaged over 4 of its Euler–Bernoulli periods, whose discrete period differs by the shear
  // and rotary inertia (r²/L² = 1e-4) and the trapezoidal period elongation ((ωh)²/12 = 8e-5);
  // the higher modes' means over a non-integer number of their periods, ≤ their share/(ω_k T)
  // (mode 2: a few % share / (6.3 · 2π · 4) ~ 1e-3 of the deflection). Measured 0.8e-3 to
  // 1.25e-3 over the seven load kinds; tolerance 3e-3 relative.
  const double rhoA = steel_inertia().mass_per_length;
  const double omega1 = 1.8751040687 * 1.8751040687 * std::sqrt(EI / (rhoA * std::pow(L, 4)));
  const double period = 2 * std::numbers::pi / omega1;
  const int steps_per_period = 200, periods = 4;
  for (const LoadCase& load : small_loads()) {
    Beam b = steel_beam(8, true);
    load.apply(b);
    solvers::GeneralizedAlpha integrator(b.model, {},
                                         {.time_step = period / steps_per_period, .spectral_radius = 1.0,
                                          .tolerance = 1e-20, .residual_tolerance = 1e-10});
    integrator.initialize();
    double previous = b.model.state().position[b.tip].y(), integral = 0.0;
    for (int k = 0; k < steps_per_period * periods; ++k) {
      integrator.step();
      const double y = b.model.state().position[b.tip].y();
      integral += 0.5 * (previous + y) / (steps_per_period * periods);
      previous = y;
    }
    INFO(load.name << ": mean tip deflection " << integral << ", linear static " << load.linear_tip_deflection
                   << ", relative difference " << integral / load.linear_tip_deflection - 1);
    CHECK(std::fabs(integral / load.linear_tip_deflection - 1) <= 3e-3);
  }
}

TEST_CASE("dynamics: forces and gravity change a free beam's linear momentum by their impulse",
          "[loads][dynamics][validation]") {
  // Internal forces cancel in the sum over nodes (translation invariance), so Σ (M v̇)_I = F at
  // every evaluation and the generalized-α update of v (a combination of the algorithmic
  // accelerations, which also sum to F for a constant F) gives p_n = F t_n exactly: only the
  // Newton residual (‖r‖∞ ≤ 1e-10 of the forces per step) and round-off remain: bound 1e-9
  // relative over 200 steps (measured 1e-14). The beam starts spinning and bending so the
  // internal forces are not zero.
  const double q = 3.0, total_force = q * L;  // N/m on the beam, and the matching nodal force
  const Eigen::Vector3d direction = Eigen::Vector3d(0.3, 1.0, -0.5).normalized();
  struct Case {
    const char* name;
    std::function<void(Beam&)> apply;
  };
  const double rhoA = steel_inertia().mass_per_length;
  const Case cases[] = {
      {"nodal force", [&](Beam& b) { core::add_load(b.model, core::NodalForce{b.tip, total_force * direction}); }},
      {"distributed force", [&](Beam& b) { core::add_load(b.model, core::DistributedForce{b.beam, q * direction}); }},
      {"gravity", [&](Beam& b) { b.model.set_gravity(q / rhoA * direction); }}};
  for (const Case& load : cases) {
    Beam b = steel_beam(4, false);
    load.apply(b);
    const double h = 1e-4;
    solvers::GeneralizedAlpha integrator(b.model, {},
                                         {.time_step = h, .spectral_radius = 0.8, .tolerance = 1e-20,
                                          .residual_tolerance = 1e-10});
    for (int k = 0; k < b.model.block_count(); ++k)
      integrator.set_velocity(k, Eigen::Vector3d(0, 2.0 * (b.model.state().position[k].x() - 0.5), 0.1),
                              Eigen::Vector3d(0.1, 0, 2.0));
    integrator.initialize();
    const Eigen::Vector3d p0 = test::momentum(b.model, b.model.state(), integrator.velocity()).first;
    for (int k = 0; k < 200; ++k) integrator.step();
    const Eigen::Vector3d p = test::momentum(b.model, b.model.state(), integrator.velocity()).first;
    const Eigen::Vector3d impulse = total_force * direction * integrator.time();
    INFO(load.name << ": momentum change " << (p - p0).transpose() << ", impulse " << impulse.transpose());
    CHECK((p - p0 - impulse).norm() <= 1e-9 * impulse.norm());
  }
}

TEST_CASE("dynamics: moments change a free body's angular momentum by their angular impulse",
          "[loads][dynamics][validation]") {
  // A tumbling rigid body (J = diag(1, 2, 3) kg m², Ω₀ = (0.3, 1.0, 0.2) rad/s) under a constant
  // nodal moment: dL/dt = M for a dead moment, R(t) M for a follower one (its angular impulse
  // ∫ R M dt by the trapezoidal rule over the steps). The Lie-group generalized-α method keeps
  // L only to second order: its change differs from the impulse by O((|Ω| h)²) = O(1e-6) relative
  // at h = 1e-3 over 1 s; measured 4.6e-8 (follower) and 2.7e-7 (dead); tolerance 1e-5, ten
  // times the estimate.
  const Eigen::Vector3d M(0.5, -0.2, 1.0);
  for (core::MomentFrame frame : {core::MomentFrame::material, core::MomentFrame::inertial}) {
    core::Model model;
    const int node = core::rigid_body(model, core::add_rigid_body(model,
        {.mass = 1.0, .inertia = Eigen::Vector3d(1, 2, 3).asDiagonal()})).node;
    core::add_load(model, core::NodalMoment{node, M, frame});
    const double h = 1e-3;
    solvers::GeneralizedAlpha integrator(model, {},
                                         {.time_step = h, .spectral_radius = 0.8, .tolerance = 1e-20,
                                          .residual_tolerance = 1e-10});
    integrator.set_velocity(node, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.3, 1.0, 0.2));
    integrator.initialize();
    const Eigen::Vector3d L0 = test::momentum(model, model.state(), integrator.velocity()).second;
    Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
    Eigen::Matrix3d previous = model.state().rotation[node];
    for (int k = 0; k < 1000; ++k) {
      integrator.step();
      const Eigen::Matrix3d R = model.state().rotation[node];
      impulse += (frame == core::MomentFrame::inertial) ? Eigen::Vector3d(h * M) : Eigen::Vector3d(0.5 * h * (previous + R) * M);
      previous = R;
    }
    const Eigen::Vector3d change = test::momentum(model, model.state(), integrator.velocity()).second - L0;
    INFO((frame == core::MomentFrame::material ? "material" : "inertial")
         << ": angular momentum change " << change.transpose() << ", impulse " << impulse.transpose()
         << ", relative difference " << (change - impulse).norm() / impulse.norm());
    CHECK((change - impulse).norm() <= 1e-5 * impulse.norm());
  }
}

TEST_CASE("dynamics: a distributed moment changes a free beam's angular momentum by its impulse",
          "[loads][dynamics][validation]") {
  // Internal forces exert no net moment (rotation invariance), so dJ/dt = ∫ m ds for a dead moment
  // per length m (= m L), and ∫ R(s) m ds for a follower one: its angular impulse is integrated
  // here by Simpson's rule over 65 points of the beam's own rotation field (error ~1e-9) and the
  // trapezoidal rule over the steps. The beam starts spinning at 2 rad/s and bending. Errors:
  // O((|Ω| h)²) of the method as for the rigid body, and for the follower moment the element's
  // consistent load ∫ N_I m ds on the nodal frames differs from ∫ R(s) m ds by the variation of
  // R across an element (O(h_e²) of the bending). Measured at h = 1e-4 over 200 steps: 9.7e-8
  // (dead) and 1.2e-7 (follower) relative; tolerance 1e-5 as for the rigid body.
  const Eigen::Vector3d m(0.4, -1.0, 2.0);
  for (core::MomentFrame frame : {core::MomentFrame::inertial, core::MomentFrame::material}) {
    Beam b = steel_beam(4, false);
    core::add_load(b.model, core::DistributedMoment{b.beam, m, frame});
    const double h = 1e-4;
    solvers::GeneralizedAlpha integrator(b.model, {},
                                         {.time_step = h, .spectral_radius = 0.8, .tolerance = 1e-20,
                                          .residual_tolerance = 1e-10});
    for (int k = 0; k < b.model.block_count(); ++k)
      integrator.set_velocity(k, Eigen::Vector3d(0, 2.0 * (b.model.state().position[k].x() - 0.5), 0),
                              Eigen::Vector3d(0, 0, 2.0));
    integrator.initialize();
    const auto moment_rate = [&]() -> Eigen::Vector3d {
      if (frame == core::MomentFrame::inertial) return m * L;
      const core::GeometricallyExactBeam& beam = core::beam(b.model, b.beam);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      const int intervals = 64;
      for (int i = 0; i <= intervals; ++i) {
        const double weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * beam.rotation_at(b.model.state(), double(i) / intervals) * m;
      }
      return sum * L / (3.0 * intervals);
    };
    const Eigen::Vector3d J0 = test::momentum(b.model, b.model.state(), integrator.velocity()).second;
    Eigen::Vector3d impulse = Eigen::Vector3d::Zero(), rate = moment_rate();
    for (int k = 0; k < 200; ++k) {
      integrator.step();
      const Eigen::Vector3d next = moment_rate();
      impulse += 0.5 * h * (rate + next);
      rate = next;
    }
    const Eigen::Vector3d change = test::momentum(b.model, b.model.state(), integrator.velocity()).second - J0;
    INFO((frame == core::MomentFrame::material ? "material" : "inertial")
         << ": angular momentum change " << change.transpose() << ", impulse " << impulse.transpose()
         << ", relative difference " << (change - impulse).norm() / impulse.norm());
    CHECK((change - impulse).norm() <= 1e-5 * impulse.norm());
  }
}

TEST_CASE("add_load refuses a load that is not finite and leaves the model as it was", "[loads]") {
  // Before the fix, a refused load was counted all the same (load_count() 4 here).
  Beam b = steel_beam(2, true);
  const int elements = b.model.element_count();
  const double nan = std::nan("");
  CHECK_THROWS_AS(core::add_load(b.model, core::NodalForce{b.tip, Eigen::Vector3d(0, nan, 0)}), Error);
  CHECK_THROWS_AS(core::add_load(b.model, core::NodalMoment{b.tip, Eigen::Vector3d(nan, 0, 0)}), Error);
  CHECK_THROWS_AS(core::add_load(b.model, core::DistributedForce{b.beam, Eigen::Vector3d(0, 0, INFINITY)}), Error);
  CHECK_THROWS_AS(core::add_load(b.model, core::DistributedMoment{b.beam, Eigen::Vector3d(0, nan, 0)}), Error);
  CHECK(core::load_count(b.model) == 0);
  CHECK(b.model.element_count() == elements);
}

namespace {

/// A clamped steel cantilever (16 cubic elements) under a tip moment EI/L about Z, applied with
/// `history`; integrated with ρ∞ = `rho` and step h to t_end. Returns the integrator's energies.
struct TipMomentRun {
  solvers::Energies energies;
  solvers::DynamicCounters counters;
  Eigen::Vector3d tip;
};

TipMomentRun tip_moment_run(core::MomentFrame frame, core::LoadHistory history, double h, double t_end,
                            double rho = 0.9) {
  Beam b = steel_beam(16, true);
  core::add_load(b.model, core::NodalMoment{b.tip, Eigen::Vector3d(0, 0, EI / L), frame}, std::move(history));
  solvers::GeneralizedAlpha integrator(b.model, {}, {.time_step = h, .spectral_radius = rho});
  while (integrator.time() < t_end - 0.5 * h) integrator.step();
  return {integrator.energies(), integrator.counters(), b.model.state().position[b.tip]};
}

}  // namespace

TEST_CASE("dynamics: a tip moment EI/L on a steel cantilever, ramped over 5 ms, runs at h = 1e-3",
          "[loads][dynamics]") {
  // The audit's run: a dead tip moment EI/L applied suddenly at t = 0, h = 1e-3, ρ∞ = 0.9 —
  // Newton fails (frames turning by π within a step) after 14 ms with h cut to 3.9e-6, and
  // likewise for a follower moment; it is not the dead load. A step moment on the tip section
  // (rotary inertia ρI ~ 4e-4 kg m) gives it an initial angular acceleration ~1e9 rad/s² and
  // excites the shear–rotary-inertia modes (ω ~ √(GA/ρI) ~ 3e5 rad/s, ωh ~ 300). Generalized-α
  // does not overshoot in displacement for such unresolved modes but does in velocity, linearly
  // in ωh (Chung & Hulbert 1993, §4): the tip section starts at ~1e4 rad/s, and the nonlinear
  // coupling of these velocities, damped only by 0.9 per step, ends in the failure. Either
  // resolving the step (h = 1e-4: no cut-back over 0.2 s) or applying the load over a time the
  // step resolves (here a 5 ms ramp, five steps) gives a smooth run. Pinned here: the ramped run
  // at the audit's step completes 0.2 s (six periods of the first mode) without a cut-back, for a
  // dead and a follower moment alike (the same motion: in the plane RᵀM = M for M along the
  // rotation axis, so both give the same forces to round-off), and dissipates numerically between
  // 0 and 1 % of the work scale M · 1 rad = 1e4 J (measured 72 J).
  const core::LoadHistory ramp = [](double t) { return std::min(1.0, t / 5e-3); };
  const TipMomentRun dead = tip_moment_run(core::MomentFrame::inertial, ramp, 1e-3, 0.2);
  const TipMomentRun follower = tip_moment_run(core::MomentFrame::material, ramp, 1e-3, 0.2);
  INFO("dead: tip " << dead.tip.transpose() << ", numerical dissipation " << dead.energies.numerical_dissipation
                    << " J, cut-backs " << dead.counters.cutbacks << "; follower: tip " << follower.tip.transpose());
  CHECK(dead.counters.cutbacks == 0);
  CHECK(follower.counters.cutbacks == 0);
  CHECK((dead.tip - follower.tip).norm() <= 1e-12);
  CHECK(dead.energies.numerical_dissipation >= 0.0);
  CHECK(dead.energies.numerical_dissipation <= 0.01 * EI);
}

TEST_CASE("dynamics: a ramped dead tip moment EI/L at rho_infinity = 1 conserves energy",
          "[loads][dynamics][validation]") {
  // In the plane a dead moment about Z has the potential −M θ_tip: the system is conservative and
  // with ρ∞ = 1 the balance external_work − ΔE is the integrator's O(h²) drift — measured 2.24,
  // 0.71 and 0.14 J at h = 2e-4, 1e-4, 5e-5 over 0.2 s with the 5 ms ramp (orders 1.7, 2.4),
  // against the work scale M · 1 rad = 1e4 J; bound 2 J at h = 1e-4. Without the ramp the
  // unresolved modes the step excites are not damped at all and pump energy into the motion:
  // −9.8e3 J of "dissipation" and 125 cut-backs at h = 1e-4, −89 J at 5e-5 — the nonlinear
  // instability of the undamped method, one more reason to ramp a load the step cannot resolve.
  const core::LoadHistory ramp = [](double t) { return std::min(1.0, t / 5e-3); };
  const TipMomentRun run = tip_moment_run(core::MomentFrame::inertial, ramp, 1e-4, 0.2, 1.0);
  INFO("numerical dissipation " << run.energies.numerical_dissipation << " J, cut-backs " << run.counters.cutbacks);
  CHECK(run.counters.cutbacks == 0);
  CHECK(std::fabs(run.energies.numerical_dissipation) <= 2.0);
}

TEST_CASE("dynamics: a suddenly applied tip moment EI/L runs once the step resolves it",
          "[loads][dynamics]") {
  // The step load of the audit with h = 1e-4 instead of 1e-3: no cut-back over 0.05 s (measured
  // 0 over 0.2 s). See the previous test for why h = 1e-3 fails.
  const TipMomentRun run = tip_moment_run(core::MomentFrame::inertial, {}, 1e-4, 0.05);
  INFO("tip " << run.tip.transpose() << ", cut-backs " << run.counters.cutbacks);
  CHECK(run.counters.cutbacks == 0);
}

TEST_CASE("dynamics: a force with a load history f(t) = sin(w t) moves a free body as integrated by hand",
          "[loads][dynamics][validation]") {
  // m ẍ = F₀ sin(ωt) from rest: v = F₀ (1 − cos ωt)/(m ω), x − x₀ = F₀ (t − sin(ωt)/ω)/(m ω). The
  // history must be evaluated at each step's own time: a lag of one step would be an O(h) error
  // (order 1); the method's own error is O(h²). m = 2 kg, ω = 5 rad/s, T = 1 s, ρ∞ = 0.9, h = 1e-2
  // and 5e-3: observed order ≥ 1.8 for both v and x, and |v error| ≤ 1e-3 of |F₀|/(m ω) at 5e-3.
  // Measured: 1.5e-4 → 3.7e-5 (v, relative to |F₀|/(m ω)) and 1.4e-3 → 3.6e-4 (x, relative to
  // |F₀|/(m ω²)), orders 2.00.
  const Eigen::Vector3d F0(3.0, -1.0, 2.0);
  const double m = 2.0, omega = 5.0, T = 1.0;
  const core::LoadHistory history = [omega](double t) { return std::sin(omega * t); };
  std::vector<double> velocity_errors, position_errors;
  for (const double h : {1e-2, 5e-3}) {
    core::Model model;
    const int node = core::rigid_body(model, core::add_rigid_body(model, {.mass = m, .inertia = Eigen::Matrix3d::Identity()})).node;
    core::add_load(model, core::NodalForce{node, F0}, history);
    solvers::GeneralizedAlpha integrator(model, {}, {.time_step = h, .tolerance = 1e-20, .residual_tolerance = 1e-12});
    while (integrator.time() < T - 0.5 * h) integrator.step();
    const double t = integrator.time();
    const Eigen::Vector3d v = F0 * (1 - std::cos(omega * t)) / (m * omega);
    const Eigen::Vector3d x = F0 * (t - std::sin(omega * t) / omega) / (m * omega);
    velocity_errors.push_back((integrator.velocity().head<3>() - v).norm() / (F0.norm() / (m * omega)));
    position_errors.push_back((model.state().position[node] - x).norm() / (F0.norm() / (m * omega * omega)));
  }
  const double velocity_order = std::log2(velocity_errors[0] / velocity_errors[1]);
  const double position_order = std::log2(position_errors[0] / position_errors[1]);
  INFO("relative errors: velocity " << velocity_errors[0] << " -> " << velocity_errors[1] << " (order "
                                    << velocity_order << "), position " << position_errors[0] << " -> "
                                    << position_errors[1] << " (order " << position_order << ")");
  CHECK(velocity_order >= 1.8);
  CHECK(position_order >= 1.8);
  CHECK(velocity_errors[1] <= 1e-3);
}
