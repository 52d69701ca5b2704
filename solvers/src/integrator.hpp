#pragma once
// Private to spar_solvers: the implementation of GeneralizedAlpha (docs/dynamics.md), its jobs in
// files of their own:
//   integrator.cpp                 options, evaluation of the residual and the matrix, snapshots
//   newton_step.cpp                one step: predictor, Newton iterations, cut-backs
//   iteration_matrix_strategy.cpp  update / frozen / modified (and the linear solver)
//   initial_assembly.cpp           consistent positions, velocities and accelerations: the start
//                                  and the restarts after events
//   event_location.cpp             user steps that land on the constraints' events
//   structure_changes.cpp          new patterns after events, model changes and remaps
//   energy_balance.cpp             the energy balance (eq. D8)
//   energy_alarm.cpp               the alarm when the run creates energy (eq. D8a)
//
// The integrator advances one DynamicState. Its configuration is the model's between the public
// calls: GeneralizedAlpha takes it from model.state() when a call starts and gives it back when
// the call returns or throws.

#include <spar/core/element.hpp>
#include <spar/core/model.hpp>
#include <spar/error.hpp>
#include <spar/solvers/dynamic_state.hpp>
#include <spar/solvers/generalized_alpha.hpp>

#include "energy_balance.hpp"
#include "iteration_matrix_strategy.hpp"
#include "step_coefficients.hpp"
#include "system_assembly.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace spar::solvers {

struct GeneralizedAlpha::Implementation {
  core::Model& model;
  ConstraintList constraints;
  DynamicOptions options;
  GeneralizedAlphaParameters alpha;
  DynamicCounters counters;
  detail::SystemAssembly assembly;
  detail::IterationMatrixStrategy matrix;
  long structure_version = 0;

  DynamicState state;
  bool initialized = false;
  /// True from an initialize() until the next completed step or remap: a second initialize() in
  /// between would only restart the method where it stands (dropping perturbed starting values).
  bool just_initialized = false;
  detail::EnergyBalance balance;
  /// The elements' energies in the assembly are not those of the current state (the step ended on
  /// evaluate_constraints_and_loads): energies() evaluates them first.
  bool energies_stale = false;
  std::vector<std::pair<double, std::string>> events;
  std::optional<EnergyAlarm> alarm;
  long watched_steps = 0;    ///< user steps the energy alarm has seen
  long unwatched_steps = 0;  ///< user steps since it last looked
  InitialAssembly assembly_report;

  /// What a failed step (or event location, or the auxiliary step of the perturbed starting
  /// values) restores: the dynamic state and the energy balance.
  struct Snapshot {
    DynamicState state;
    detail::EnergyBalance balance;
  };
  // Newton state of the current step: its start (also its chart's origin, q_n) and its increment.
  Snapshot start;
  Eigen::VectorXd increment, solution;
  int last_iterations = 0;
  std::string last_failure;  // why the last failed iteration failed, for the final message
  // The start of the user's step, restored when the whole step fails (buffers kept across steps).
  Snapshot step_start;

  // integrator.cpp: options, evaluation, snapshots ------------------------------------------------

