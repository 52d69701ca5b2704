#pragma once
/// \file
/// The Lie-group generalized-α method for index-3 constrained systems (Arnold & Brüls 2007;
/// Brüls, Cardona & Arnold 2012; 003 eq. 49), with the iteration-matrix strategies of 003 §5.1
/// (docs/dynamics.md).
///
/// Equations: M(q) v̇ + f_qv(q, v) + f_int(q, v) − f_ext(q, t) + Bᵀλ = 0, Φ(q, t) = 0, with q a
/// product of frame blocks (R³ × SO(3)) and vector blocks (Rⁿ), v in the blocks' tangent layout
/// and B the constraint Jacobian in local increments (docs/model.md). The integrator sees only the
/// model's blocks and elements and the constraints: a new element or joint needs no change here.

#include <spar/core/model.hpp>
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/joints/constraint.hpp>
#include <spar/solvers/dynamic_state.hpp>
#include <spar/solvers/linear_solver.hpp>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace spar::solvers {

/// How the Newton iterations of a step get their iteration matrix.
enum class IterationMatrix {
  update,    ///< full Newton: assembled and factorized every iteration
  frozen,    ///< 003's strategy: the rotation–rotation blocks J_θ of the mass, damping (gyroscopic)
             ///< and stiffness matrices taken when the method starts and kept, taken anew only when
             ///< it restarts (initialize(), a structure change, an event, remap); the rest updated
             ///< every iteration
  modified,  ///< modified Newton: the whole factorization kept across iterations and steps until
             ///< the contraction of the increments slows down
};

/// "update", "frozen" or "modified"; spar::Error listing them otherwise.
IterationMatrix iteration_matrix_from_string(std::string_view name);
std::string_view to_string(IterationMatrix strategy);

/// α_m, α_f, γ, β from the spectral radius at infinite frequency ρ∞ ∈ [0, 1] (Chung & Hulbert
/// 1993): α_m = (2ρ∞ − 1)/(ρ∞ + 1), α_f = ρ∞/(ρ∞ + 1), γ = ½ + α_f − α_m, β = ¼(γ + ½)².
struct GeneralizedAlphaParameters {
  double alpha_m = 0.0, alpha_f = 0.0, gamma = 0.5, beta = 0.25;
  static GeneralizedAlphaParameters from_spectral_radius(double rho_infinity);
};

