// The energy alarm of the generalized-α integrator (docs/dynamics.md D8a): a run that creates
// energy says so, once, when it happens.
#include "integrator.hpp"

#include <cmath>
#include <cstdio>

namespace spar::solvers {

namespace {

/// Steps from the start before the alarm judges (D8a): the balance books work by the trapezoidal
/// rule, whose relative error in the first steps from rest is of order one (a motion started with
/// a constant jerk, integrated exactly, books 2/3 of its kinetic energy as work in the first
/// step: the truss deployment's first step showed C = 5 % of S, at energies of 1e-20 J) and
/// decays as the energy grows; an instability builds up over many more steps than these.
constexpr long grace_steps = 10;

/// The most user steps between two looks when the energies are not at hand: an energy
/// evaluation at every step cost 6 % of the flagship's run (bench_dynamics slider_crank_run,
/// 003's Newton test, which leaves the elements' energies stale), one in ten costs ~0.6 %.
constexpr long check_interval = 10;

}  // namespace

bool GeneralizedAlpha::Implementation::energy_check_due() {
  if (energies_stale && ++unwatched_steps < check_interval) return false;
  unwatched_steps = 0;
  return true;
}

void GeneralizedAlpha::Implementation::watch_energy(const Energies& energies) {
  balance.widen_scale(energies);
  if (alarm || ++watched_steps <= grace_steps) return;
  // eq. D8a: created energy beyond the alarm's share of the scale, and beyond the round-off of the
  // balance's sums (E and E₀ carry the gravity potential's arbitrary datum).
  const double round_off = 1e-12 * (std::abs(energies.total()) + std::abs(balance.initial_energy));
  if (!(energies.created > options.energy_alarm * balance.scale + round_off)) return;
  alarm = EnergyAlarm{.time = state.time, .created = energies.created, .scale = balance.scale};
  std::fprintf(stderr,
               "spar: warning: the integrator created %.4g J of energy by t = %.6g s (%.3g %% of the run's energy "
               "scale %.4g J; the alarm is at %.3g %%): the run is unstable or under-resolved. Use rho_inf < 1 "
               "(e.g. 0.9) or a smaller time step; the index-3 form at rho_inf = 1 with constraints can be "
               "unstable (docs/dynamics.md D8a).\n",
               energies.created, state.time, 100.0 * energies.created / balance.scale, balance.scale,
               100.0 * options.energy_alarm);
}

}  // namespace spar::solvers
