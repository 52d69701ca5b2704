// The energy balance books the heat of the elements' own damping as physical dissipation, apart
// from the integrator's numerical dissipation (issue 30; docs/dynamics.md D8).
#include <spar/spar.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace spar;

namespace {

struct Balance {
  double physical = 0.0, numerical = 0.0, mechanical_change = 0.0;
  bool physical_never_decreased = true;
};

/// A planar cable of 1 m pinned at its root (the root's position fixed, its slope free), released
/// horizontally under gravity and integrated for 0.5 s at ρ∞ = 1 (no numerical damping of the
/// method's own). Kelvin–Voigt coefficient `damping` (s).
Balance swing(double damping) {
  core::Model model;
  const core::Cable cable =
      core::add_cable<2>(model, {.end = Eigen::Vector3d(1, 0, 0), .elements = 4,
                                 .section = {.axial_stiffness = 1e3, .bending_stiffness = 0.1,
                                             .mass_per_length = 1.0, .damping_coefficient = damping}});
  model.fix_coordinates(cable.nodes.front(), {0, 1});
  model.set_gravity(Eigen::Vector3d(0, -9.81, 0));
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = 1e-3, .spectral_radius = 1.0});
  integrator.initialize();
  const solvers::Energies start = integrator.energies();
  Balance balance;
  double last_physical = 0.0;
  for (int step = 0; step < 500; ++step) {
    integrator.step();
    const double physical = integrator.energies().physical_dissipation;
    balance.physical_never_decreased = balance.physical_never_decreased && physical >= last_physical;
    last_physical = physical;
  }
  const solvers::Energies end = integrator.energies();
  balance.physical = end.physical_dissipation;
  balance.numerical = end.numerical_dissipation;
  balance.mechanical_change = end.total() - start.total();
  return balance;
}

}  // namespace

TEST_CASE("a damped cable's Kelvin-Voigt heat is physical dissipation, not the integrator's",
          "[loads][rancf][energy]") {
  const Balance undamped = swing(0.0);
  const Balance damped = swing(0.02);
  INFO("undamped: numerical " << undamped.numerical << " J; damped: physical " << damped.physical
                              << " J, numerical " << damped.numerical << " J, change of energy "
                              << damped.mechanical_change << " J");
  // Without damping nothing is physical, and ρ∞ = 1 leaves the method's own dissipation small.
  CHECK(undamped.physical == 0.0);
  // With it, the damping takes energy at every step (D grows, as ½(f_n + f_n+1)·hΔq of a force
  // that opposes the rates must)...
  CHECK(damped.physical > 0.0);
  CHECK(damped.physical_never_decreased);
  // ...and the integrator's share stays what it was without damping: before this booking the
  // whole heat appeared as numerical dissipation. The bound: the undamped run's own numerical
  // dissipation plus 1 % of the heat (the O(h²) difference of two trapezoidal integrals).
  CHECK(std::abs(damped.numerical) <= std::abs(undamped.numerical) + 1e-2 * damped.physical);
  // Nearly all the energy the damped cable lost is the damping's heat (0.1008 of 0.1009 J
  // measured), so the bound above is a real one.
  CHECK(damped.physical > 0.9 * -damped.mechanical_change);
}