struct DynamicOptions {
  double time_step = 1e-3;
  double spectral_radius = 0.9;  ///< ρ∞; 1 = no numerical dissipation
  IterationMatrix iteration_matrix = IterationMatrix::update;
  /// 003 §5.1: converged when ‖[Δq, h²βΔλ]‖² ≤ tolerance — a *squared* norm, Δq in m and rad
  /// (or each block's own unit when `increment_units` is set): the default 1e-6 accepts a last
  /// Newton increment of up to 1e-3 m or rad (the iterate itself is then far closer, Newton
  /// converging quadratically); for increments below δ give δ²…
  double tolerance = 1e-6;
  /// Optional unit of each increment entry (global tangent layout, dof_count entries): the
  /// convergence test divides Δq by it, so metres, radians, slopes and curve parameters are
  /// measured alike in mixed models. Empty: every entry's unit is 1 (003's test).
  Eigen::VectorXd increment_units;
  /// …and the constraints hold, ‖Φ‖∞ ≤ constraint_tolerance…
  double constraint_tolerance = 1e-10;
  /// …and the dynamic residual is small: ‖r‖∞ ≤ residual_tolerance · (size of its terms).
  double residual_tolerance = 1e-6;
  int max_iterations = 25;
  int max_cutbacks = 8;                      ///< halvings of a step that does not converge
  double modified_newton_contraction = 0.5;  ///< refactorize when ‖Δ_k‖ > this · ‖Δ_{k−1}‖
  LinearSolverKind linear_solver = LinearSolverKind::klu;
  /// Tell the linear solver which unknowns belong to which body (LinearSolver::set_substructures):
  /// KLU then factorizes a structure of several beams by substructuring when that is cheaper, and
  /// refines its solves to round-off (docs/dynamics.md D12). Used with `update` and `frozen` (a
  /// factorization per iteration), not with `modified` (solves dominate). Off: the whole matrix.
  bool substructuring = true;
  /// Events inside a step (a slider reaching its end stop) are located: the step is shortened
  /// so that it ends past the event by at most `event_tolerance`, in the unit of the constraint's
  /// event distance (m for a sliding joint), before the event switches the equations
  /// (docs/dynamics.md D6c). Off: the event happens at the end of the step that crossed it, and
  /// the projection onto the new equations moves the state by the overshoot.
  /// 1 µm for a slider: its projection onto the stop then costs a stiff steel tube ~1e-5 J of
  /// strain energy, and the step after the event is not shorter than ~1 µm over the slider's speed.
  bool locate_events = true;
  double event_tolerance = 1e-6;
  /// Parallel from solvers::parallel_assembly_min_blocks elements and joints up; below, with more than
  /// one thread, serial or parallel as the faster of the two is timed during the run (bitwise the
  /// serial result either way; docs/performance.md, "Parallel assembly").
  solvers::AssemblyExecution assembly = solvers::AssemblyExecution::automatic;
  /// Consistent initial assembly by the first initialize() (docs/dynamics.md, "Initial
  /// assembly"): the positions are moved onto Φ(q, t₀) = 0 and the velocities onto
  /// B v + Φ_t = 0, each by the least change in the metric of the mass matrix; what changed is
  /// reported by GeneralizedAlpha::initial_assembly(). Off: the run starts from the state as given
  /// (an inconsistent start is then snapped onto the constraints by the first step).
  bool initial_assembly = true;
  /// The largest position change the initial assembly may make, ‖Δq‖∞ over the increments (m for
  /// translations, rad for rotations, each vector entry in its own unit, or divided by
  /// `increment_units` when given). A larger one is a spar::Error and leaves the state as given:
  /// a joint placed that far off is a modelling error, not a start to be snapped shut.
  double initial_assembly_tolerance = 1e-3;
  /// τ [s] of the metric M + τ²K in which the initial assembly projects the velocities (K the
  /// tangent stiffness at the assembled state). 0: the mass metric, the least change of kinetic
  /// energy — the velocities an impulse through the constraints gives (a driver started from
  /// rest spins its own node and leaves the rest of a flexible body behind, which then rings).
  /// τ well above the period of the slowest elastic mode makes deformation rates expensive: the
  /// projection then gives the bodies the rigid motion the constraints allow (to ~1/(τω)²).
  double initial_velocity_stiffness_time = 0.0;
  /// Perturbed starting values (docs/dynamics.md D6d; Arnold, Brüls & Cardona 2015): the first
  /// initialize() starts the method on its smooth numerical solution, a₀ = v̇₀ + Δ_α h v̈₀ and
  /// v₀ ← v₀ + (1/6 − β − Δ_α/2) h² v̈₀, plus h²/12 Ω₀ × Ω̇₀ on a frame's rotation (Δ_α = α_m −
  /// α_f, v̈₀ from one auxiliary step of h), instead of a₀ = v̇₀ and the consistent v₀. The
  /// index-3 method's multipliers and accelerations then lose their O(h) start-up transient (an
  /// error alternating from step to step, decaying as ρ∞ per step) and are second order from the
  /// first step; velocity() at t₀ is then v₀ + O(h²) (the method's own). Costs one step; events
  /// and remaps restart with a = v̇ and the velocities as they are. Off by default: a step drive
  /// (the flexible slider-crank's) makes v̈₀ meaningless (D6d).
  bool perturbed_starting_values = false;
  /// The energy alarm (docs/dynamics.md D8a): after every step whose energies are at hand, and at
  /// least every 10th step (an energy evaluation there), the energy the integrator created since
  /// t = 0 (Energies::created) is compared with the run's energy scale (Energies::scale);
  /// the first time it exceeds `energy_alarm` times the scale, the integrator warns on stderr
  /// (once per run) and energy_alarm() reports when and how much. A run that creates energy is
  /// unstable or under-resolved: the index-3 form at ρ∞ = 1 with constraints can be (the heavy
  /// top at h = 1e-3); ρ∞ < 1 or a smaller step cures it. ∞ turns the alarm off.
  double energy_alarm = 0.05;
};

/// What the initial assembly changed (DynamicOptions::initial_assembly).
struct InitialAssembly {
  bool performed = false;                 ///< false when switched off (or before initialize())
  int position_iterations = 0;            ///< Gauss–Newton iterations onto Φ = 0 (0: already there)
  double constraint_residual = 0.0;       ///< ‖Φ(q₀, t₀)‖∞ of the state as given
  double velocity_constraint_residual = 0.0;  ///< ‖B v₀ + Φ_t‖∞ of the velocities as given
  /// The position change Δq, global tangent layout (q ← q₀ ⊕ Δq up to round-off: the sum of the
  /// Gauss–Newton increments).
  Eigen::VectorXd position_change;
  /// ‖Δq‖∞ in the units of the tolerance (see DynamicOptions::initial_assembly_tolerance), and the
  /// block where it happened (−1: none moved).
  double largest_position_change = 0.0;
  int largest_position_change_block = -1;
  /// The velocity change Δv (global tangent layout: ẋ inertial, Ω material) and ‖Δv‖∞.
  Eigen::VectorXd velocity_change;
  double largest_velocity_change = 0.0;
};

