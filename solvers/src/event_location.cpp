// The user's steps of the generalized-α integrator and the constraints' events inside them
// (docs/dynamics.md D6b, D6c): a step that crosses an event is redone to end just past it, and the
// event switches the equations there.
#include "integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace spar::solvers {

/// The smallest event distance of the constraints in the current state (+∞: no event ahead).
double GeneralizedAlpha::Implementation::event_distance() const {
  double g = INFINITY;
  for (const auto& constraint : constraints) g = std::min(g, constraint->event_distance(state.q));
  return g;
}

/// One user step of options.time_step (docs/dynamics.md D6c). When a constraint's event falls
/// inside it (its event distance g goes from positive to below −event_tolerance), the step is
/// replaced by steps that end just past the event, −event_tolerance ≤ g ≤ 0; the event is
/// handled there and the rest of the user step follows. A lock that happens where the slider
/// is, not a step's overshoot later, needs no projection of the state worth the name: an
/// overshoot δ projected back onto the stop would stretch the stiff members it moves by δ.
void GeneralizedAlpha::Implementation::step_with_events() {
  const double t_target = state.time + options.time_step;
  while (t_target - state.time > 1e-9 * options.time_step) {
    const double h = t_target - state.time, g0 = event_distance();
    whole_step(h);
    if (options.locate_events && g0 > 0.0 && event_distance() < -options.event_tolerance) locate_event(g0, h);
    handle_events();
  }
  state.time = t_target;  // not t + rounding: the user's steps land on multiples of h
}

/// After a step of length h from step_start that crossed an event (g0 > 0 before it, g1 after
/// it below −event_tolerance): redone as one step from step_start that ends past the event by
/// at most the tolerance, −event_tolerance ≤ g ≤ 0. The step's length is found by regula falsi
/// with the Illinois modification (the end of the bracket kept twice has its g halved), which
/// converges superlinearly on the smooth g(θh). Every try starts from step_start: keeping the
/// tries that end short of the event would leave steps of nanoseconds near it, whose index-3
/// multipliers (Φ's round-off over βh²) are meaningless. After 30 tries the shortest step past
/// the event is taken as it is.
void GeneralizedAlpha::Implementation::locate_event(double g0, double h) {
  double lo = 0.0, hi = 1.0, g_lo = g0, g_hi = event_distance();
  int kept = 0;  // the end of the bracket that moved last: −1 lo, +1 hi
  for (int attempt = 0; attempt < 30; ++attempt) {
    const double theta = lo + (hi - lo) * g_lo / (g_lo - g_hi);
    restore(step_start);
    whole_step(theta * h);
    ++counters.event_substeps;
    const double g = event_distance();
    if (g <= 0.0 && g >= -options.event_tolerance) return;
    if (g > 0.0) {
      lo = theta;
      g_lo = g;
      if (kept == -1) g_hi /= 2;
      kept = -1;
    } else {
      hi = theta;
      g_hi = g;
      if (kept == 1) g_lo /= 2;
      kept = 1;
    }
  }
  restore(step_start);
  whole_step(hi * h);
}

/// After a converged step: let the constraints switch at their events, and rebuild when they or
/// the model changed the structure. After an event the method restarts from accelerations
/// consistent with the new equations: the algorithmic acceleration a is an O(h)-shifted mean of
/// v̇ under the old equations (a released mass would keep its pendulum's), and carrying it
/// across makes every later step first-order accurate. When an event changed a constraint's
/// equations the state is first projected onto them (project_onto_constraints).
void GeneralizedAlpha::Implementation::handle_events() {
  bool changed = model.structure_version() != structure_version, event = false;
  bool equations_changed = false;
  for (auto& constraint : constraints) {
    const int before = constraint->equation_count();
    std::string description;
    if (constraint->update_structure(state.q, state.velocity, state.time, description)) {
      changed = event = true;
      events.emplace_back(state.time, description);
    }
    equations_changed = equations_changed || constraint->equation_count() != before;
  }
  if (!changed) return;
  rebuild(nullptr);
  if (equations_changed) {
    project_onto_constraints();  // a new equation: onto it, then a consistent restart
  } else if (event) {
    consistent_accelerations(false);
    evaluate(state.time, nullptr, 1.0);
    restart_balance();
  }
}

}  // namespace spar::solvers