  Implementation(core::Model& m, ConstraintList c, const DynamicOptions& o);
  static GeneralizedAlphaParameters validated_parameters(const DynamicOptions& options);
  void check_units() const;
  core::ElementInput input(double time) const;
  /// Scaled residual [r/β′ ; Φ] at the current state (the iteration matrix too when `c` is given).
  /// With `exact_mass`, the frozen strategy's stored rotation blocks are not used (the start-up and
  /// event projections need the true M).
  /// A residual-only evaluation computes the energies too, unless `with_energies` is false (an
  /// iterate that cannot be accepted).
  void evaluate(double time, const detail::MatrixCoefficients* c, double residual_scale, bool exact_mass = false,
                bool with_energies = true);
  /// The constraints and loads at an iterate that the Newton test may accept without the dynamic
  /// residual (SystemAssembly::evaluate_constraints_and_loads): the energies of the elements are
  /// computed when asked for (energies()).
  void evaluate_constraints_and_loads(double time);
  /// The elements' energies at the current state, for energies() after a step that ended on
  /// evaluate_constraints_and_loads.
  void evaluate_energies();
  /// The balance's forces at the current state start the next step's work.
  void restart_balance() { balance.restart(assembly, detail::driver_force(assembly, state.q, state.time, balance.driven)); }
  bool dynamic_residual_small(double residual_scale) const;
  double constraint_norm() const;
  /// 003 §5.1's ‖[Δq, h²βΔλ]‖², with Δq measured in each entry's unit when units are given.
  double increment_norm_squared(const Eigen::Ref<const Eigen::VectorXd>& dx, double dlambda_norm) const;
  void factorize(double time) { matrix.factorize(assembly, model, time); }
  /// The constraint terms of every constraint (acceleration terms c or Φ_t) into `out`'s
  /// multiplier rows.
  template <class Terms>
  void constraint_terms(Eigen::VectorXd& out, const Terms& terms) const {
    const int n = assembly.dof_count();
    for (std::size_t ci = 0; ci < constraints.size(); ++ci) {
      const int m = constraints[ci]->equation_count();
      terms(*constraints[ci], out.segment(n + assembly.first_multiplier(static_cast<int>(ci)), m));
    }
  }
  void save(Snapshot& s) const {
    s.state = state;
    s.balance = balance;
  }
  void restore(const Snapshot& s) {
    state = s.state;
    balance = s.balance;
  }
  /// Runs `job` on the state with the configuration taken from the model (where the user may
  /// have changed it since the last call); the model's configuration is the state's afterwards,
  /// also when `job` throws.
  template <class Job>
  void on_model_state(const Job& job) {
    state.q = model.state();
    try {
      job();
    } catch (...) {
      model.state() = state.q;
      throw;
    }
    model.state() = state.q;
  }

  // initial_assembly.cpp: the start and the restarts ---------------------------------------------

  void initialize();
  void factorize_mass_and_constraints();
  void consistent_accelerations(bool factorized);
  void perturb_starting_values();
  int project_positions(Eigen::VectorXd& change, const std::string& what);
  Eigen::VectorXd project_velocities(double& violation);
  void project_onto_constraints();
  void assemble_initial_state();

  // newton_step.cpp: one step ----------------------------------------------------------------------

  /// The Newton starting point of a step. `extrapolated` is Brüls et al.'s (v̇_{n+1} = 0, which
  /// carries a_n into the step); `velocity_only` picks v̇_{n+1} so that the motion starts as
  /// q_n ⊕ h v_n, the better guess after an impulsive start (a concentrated moment on a section
  /// of tiny rotary inertia has a huge, short-lived initial acceleration). Both keep the update
  /// relations of eq. 49, so the converged step is the same.
  enum class Predictor { extrapolated, velocity_only };
  Predictor predictor = Predictor::extrapolated;
  /// An element or joint could not be evaluated at an iterate (its spar::Error is kept in
  /// last_failure): the iteration has failed and the step is cut back.
  struct EvaluationFailure {};

  bool inside_chart();
  bool try_step(double h, Predictor predictor);
  bool newton(const detail::StepCoefficients& c, double t_next);
  void guarded_evaluate(double time, const detail::MatrixCoefficients* c, double residual_scale,
                        bool with_energies = true);
  /// Runs an evaluation; an element's or joint's spar::Error becomes an EvaluationFailure.
  template <class Evaluation>
  void guarded(const Evaluation& evaluation) {
    try {
      evaluation();
    } catch (const InputError&) {
      throw;  // bad input: a shorter step would meet it again (the user step is restored)
    } catch (const Error& error) {
      last_failure = error.what();
      throw EvaluationFailure{};
    }
  }
  void whole_step(double h);
  void advance(double h, int depth);

  // event_location.cpp: user steps and events ------------------------------------------------------

  double event_distance() const;
  void step_with_events();
  void locate_event(double g0, double h);
  void handle_events();

  // structure_changes.cpp ---------------------------------------------------------------------------

  void take_structure_changes();

  // energy_alarm.cpp ------------------------------------------------------------------------------

  /// Whether the alarm looks at this user step: when its energies are at hand (a residual-only
  /// evaluation ended the step, or a driver asked for them), and at least every 10th step, where
  /// it pays an energy evaluation (eq. D8a).
  bool energy_check_due();
  /// After a user step: `energies` (of the accepted state) widen the scale; the first time the
  /// energy created passes DynamicOptions::energy_alarm of it, the alarm goes off (eq. D8a).
  void watch_energy(const Energies& energies);
  void rebuild(const Eigen::MatrixXd* P);
};

}  // namespace spar::solvers