/// What a run did.
struct DynamicCounters {
  /// Completed steps, sub-steps included: a user step() halved once counts 2 (the halvings are
  /// in `cutbacks`), so steps − cutbacks is the number of step() calls that completed (as long as
  /// none threw: a failed call keeps its cut-backs, not its sub-steps).
  long steps = 0;
  long newton_iterations = 0;     ///< linear solves
  long jtheta_evaluations = 0;    ///< iterations that evaluated the rotational block J_θ
  long factorizations = 0;        ///< numeric factorizations
  long substructured_factorizations = 0;  ///< of which by substructuring (DynamicOptions::substructuring)
  long residual_evaluations = 0;
  long cutbacks = 0;
  long rejected_rotations = 0;     ///< Newton iterates refused because a frame turned by ≥ π in a step
  long pattern_builds = 1;         ///< sparse patterns built (1 + structure changes)
  long event_substeps = 0;         ///< extra steps taken to land on events (counted in steps too)
  double wall_seconds = 0.0;
};

/// The energy balance of a run (docs/dynamics.md eq. D8), in joules.
struct Energies {
  double kinetic = 0.0;
  double strain = 0.0;
  double gravity = 0.0;         ///< gravity potential
  /// Work done since t = 0 by external loads (f_ext · v) and by the constraint forces (−λᵀ B v,
  /// non-zero for drivers), trapezoidal in time.
  double external_work = 0.0;
  /// The work of the elements' dissipative forces since t = 0 (dampers, the Kelvin–Voigt stresses
  /// of cables: Element::has_dissipation), trapezoidal in time like external_work: the heat the
  /// model's own damping made (docs/dynamics.md D8).
  double physical_dissipation = 0.0;
  /// What the integrator dissipated since t = 0: external_work − (total() − total at t = 0) −
  /// physical_dissipation.
  double numerical_dissipation = 0.0;
  /// The energy the integrator created since t = 0 (docs/dynamics.md D8a): (total() − total at
  /// t = 0) + physical_dissipation − the work of the loads and of the drivers (the constraints
  /// whose Φ_t is not zero; a passive joint does no work). Near zero or negative in a stable run;
  /// its growth is what DynamicOptions::energy_alarm watches.
  double created = 0.0;
  /// The run's energy scale so far: the largest kinetic + |strain| + |gravity − gravity at t = 0|
  /// + |work of the loads| + |work of the drivers| + physical_dissipation of the accepted states.
  double scale = 0.0;
  double total() const { return kinetic + strain + gravity; }
};

/// When and how much energy the integrator created, the first time it passed the alarm
/// (DynamicOptions::energy_alarm).
struct EnergyAlarm {
  double time = 0.0;     ///< the end of the step where it happened, s
  double created = 0.0;  ///< Energies::created then, J
  double scale = 0.0;    ///< Energies::scale then, J
};

using ConstraintList = std::vector<std::unique_ptr<joints::Constraint>>;

class GeneralizedAlpha {
public:
  /// Integrates `model` (whose state() is the initial configuration) with `constraints`. Throws
  /// spar::Error for invalid options.
  GeneralizedAlpha(core::Model& model, ConstraintList constraints, const DynamicOptions& options);
  ~GeneralizedAlpha();
  GeneralizedAlpha(const GeneralizedAlpha&) = delete;
  GeneralizedAlpha& operator=(const GeneralizedAlpha&) = delete;

  /// Sets a frame block's initial velocity (before the first step): ẋ inertial, Ω material.
  void set_velocity(int node, const Eigen::Vector3d& linear, const Eigen::Vector3d& angular);
  /// Sets any block's initial velocity (before the first step), in the block's tangent layout.
  void set_velocity(int block, const Eigen::VectorXd& velocity);
  /// The first call assembles the initial state (DynamicOptions::initial_assembly: positions
  /// onto Φ = 0, velocities onto B v + Φ_t = 0, least change in the mass metric; spar::Error
  /// when the positions would move by more than initial_assembly_tolerance or do not converge,
  /// the state then left as given), then computes consistent initial accelerations and
  /// multipliers from M v̇ + Bᵀλ = −f and B v̇ = −c. Done by the first step() if not called (the
  /// same run, bit for bit). Called again during a run (after a remap
  /// whose map P does not carry the accelerations, e.g. an ALE re-mesh), it restarts the method
  /// from consistent accelerations at the current state (a = v̇; the initial assembly and the
  /// perturbed starting values are the first call's only); the energy balance carries on, and a
  /// jump of the energy at the re-mesh shows in the numerical dissipation. A call with no
  /// completed step or remap since the last one is a spar::Error: it could only restart the
  /// method where it stands. Also a spar::Error for a model that Model::check_consistent refuses.
  void initialize();
  /// Advances by one time step (in halves, recursively, if Newton fails). Throws spar::Error
  /// naming the step, the time and the likely cause when even max_cutbacks halvings fail; the
  /// state, velocities, accelerations, multipliers and time are then those before the call (no
  /// converged half-step of the failed step is kept). Refuses, before anything, a model that
  /// Model::check_consistent refuses (a block written into model.state() that is no rotation).
  void step();

  double time() const;
  const core::Configuration& configuration() const;
  const Eigen::VectorXd& velocity() const;
  const Eigen::VectorXd& acceleration() const;
  /// The Lagrange multipliers λ (constraint forces), constraint by constraint.
  const Eigen::VectorXd& multipliers() const;
  /// The state the integrator advances: t, q, v, v̇, the algorithmic acceleration a and λ (a copy
  /// is a snapshot of the motion). Its q is the model's configuration as the integrator's last
  /// call left it (configuration() is the model's now).
  const DynamicState& state() const;
  /// The multipliers of constraint `c` (its equation_count() entries), in the order of the
  /// constructor's list; with joints::reaction or a joint's reaction_in_frame they give the
  /// joint's reaction (docs/joints.md §5). spar::Error for a constraint that does not exist.
  Eigen::VectorXd multipliers(int c) const;
  /// Constraint `c` of the constructor's list (the integrator owns them), e.g. to read a joint's
  /// coordinates: dynamic_cast<const joints::RevoluteJoint&>(integrator.constraint(0)).
  const joints::Constraint& constraint(int c) const;
  int constraint_count() const;
  const DynamicCounters& counters() const;
  int multiplier_count() const;
  /// Newton iterations of the last completed step.
  int last_step_iterations() const;
  /// ‖Φ(q, t)‖∞ now.
  double constraint_residual() const;
  /// The energies at the current state and the balance since t = 0.
  Energies energies() const;
  /// The first time the energy alarm went off (DynamicOptions::energy_alarm), or nothing.
  const std::optional<EnergyAlarm>& energy_alarm() const;
  /// What the initial assembly of the first initialize() changed.
  const InitialAssembly& initial_assembly() const;

  /// Structure changes (docs/model.md, "Structure changes"). The integrator rebuilds its sparse
  /// pattern and symbolic factorization by itself after a step in which a constraint's
  /// update_structure() reported a change or the model's structure_version() moved; after a
  /// constraint's event it also restarts the method from v̇ and λ consistent with the new
  /// equations (a = v̇, as at t = 0), which keeps it second order across the event. When blocks
  /// were split or merged (Model::replace_state), call remap with the linear map P (new dofs ×
  /// old dofs) that carries velocities, accelerations and the algorithmic acceleration across:
  /// v ← P v, v̇ ← P v̇, a ← P a. Multipliers of constraints whose equation count is unchanged are
  /// kept; the others start from zero (an index-3 multiplier has no history in the method). A run
  /// with DynamicOptions::increment_units needs the new layout's units, one per new dof (they
  /// replace the old ones; refused when missing or misfitting). An element or block changed
  /// without a new dof count is taken in by the next step() itself; a new dof count without
  /// remap is refused there. When a constraint's equations changed at an event (an end stop
  /// locking), the state is projected onto the new constraint set, positions and velocities in
  /// the metric of M (a plastic impact), and the accelerations restart consistent
  /// (docs/dynamics.md D6b).
  void remap(const Eigen::MatrixXd& P, const Eigen::VectorXd& increment_units = {});
  /// The events of the run so far (time and what the constraint said), in order.
  const std::vector<std::pair<double, std::string>>& events() const;

private:
  struct Implementation;
  std::unique_ptr<Implementation> impl_;
};

}  // namespace spar::solvers
