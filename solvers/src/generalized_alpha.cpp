// The Lie-group generalized-α integrator (docs/dynamics.md; Brüls, Cardona & Arnold 2012,
// Algorithm 1, with the index-3 constraints of Arnold & Brüls 2007 and 003 eq. 49).
//
// Unknowns of a Newton iteration: the increment Δx of the step's motion h·Δq (6 per node) and the
// scaled multipliers λ̃ = λ/β′. The dynamic rows are divided by β′ = (1 − α_m)/(h²β(1 − α_f)), so
// the iteration matrix
//     [ M + (γ′/β′) C + (1/β′)(K + K_λ) T    Bᵀ ]
//     [ B T                                   0  ]
// has entries of the size of the mass and of the constraint Jacobian for every h (the scaling of
// Bottasso, Bauchau & Cardoso 2007), and Newton's increment of the multipliers is h²β-sized.
#include <spar/solvers/generalized_alpha.hpp>

#include <spar/error.hpp>
#include <spar/lie/exp.hpp>
#include <spar/lie/tangent.hpp>

#include "finite_values.hpp"
#include "round_off.hpp"
#include "system_assembly.hpp"

#include <Eigen/LU>

#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace spar::solvers {


IterationMatrix iteration_matrix_from_string(std::string_view name) {
  if (name == "update") return IterationMatrix::update;
  if (name == "frozen") return IterationMatrix::frozen;
  if (name == "modified") return IterationMatrix::modified;
  throw Error("unknown iteration-matrix strategy '" + std::string(name) + "'",
              "solvers::iteration_matrix_from_string", "use update, frozen or modified");
}

std::string_view to_string(IterationMatrix strategy) {
  switch (strategy) {
    case IterationMatrix::update: return "update";
    case IterationMatrix::frozen: return "frozen";
    case IterationMatrix::modified: return "modified";
  }
  return "";
}

GeneralizedAlphaParameters GeneralizedAlphaParameters::from_spectral_radius(double rho) {
  if (!(rho >= 0.0 && rho <= 1.0))
    throw Error("spectral radius rho_infinity = " + significant(rho) + " is outside [0, 1]",
                "solvers::GeneralizedAlphaParameters", "give 0 <= rho_infinity <= 1");
  GeneralizedAlphaParameters p;
  p.alpha_m = (2 * rho - 1) / (rho + 1);
  p.alpha_f = rho / (rho + 1);
  p.gamma = 0.5 + p.alpha_f - p.alpha_m;
  p.beta = 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5);
  return p;
}

namespace {

using detail::Chart;
using detail::MatrixCoefficients;

std::vector<joints::Constraint*> pointers(const ConstraintList& constraints) {
  std::vector<joints::Constraint*> raw;
  for (const auto& constraint : constraints) raw.push_back(constraint.get());
  return raw;
}

}  // namespace

struct GeneralizedAlpha::Implementation {
  core::Model& model;
  ConstraintList constraints;
  DynamicOptions options;
  GeneralizedAlphaParameters alpha;
  detail::SystemAssembly assembly;
  std::unique_ptr<LinearSolver> solver;
  long structure_version = 0;

  double t = 0.0;
  Eigen::VectorXd velocity, acceleration, algorithmic_acceleration, lambda;
  bool initialized = false;
  /// True from an initialize() until the next completed step or remap: a second initialize() in
  /// between would only restart the method where it stands (dropping perturbed starting values).
  bool just_initialized = false;
  /// The integrator's state at the start of a step, restored when the step fails.
  struct Snapshot {
    core::Configuration q;
    Eigen::VectorXd velocity, acceleration, algorithmic_acceleration, lambda, work_force;
    double t = 0.0, external_work = 0.0;
  };
  // Newton state of the current step: its start (also its chart's origin, q_n) and its increment.
  Snapshot start;
  Eigen::VectorXd increment, solution;
  bool have_factorization = false, refactor_requested = false;
  double factorized_step = 0.0;
  int last_iterations = 0;
  std::string last_failure;  // why the last failed iteration failed, for the final message
  DynamicCounters counters;
  // Energy balance (eq. D8).
  double initial_energy = 0.0, external_work = 0.0;
  /// The elements' energies in the assembly are not those of the current state (the step ended on
  /// evaluate_constraints_and_loads): energies() evaluates them first.
  bool energies_stale = false;
  Eigen::VectorXd last_work_force;
  std::vector<std::pair<double, std::string>> events;
  InitialAssembly assembly_report;

  Implementation(core::Model& m, ConstraintList c, const DynamicOptions& o)
      : model(m),
        constraints(std::move(c)),
        options(o),
        alpha(validated_parameters(o)),
        assembly(m, pointers(constraints), o.assembly),
        solver(make_linear_solver(o.linear_solver)),
        structure_version(m.structure_version()) {
    analyze();
    const int n = assembly.dof_count();
    velocity = acceleration = algorithmic_acceleration = increment = Eigen::VectorXd::Zero(n);
    lambda = Eigen::VectorXd::Zero(assembly.multiplier_count());
    solution = Eigen::VectorXd::Zero(assembly.size());
    check_units();
  }

  static GeneralizedAlphaParameters validated_parameters(const DynamicOptions& options) {
    const char* where = "solvers::GeneralizedAlpha";
    if (!(options.initial_assembly_tolerance >= 0.0) || !(options.initial_velocity_stiffness_time >= 0.0) ||
        !std::isfinite(options.initial_velocity_stiffness_time))
      throw Error("initial_assembly_tolerance and initial_velocity_stiffness_time must be >= 0 and finite", where,
                  "fix the DynamicOptions");
    if (!(options.time_step > 0.0) || !std::isfinite(options.time_step))
      throw Error("time step must be positive and finite", where, "give DynamicOptions::time_step > 0");
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance) || options.max_iterations < 1 ||
        options.max_cutbacks < 0)
      throw Error("tolerance must be positive and finite, max_iterations >= 1, max_cutbacks >= 0", where,
                  "fix the DynamicOptions");
    // The constraint and residual tests may be switched off with +infinity, never with NaN (every
    // comparison with NaN is false: a NaN tolerance failed every step as "Newton did not converge").
    if (!(options.constraint_tolerance > 0.0) || !(options.residual_tolerance > 0.0))
      throw Error("constraint_tolerance = " + significant(options.constraint_tolerance) + " and residual_tolerance = " +
                      significant(options.residual_tolerance) + " must be positive (+inf: the test is off)",
                  where, "fix the DynamicOptions' tolerances (NaN and values <= 0 are refused)");
    if (!(options.modified_newton_contraction > 0.0 && options.modified_newton_contraction <= 1.0))
      throw Error("modified_newton_contraction = " + significant(options.modified_newton_contraction) +
                      " is outside (0, 1]",
                  where, "give the contraction factor that triggers a refactorization, e.g. 0.5");
    return GeneralizedAlphaParameters::from_spectral_radius(options.spectral_radius);
  }

  void check_units() const {
    const Eigen::VectorXd& units = options.increment_units;
    if (units.size() == 0) return;
    if (units.size() != assembly.dof_count() || !(units.array() > 0.0).all() || !units.allFinite())
      throw Error("increment_units has " + std::to_string(units.size()) + " entries for " +
                      std::to_string(assembly.dof_count()) + " dofs, or a non-positive entry",
                  "solvers::GeneralizedAlpha", "give one positive unit per dof, or none");
  }

  core::ElementInput input(double time) const {
    core::ElementInput in;
    in.q = &model.state();
    in.velocity = &velocity;
    in.acceleration = &acceleration;
    in.time = time;
    in.load_factor = 1.0;
    in.gravity = model.gravity();
    return in;
  }

  /// Scaled residual [r/β′ ; Φ] at the current state (the iteration matrix too when `c` is given).
  /// With `exact_mass`, the frozen strategy's stored rotation blocks are not used (the start-up and
  /// event projections need the true M).
  /// A residual-only evaluation computes the energies too, unless `with_energies` is false (an
  /// iterate that cannot be accepted).
  void evaluate(double time, const MatrixCoefficients* c, double residual_scale, bool exact_mass = false,
                bool with_energies = true) {
    ++counters.residual_evaluations;
    const bool frozen = options.iteration_matrix == IterationMatrix::frozen && initialized && !exact_mass;
    const bool energies = !c && with_energies;
    assembly.evaluate(input(time), lambda, c, Chart::local_increment, increment, frozen, energies);
    energies_stale = !energies;
    auto dynamic = assembly.residual().head(assembly.dof_count());
    for (int dof : model.fixed_dofs()) dynamic(dof) = 0.0;
    dynamic /= residual_scale;
  }

  /// The constraints and loads at an iterate that the Newton test may accept without the dynamic
  /// residual (SystemAssembly::evaluate_constraints_and_loads): the energies of the elements are
  /// computed when asked for (energies()).
  void evaluate_constraints_and_loads(double time) {
    assembly.evaluate_constraints_and_loads(input(time), lambda, increment);
    energies_stale = true;
  }

  /// The elements' energies at the current state, for energies() after a step that ended on
  /// evaluate_constraints_and_loads.
  void evaluate_energies() {
    assembly.evaluate_energies(input(t));
    energies_stale = false;
  }

  bool dynamic_residual_small(double residual_scale) const {
    if (!std::isfinite(options.residual_tolerance)) return true;  // the test is off
    const double floor = detail::residual_round_off_floor(assembly.pattern().matrix(), model.state());
    const Eigen::VectorXd& r = assembly.residual();
    for (int i = 0; i < assembly.dof_count(); ++i)
      if (std::abs(r(i)) > options.residual_tolerance * assembly.scale()(i) / residual_scale + floor)
        return false;
    return true;
  }

  double constraint_norm() const {
    const int m = assembly.multiplier_count();
    return m ? assembly.residual().tail(m).lpNorm<Eigen::Infinity>() : 0.0;
  }

  /// 003 §5.1's ‖[Δq, h²βΔλ]‖², with Δq measured in each entry's unit when units are given.
  double increment_norm_squared(const Eigen::Ref<const Eigen::VectorXd>& dx, double dlambda_norm) const {
    const double dq = options.increment_units.size() ? dx.cwiseQuotient(options.increment_units).squaredNorm()
                                                     : dx.squaredNorm();
    return dq + dlambda_norm * dlambda_norm;
  }

  /// Factorizes the assembled matrix after the Dirichlet conditions; a singular matrix is a
  /// modelling error that no smaller step repairs.
  void factorize(double time) {
    if (!model.fixed_dofs().empty()) {
      Eigen::VectorXd unused = Eigen::VectorXd::Zero(assembly.size());
      assembly.pattern().apply_dirichlet(model.fixed_dofs(), unused);
    }
    try {
      solver->factorize(assembly.pattern().matrix());
    } catch (const Error& error) {
      std::ostringstream what;
      what << "the iteration matrix is singular at t = " << time << " (step " << counters.steps + 1
           << "): " << error.what();
      const std::string defects = mass_defects();
      if (!defects.empty())
        throw Error(what.str() + "; " + defects, "solvers::GeneralizedAlpha",
                    "give the parts named above mass (each says how)");
      throw Error(what.str(), "solvers::GeneralizedAlpha",
                  "check for a redundant constraint (e.g. two joints fixing the same freedom) or a "
                  "freedom with neither mass nor constraint (e.g. a beam without section inertia, "
                  "a massless body's rotation, a coordinate that no constraint involves)");
    }
    ++counters.factorizations;
    if (solver->substructured()) ++counters.substructured_factorizations;
    have_factorization = true;
  }

  /// What the model's elements say of freedoms they leave without mass (Element::mass_defect),
  /// each distinct message once, joined by "; "; empty when there are none.
  std::string mass_defects() const {
    std::vector<std::string> defects;
    for (int i = 0; i < model.element_count(); ++i) {
      std::string defect = model.element(i).mass_defect();
      if (!defect.empty() && std::find(defects.begin(), defects.end(), defect) == defects.end())
        defects.push_back(std::move(defect));
    }
    std::string joined;
    for (const std::string& defect : defects) joined += (joined.empty() ? "" : "; ") + defect;
    return joined;
  }

  // Initial conditions ---------------------------------------------------------------------------

  /// M v̇₀ + Bᵀλ₀ = −(f_qv + f_int − f_ext), B v̇₀ = −c(q₀, v₀, 0).
  /// The first call starts the run (and its energy balance); a later one restarts the method from
  /// consistent accelerations at the current state, the balance carrying on.
  void initialize() {
    if (!initialized && options.initial_assembly) {
      assemble_initial_state();
      consistent_accelerations(true);
    } else {
      consistent_accelerations(false);
    }
    if (!initialized && options.perturbed_starting_values) perturb_starting_values();
    if (options.iteration_matrix == IterationMatrix::frozen) assembly.freeze(input(t));
    evaluate(t, nullptr, 1.0);
    // The balance starts at t = 0 with the consistent accelerations.
    if (!initialized) initial_energy = mechanical_energy();
    // Finite inputs may still overflow in the energies (a mass of 1e300 kg at z = -1e300 m): the
    // balance would be NaN from the start (found by tests/input/fuzz_test.cpp).
    if (!std::isfinite(mechanical_energy()))
      throw Error("the mechanical energy at t = " + significant(t) + " is not finite (kinetic, strain or gravity "
                  "potential overflows)",
                  "solvers::GeneralizedAlpha::initialize",
                  "check the model's masses, positions, velocities and gravity for absurd magnitudes");
    last_work_force = work_force();
    initialized = true;
  }

  /// Assembles [M Bᵀ; B 0] at the current state (the residual then holds [r ; Φ]) and factorizes
  /// it with the Dirichlet conditions. It is not an iteration matrix. Its chart is the current
  /// state: with the last step's increment left in it, B came out as B T(hΔq), and the
  /// accelerations of initialize() during a run missed the joints by ½ h (Ω × v̇) (tests/dynamics/
  /// heavy_top_test.cpp, "initialize() during a run …").
  void factorize_mass_and_constraints() {
    increment.setZero();
    const MatrixCoefficients mass_only{.mass = 1.0, .damping = 0.0, .stiffness = 0.0};
    evaluate(t, &mass_only, 1.0, true);
    factorize(t);
    have_factorization = false;
  }

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

  /// v̇ and λ consistent with the equations at the current (q, v, t), and a = v̇: the method's
  /// start at t = 0, and its restart after an event changed the equations.
  /// M v̇ + Bᵀλ = −(f_qv + f_int − f_ext), B v̇ = −c(q, v, t).
  /// `factorized`: [M Bᵀ; B 0] is factorized at the current state and the residual holds
  /// [r ; Φ] with v̇ = 0, λ = 0 at the current v (what assemble_initial_state leaves).
  void consistent_accelerations(bool factorized) {
    acceleration.setZero();
    lambda.setZero();
    if (!factorized) factorize_mass_and_constraints();
    const int n = assembly.dof_count();
    solution = -assembly.residual();
    constraint_terms(solution, [&](const joints::Constraint& c, Eigen::Ref<Eigen::VectorXd> out) {
      c.acceleration_terms(model.state(), velocity, t, out);
      out = -out;
    });
    for (int dof : model.fixed_dofs()) solution(dof) = 0.0;
    solver->solve(solution);
    acceleration = solution.head(n);
    algorithmic_acceleration = acceleration;
    lambda = solution.tail(assembly.multiplier_count());
    if (!solution.allFinite())
      throw Error("the consistent accelerations are not finite at t = " + significant(t),
                  "solvers::GeneralizedAlpha",
                  "check the model's masses, loads and velocities for NaN or infinite values");
  }

  /// Perturbed starting values (DynamicOptions::perturbed_starting_values, docs/dynamics.md
  /// D6d). The method's smooth numerical solution has a_n = v̇(t_n) + Δ_α h v̈(t_n) + O(h²) and
  /// v_n = v(t_n) + c_v h² v̈(t_n) + O(h³), Δ_α = α_m − α_f, c_v = 1/6 − β − Δ_α/2 (the update
  /// relations of D3 expanded about an exact trajectory, derived there; cf. Arnold & Brüls 2007,
  /// Arnold, Brüls & Cardona 2015). Started from a₀ = v̇₀, v₀ = v(t₀), the index-3 method turns
  /// the O(h²) velocity offset along the constraints into an O(h) acceleration and multiplier
  /// transient that decays like (−ρ∞)ⁿ; started on the smooth solution it has none. v̈₀ is the
  /// difference quotient (v̇₁ − v̇₀)/h of the consistent accelerations at t₀ and at the end of one
  /// auxiliary step of h from the unperturbed values (its v₁ is O(h²) off, so v̈₀ is O(h) off and
  /// the starting values O(h²) and O(h³) off). The auxiliary step is undone; its Newton
  /// iterations and factorizations stay in the counters. A frame's rotation adds h²/12 Ω × Ω̇ to
  /// its velocity (from log(R(t)ᵀR(t + h)), D6d).
  void perturb_starting_values() {
    const double h = options.time_step;
    Snapshot initial;
    save(initial);
    // The step books its work against the forces at its start, which initialize() sets only
    // afterwards; the auxiliary step's work is discarded with it.
    last_work_force = Eigen::VectorXd::Zero(assembly.dof_count());
    if (!try_step(h, Predictor::extrapolated) && !try_step(h, Predictor::velocity_only))
      throw Error("the auxiliary step of the perturbed starting values did not converge at t = " +
                      significant(t) + " (h = " + significant(h) + "): " + last_failure,
                  "solvers::GeneralizedAlpha::initialize",
                  "reduce the time step, or switch DynamicOptions::perturbed_starting_values off");
    consistent_accelerations(false);
    const Eigen::VectorXd vdot_next = acceleration;
    restore(initial);
    const double delta_alpha = alpha.alpha_m - alpha.alpha_f;
    const Eigen::VectorXd vddot = (vdot_next - acceleration) / h;
    algorithmic_acceleration = acceleration + delta_alpha * h * vddot;
    // A frame's rotation also has log(R(t)ᵀR(t + h)) = … + h³/12 Ω × Ω̇ (D6d): its velocity the
    // extra h²/12 Ω × Ω̇.
    Eigen::VectorXd offset = h * h * (1.0 / 6.0 - alpha.beta - 0.5 * delta_alpha) * vddot;
    for (int b = 0; b < model.state().block_count(); ++b)
      if (model.state().is_frame(b)) {
        const int rotation = model.state().blocks[b].offset + 3;
        offset.segment<3>(rotation) +=
            h * h / 12.0 * velocity.segment<3>(rotation).cross(acceleration.segment<3>(rotation));
      }
    velocity += offset;
    for (int dof : model.fixed_dofs()) algorithmic_acceleration(dof) = velocity(dof) = 0.0;
  }

  /// Moves the positions onto Φ(q, t) = 0 by Gauss–Newton on the least change in the metric of
  /// M: with d the change so far, [M Bᵀ; B 0] [Δ; μ] = [−M d; −Φ] (docs/dynamics.md D6b), whose
  /// fixed point is the KKT point of min ½ dᵀM d subject to Φ(q ⊕ d) = 0. Leaves [M Bᵀ; B 0]
  /// factorized at the final state with the residual [r ; Φ] at v̇ = 0, λ = 0. Returns the
  /// iterations; `change` accumulates d. spar::Error (the state restored) when it does not converge
  /// in max_iterations; `what` names the occasion for it.
  int project_positions(Eigen::VectorXd& change, const std::string& what) {
    const int n = assembly.dof_count(), m = assembly.multiplier_count();
    const core::Configuration given = model.state();
    acceleration.setZero();
    lambda.setZero();
    change = Eigen::VectorXd::Zero(n);
    for (int iteration = 0;; ++iteration) {
      factorize_mass_and_constraints();
      if (constraint_norm() <= options.constraint_tolerance) return iteration;
      if (iteration == options.max_iterations || !assembly.residual().allFinite()) {
        const double residual = constraint_norm();
        model.state() = given;
        evaluate(t, nullptr, 1.0);
        throw Error("the configuration could not be projected onto the constraints " + what + " at t = " +
                        significant(t) + " (|Phi| = " + significant(residual) + " after " +
                        std::to_string(iteration) + " iterations)",
                    "solvers::GeneralizedAlpha",
                    "check that the constraints can hold together at this state (joint positions, axes and "
                    "drivers' angles at t = " + significant(t) + ")");
      }
      Eigen::VectorXd state = Eigen::VectorXd::Zero(assembly.size());
      state.head(n) = change;
      solution = assembly.pattern().matrix() * state;
      solution.head(n) = -solution.head(n);
      solution.tail(m) = -assembly.residual().tail(m);
      for (int dof : model.fixed_dofs()) solution(dof) = 0.0;
      solver->solve(solution);
      change += solution.head(n);
      model.state().apply_increment(solution.head(n));
    }
  }

  /// The least change of the velocities in the metric of M onto B v + Φ_t = 0:
  /// [M Bᵀ; B 0] [Δv; μ] = [0; −(B v + Φ_t)], with B v read off the factorized matrix
  /// (project_positions leaves it at the current state). Returns Δv; `violation` gets
  /// ‖B v + Φ_t‖∞ before.
  Eigen::VectorXd project_velocities(double& violation) {
    const int n = assembly.dof_count(), m = assembly.multiplier_count();
    Eigen::VectorXd state = Eigen::VectorXd::Zero(assembly.size());
    state.head(n) = velocity;
    solution = assembly.pattern().matrix() * state;
    solution.head(n).setZero();
    constraint_terms(solution, [&](const joints::Constraint& c, Eigen::Ref<Eigen::VectorXd> out) {
      Eigen::VectorXd phi_t(out.size());
      c.time_derivative(model.state(), t, phi_t);
      out = -(out + phi_t);
    });
    violation = m ? solution.tail(m).lpNorm<Eigen::Infinity>() : 0.0;
    solver->solve(solution);
    Eigen::VectorXd change = solution.head(n);
    for (int dof : model.fixed_dofs()) change(dof) = 0.0;
    velocity += change;
    return change;
  }

  /// After an event that changed the constraint equations (an end stop locking a slider), the
  /// state may violate the new constraints (the slider passed its stop within the step) and move
  /// against them. Projects the positions onto Φ = 0 and the velocities onto B v + Φ_t = 0 in the
  /// metric of the mass matrix — the perfectly plastic impact the event stands for, whose energy
  /// loss shows in the numerical dissipation — and restarts from consistent accelerations
  /// (docs/dynamics.md, "Events"). Without it the index-3 method meets the new constraint within
  /// one step and its velocity rings, gaining energy.
  void project_onto_constraints() {
    Eigen::VectorXd change;
    double violation = 0.0;
    project_positions(change, "after the event");
    project_velocities(violation);
    consistent_accelerations(false);
    evaluate(t, nullptr, 1.0);
    last_work_force = work_force();
  }

  /// The initial assembly (DynamicOptions::initial_assembly): positions, then velocities, onto
  /// the constraints by least change in the metric of M; the report in `assembly_report`. Leaves
  /// [M Bᵀ; B 0] factorized and the residual [r ; Φ] at v̇ = 0, λ = 0 at the assembled state.
  void assemble_initial_state() {
    InitialAssembly& report = assembly_report;
    report = InitialAssembly{};
    report.performed = true;
    const core::Configuration given = model.state();
    // Φ of the state as given, before any change.
    for (const auto& constraint : constraints) {
      Eigen::VectorXd phi(constraint->equation_count());
      constraint->value(model.state(), t, phi);
      if (phi.size()) report.constraint_residual = std::max(report.constraint_residual, phi.lpNorm<Eigen::Infinity>());
    }
    report.position_iterations = project_positions(report.position_change, "by the initial assembly");
    const Eigen::VectorXd& units = options.increment_units;
    for (int b = 0; b < model.state().block_count(); ++b) {
      const core::Block& block = model.state().blocks[b];
      for (int i = block.offset; i < block.offset + block.size; ++i) {
        const double change = std::abs(report.position_change(i)) / (units.size() ? units(i) : 1.0);
        if (change > report.largest_position_change) {
          report.largest_position_change = change;
          report.largest_position_change_block = b;
        }
      }
    }
    if (report.largest_position_change > options.initial_assembly_tolerance) {
      model.state() = given;
      evaluate(t, nullptr, 1.0);
      std::ostringstream what;
      what << "the initial assembly would move block " << report.largest_position_change_block << " by "
           << report.largest_position_change << " (|Phi| = " << report.constraint_residual
           << " as given), more than initial_assembly_tolerance = " << options.initial_assembly_tolerance;
      throw Error(what.str(), "solvers::GeneralizedAlpha::initialize",
                  "place the bodies and joints consistently (check the joints' points and the "
                  "drivers' angles at t = 0), or raise DynamicOptions::initial_assembly_tolerance");
    }
    const double tau = options.initial_velocity_stiffness_time;
    if (tau > 0.0) {  // [M + τ²K, Bᵀ; B 0] for the velocities, [M Bᵀ; B 0] again for v̇ below
      const MatrixCoefficients weighted{.mass = 1.0, .damping = 0.0, .stiffness = tau * tau};
      evaluate(t, &weighted, 1.0, true);
      factorize(t);
      have_factorization = false;
    }
    report.velocity_change = project_velocities(report.velocity_constraint_residual);
    report.largest_velocity_change =
        report.velocity_change.size() ? report.velocity_change.lpNorm<Eigen::Infinity>() : 0.0;
    if (tau > 0.0) {
      factorize_mass_and_constraints();
    } else if (report.largest_velocity_change > 0.0) {
      // The residual [r ; Φ] depends on v (gyroscopic and damping forces): evaluated again.
      evaluate(t, nullptr, 1.0);
    }
  }

  double mechanical_energy() const {
    const detail::SummedEnergies e = assembly.energies();
    return e.kinetic + e.strain + e.gravity;
  }

  /// The forces whose work the balance books, at the last evaluation: the external loads without
  /// a potential and the constraint forces −Bᵀλ (non-zero work for drivers only).
  Eigen::VectorXd work_force() const { return assembly.external_force() - assembly.constraint_force(); }

  // One step -------------------------------------------------------------------------------------

  /// The Newton starting point of a step. `extrapolated` is Brüls et al.'s (v̇_{n+1} = 0, which
  /// carries a_n into the step); `velocity_only` picks v̇_{n+1} so that the motion starts as
  /// q_n ⊕ h v_n, the better guess after an impulsive start (a concentrated moment on a section
  /// of tiny rotary inertia has a huge, short-lived initial acceleration). Both keep the update
  /// relations of eq. 49, so the converged step is the same.
  enum class Predictor { extrapolated, velocity_only };
  Predictor predictor = Predictor::extrapolated;

  /// A frame turned by π or more within one step has left the chart: exp(hΔφ) cannot tell hΔφ from
  /// hΔφ + 2πk (docs/model.md eq. M2). Such an iterate is refused, and the step cut back.
  bool inside_chart() {
    if (model.state().largest_rotation(increment) < std::numbers::pi) return true;
    ++counters.rejected_rotations;
    last_failure = "a frame turned by pi or more within the step";
    return false;
  }

  /// Tries one step of size h from the current state; on failure restores it and returns false.
  bool try_step(double h, Predictor predictor) {
    const double t_next = t + h;
    const double beta_prime = (1 - alpha.alpha_m) / (h * h * alpha.beta * (1 - alpha.alpha_f));
    const double gamma_prime = alpha.gamma / (h * alpha.beta);
    const MatrixCoefficients coefficients{.mass = 1.0, .damping = gamma_prime / beta_prime,
                                          .stiffness = 1.0 / beta_prime};
    const int n = assembly.dof_count();
    save(start);
    const Eigen::VectorXd& v0 = start.velocity;
    const Eigen::VectorXd& vdot0 = start.acceleration;
    const Eigen::VectorXd& a0 = start.algorithmic_acceleration;
    if (h != factorized_step) have_factorization = false;

    // Predictor (Brüls et al. 2012, Algorithm 1): a_{n+1} = base + (1 − α_f)/(1 − α_m) v̇_{n+1}.
    const Eigen::VectorXd a = (alpha.alpha_f * vdot0 - alpha.alpha_m * a0) / (1 - alpha.alpha_m);
    acceleration.setZero();
    if (predictor == Predictor::velocity_only)  // (½ − β) a_n + β a_{n+1} = 0
      acceleration = (-(0.5 - alpha.beta) / alpha.beta * a0 - a) * (1 - alpha.alpha_m) / (1 - alpha.alpha_f);
    const Eigen::VectorXd a_next = a + (1 - alpha.alpha_f) / (1 - alpha.alpha_m) * acceleration;
    velocity = v0 + h * (1 - alpha.gamma) * a0 + h * alpha.gamma * a_next;
    increment = h * v0 + h * h * (0.5 - alpha.beta) * a0 + h * h * alpha.beta * a_next;
    for (int dof : model.fixed_dofs()) velocity(dof) = increment(dof) = acceleration(dof) = 0.0;

    bool converged = false;
    if (inside_chart()) {
      model.state().assign_increment(start.q, increment);
      try {
        converged = newton(h, t_next, beta_prime, gamma_prime, coefficients, n);
      } catch (const EvaluationFailure&) {
        converged = false;
      }
    }
    if (converged) {
      algorithmic_acceleration = a + (1 - alpha.alpha_f) / (1 - alpha.alpha_m) * acceleration;
      // Trapezoidal work along the step's increment, W += ½ (f_n + f_{n+1}) · hΔq (eq. D8): the
      // increment is what the configuration did, so an unresolved velocity oscillation of a
      // stiff mode (ωh ≫ 1) books no spurious work.
      Eigen::VectorXd force_next = work_force();
      external_work += 0.5 * (last_work_force + force_next).dot(increment);
      last_work_force = std::move(force_next);
      t = t_next;
      return true;
    }
    // Not converged: restore the step's start.
    restore(start);
    refactor_requested = true;
    return false;
  }

  void save(Snapshot& s) const {
    s.q = model.state();
    s.velocity = velocity;
    s.acceleration = acceleration;
    s.algorithmic_acceleration = algorithmic_acceleration;
    s.lambda = lambda;
    s.work_force = last_work_force;
    s.t = t;
    s.external_work = external_work;
  }

  void restore(const Snapshot& s) {
    model.state() = s.q;
    velocity = s.velocity;
    acceleration = s.acceleration;
    algorithmic_acceleration = s.algorithmic_acceleration;
    lambda = s.lambda;
    last_work_force = s.work_force;
    t = s.t;
    external_work = s.external_work;
  }

  /// An element or joint could not be evaluated at an iterate (its spar::Error is kept in
  /// last_failure): the iteration has failed and the step is cut back.
  struct EvaluationFailure {};

  void guarded_evaluate(double time, const MatrixCoefficients* c, double residual_scale,
                        bool with_energies = true) {
    guarded([&] { evaluate(time, c, residual_scale, false, with_energies); });
  }

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

  /// The backward error to which a substructured solve refines a Newton increment (docs/dynamics.md
  /// D12): not round-off. The refinement gains in the increment's relative error what it shows in
  /// ω, so at 1e-9 an increment of a millimetre is within ~1e-12 m of the exact one, below every
  /// test of the iteration, and as accurate as KLU's LU of the whole saddle-point matrix
  /// (2e-9…6e-9, tests/solvers/linear_solver_test.cpp). On the truss unit's linear law the first
  /// solve leaves 1e-3…1e-5 (the couplings of kN multipliers that P leaves out) and each sweep gains
  /// ~1e-4: round-off took three sweeps, 1e-9 takes one or two.
  static constexpr double newton_refinement_target = 1e-9;

  /// The linear solver's analysis of the current pattern, with the model's substructures where
  /// every iteration factorizes (docs/dynamics.md D12): modified Newton solves ~100 times per
  /// factorization, and P's two back-substitutions and two products with A per solve cost more
  /// than the whole matrix's one (the truss's cosine law, 10 s: 2.5 against 1.8 s).
  void analyze() {
    const bool substructure = options.substructuring && options.iteration_matrix != IterationMatrix::modified;
    solver->set_substructures(substructure ? assembly.substructures() : std::vector<int>{});
    solver->set_refinement_target(newton_refinement_target);
    solver->analyze(assembly.pattern().matrix());
  }

  /// Newton iterations of one step from the predictor; true when converged.
  bool newton(double h, double t_next, double beta_prime, double gamma_prime,
              const MatrixCoefficients& coefficients, int n) {
    const int m = assembly.multiplier_count();
    double previous_norm = INFINITY, norm_squared = INFINITY;
    for (int iteration = 0;; ++iteration) {
      // Once the increment is below the tolerance the next evaluation is most likely the last:
      // it computes the residual only, and the matrix follows if the residual check fails.
      const bool expect_convergence = norm_squared <= options.tolerance;
      const bool need_matrix = options.iteration_matrix != IterationMatrix::modified ||
                               !have_factorization || refactor_requested;
      // With the dynamic residual untested (003's test), an iterate that may be the last needs
      // only Φ: the elements are evaluated when the test fails (docs/dynamics.md D4).
      const bool constraints_only = expect_convergence && !std::isfinite(options.residual_tolerance);
      if (constraints_only)
        guarded([&] { evaluate_constraints_and_loads(t_next); });
      else  // the energies only where the iterate may be accepted
        guarded_evaluate(t_next, need_matrix && !expect_convergence ? &coefficients : nullptr, beta_prime,
                         expect_convergence);
      if (!assembly.residual().allFinite()) {
        last_failure = "the residual is not finite";
        return false;
      }
      if (iteration > 0 && norm_squared <= options.tolerance &&
          constraint_norm() <= options.constraint_tolerance && dynamic_residual_small(beta_prime)) {
        last_iterations = iteration;
        return true;
      }
      if (iteration == options.max_iterations) {
        last_failure = "Newton did not converge in max_iterations";
        return false;
      }
      if (constraints_only)
        guarded_evaluate(t_next, need_matrix ? &coefficients : nullptr, beta_prime, false);
      else if (need_matrix && expect_convergence)
        guarded_evaluate(t_next, &coefficients, beta_prime);
      if (need_matrix) {
        if (options.iteration_matrix != IterationMatrix::frozen) ++counters.jtheta_evaluations;
        // A non-finite tangent at an iterate fails the iteration (the step is cut back), as a
        // non-finite residual does; it is no sign of a redundant constraint.
        const auto& matrix = assembly.pattern().matrix();
        if (!detail::all_finite(matrix.valuePtr(), matrix.nonZeros())) {
          last_failure = "the iteration matrix has a NaN or infinite entry";
          return false;
        }
        factorize(t_next);
        factorized_step = h;
        refactor_requested = false;
      }
      solution = -assembly.residual();
      for (int dof : model.fixed_dofs()) solution(dof) = 0.0;
      solver->solve(solution);
      ++counters.newton_iterations;
      if (!solution.allFinite()) {  // a failed iteration: the step is cut back
        last_failure = "the Newton increment is not finite";
        return false;
      }
      const auto dx = solution.head(n);
      const auto dlambda = solution.tail(m);
      increment += dx;
      velocity += gamma_prime * dx;
      acceleration += beta_prime * dx;
      lambda += beta_prime * dlambda;
      if (!inside_chart()) return false;
      model.state().assign_increment(start.q, increment);
      // 003 §5.1: D = [Δq, h²β Δλ].
      const double dlambda_norm = h * h * alpha.beta * beta_prime * dlambda.norm();
      norm_squared = increment_norm_squared(dx, dlambda_norm);
      const double norm = std::sqrt(norm_squared);
      if (options.iteration_matrix == IterationMatrix::modified &&
          norm > options.modified_newton_contraction * previous_norm)
        refactor_requested = true;
      previous_norm = norm;
    }
  }

  // The start of the user's step, restored when the whole step fails (buffers kept across steps).
  Snapshot step_start;

  /// One step of options.time_step, all or nothing: when it fails even after the cut-backs (or
  /// anything in it throws), state, velocities, accelerations, multipliers, time and energy
  /// balance are restored to the step's start, so no converged sub-step of it is left behind.
  void whole_step(double h) {
    save(step_start);
    const long steps0 = counters.steps;
    try {
      advance(h, 0);
    } catch (...) {
      restore(step_start);
      counters.steps = steps0;
      refactor_requested = true;
      evaluate(t, nullptr, 1.0);  // the energies and residual of the restored state
      throw;
    }
  }

  /// The smallest event distance of the constraints in the current state (+∞: no event ahead).
  double event_distance() const {
    double g = INFINITY;
    for (const auto& constraint : constraints) g = std::min(g, constraint->event_distance(model.state()));
    return g;
  }

  /// One user step of options.time_step (docs/dynamics.md D6c). When a constraint's event falls
  /// inside it (its event distance g goes from positive to below −event_tolerance), the step is
  /// replaced by steps that end just past the event, −event_tolerance ≤ g ≤ 0; the event is
  /// handled there and the rest of the user step follows. A lock that happens where the slider
  /// is, not a step's overshoot later, needs no projection of the state worth the name: an
  /// overshoot δ projected back onto the stop would stretch the stiff members it moves by δ.
  void step_with_events() {
    const double t_target = t + options.time_step;
    while (t_target - t > 1e-9 * options.time_step) {
      const double h = t_target - t, g0 = event_distance();
      whole_step(h);
      if (options.locate_events && g0 > 0.0 && event_distance() < -options.event_tolerance)
        locate_event(g0, h);
      handle_events();
    }
    t = t_target;  // not t + rounding: the user's steps land on multiples of h
  }

  /// After a step of length h from step_start that crossed an event (g0 > 0 before it, g1 after
  /// it below −event_tolerance): redone as one step from step_start that ends past the event by
  /// at most the tolerance, −event_tolerance ≤ g ≤ 0. The step's length is found by regula falsi
  /// with the Illinois modification (the end of the bracket kept twice has its g halved), which
  /// converges superlinearly on the smooth g(θh). Every try starts from step_start: keeping the
  /// tries that end short of the event would leave steps of nanoseconds near it, whose index-3
  /// multipliers (Φ's round-off over βh²) are meaningless. After 30 tries the shortest step past
  /// the event is taken as it is.
  void locate_event(double g0, double h) {
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

  void advance(double h, int depth) {
    // The predictor that converged last is tried first, the other one next.
    const Predictor other = (predictor == Predictor::extrapolated) ? Predictor::velocity_only
                                                                   : Predictor::extrapolated;
    if (try_step(h, predictor) || try_step(h, predictor = other)) {
      ++counters.steps;
      return;
    }
    if (depth >= options.max_cutbacks) {
      std::ostringstream what;
      what << "Newton did not converge at t = " << t + h << " (step " << counters.steps + 1
           << ", h = " << h << ") after " << depth << " halvings of the time step; last failure: "
           << last_failure;
      throw Error(what.str(), "solvers::GeneralizedAlpha",
                  "reduce the time step, raise max_iterations, or check the model: a diverging "
                  "Newton often means an unrealistic load or an inconsistent initial state");
    }
    ++counters.cutbacks;
    advance(h / 2, depth + 1);
    advance(h / 2, depth + 1);
  }

  // Structure changes ----------------------------------------------------------------------------

  /// Blocks or elements the user changed since the last step (Model::replace_element,
  /// add_element, replace_state with the same dofs) are taken in before the next step: an element
  /// evaluated through a stale pattern would add its rows to another element's dofs. A new number
  /// of dofs needs remap(P) first, which carries the state across.
  void take_structure_changes() {
    if (model.structure_version() == structure_version) return;
    if (model.dof_count() != assembly.dof_count())
      throw Error("the model now has " + std::to_string(model.dof_count()) + " dofs, the integrator's state " +
                      std::to_string(assembly.dof_count()),
                  "solvers::GeneralizedAlpha::step",
                  "after Model::replace_state, call remap(P) with P of (new dofs) x (old dofs)");
    rebuild(nullptr);
  }

  /// After a converged step: let the constraints switch at their events, and rebuild when they or
  /// the model changed the structure. After an event the method restarts from accelerations
  /// consistent with the new equations: the algorithmic acceleration a is an O(h)-shifted mean of
  /// v̇ under the old equations (a released mass would keep its pendulum's), and carrying it
  /// across makes every later step first-order accurate. When an event changed a constraint's
  /// equations the state is first projected onto them (project_onto_constraints).
  void handle_events() {
    bool changed = model.structure_version() != structure_version, event = false;
    bool equations_changed = false;
    for (auto& constraint : constraints) {
      const int before = constraint->equation_count();
      std::string description;
      if (constraint->update_structure(model.state(), velocity, t, description)) {
        changed = event = true;
        events.emplace_back(t, description);
      }
      equations_changed = equations_changed || constraint->equation_count() != before;
    }
    if (!changed) return;
    rebuild(nullptr);
    if (equations_changed) {
      project_onto_constraints();  // a new equation: onto it, then a consistent restart
    } else if (event) {
      consistent_accelerations(false);
      evaluate(t, nullptr, 1.0);
      last_work_force = work_force();
    }
  }

  /// Rebuilds the pattern and the symbolic factorization; carries v, v̇, a through P (if the dof
  /// layout changed) and the multipliers of constraints whose equation count is unchanged.
  void rebuild(const Eigen::MatrixXd* P) {
    std::vector<int> old_first, old_count;
    for (std::size_t ci = 0; ci < constraints.size(); ++ci) {
      old_first.push_back(assembly.first_multiplier(static_cast<int>(ci)));
      old_count.push_back(ci + 1 < constraints.size()
                              ? assembly.first_multiplier(static_cast<int>(ci + 1)) - old_first.back()
                              : assembly.multiplier_count() - old_first.back());
    }
    const Eigen::VectorXd old_lambda = lambda;
    assembly.rebuild();
    analyze();
    ++counters.pattern_builds;
    structure_version = model.structure_version();
    have_factorization = false;
    if (P) {
      velocity = *P * velocity;
      acceleration = *P * acceleration;
      algorithmic_acceleration = *P * algorithmic_acceleration;
    }
    lambda = Eigen::VectorXd::Zero(assembly.multiplier_count());
    for (std::size_t ci = 0; ci < constraints.size(); ++ci)
      if (constraints[ci]->equation_count() == old_count[ci])
        lambda.segment(assembly.first_multiplier(static_cast<int>(ci)), old_count[ci]) =
            old_lambda.segment(old_first[ci], old_count[ci]);
    increment = Eigen::VectorXd::Zero(assembly.dof_count());
    solution = Eigen::VectorXd::Zero(assembly.size());
    if (options.iteration_matrix == IterationMatrix::frozen) assembly.freeze(input(t));
    // The balance carries on across the change: a jump of the energy at the event shows in the
    // numerical dissipation, where a user sees it.
    evaluate(t, nullptr, 1.0);
    last_work_force = work_force();
  }
};

namespace {

/// The model, once Model::check_consistent has passed it (for the constructor's initializer).
core::Model& consistent(core::Model& model, const char* where) {
  model.check_consistent(where);
  return model;
}

}  // namespace

GeneralizedAlpha::GeneralizedAlpha(core::Model& model, ConstraintList constraints,
                                   const DynamicOptions& options)
    : impl_(std::make_unique<Implementation>(consistent(model, "solvers::GeneralizedAlpha"), std::move(constraints),
                                             options)) {}

GeneralizedAlpha::~GeneralizedAlpha() = default;

namespace {

void check_velocity_block(const core::Model& model, int block, bool initialized, const char* where) {
  if (block < 0 || block >= model.block_count())
    throw Error("block " + std::to_string(block) + " does not exist", where, "give a block of the model");
  if (initialized)
    throw Error("initial velocities must be set before the first step", where,
                "call set_velocity before initialize() and step()");
}

}  // namespace

void GeneralizedAlpha::set_velocity(int node, const Eigen::Vector3d& linear, const Eigen::Vector3d& angular) {
  const char* where = "solvers::GeneralizedAlpha::set_velocity";
  check_velocity_block(impl_->model, node, impl_->initialized, where);
  if (!impl_->model.state().is_frame(node))
    throw Error("block " + std::to_string(node) + " is a vector block", where,
                "give a vector block's velocity as one Eigen::VectorXd");
  if (!linear.allFinite() || !angular.allFinite())
    throw Error("the velocity has a NaN or infinite entry", where, "give finite velocities");
  const int offset = impl_->model.state().blocks[node].offset;
  impl_->velocity.segment<3>(offset) = linear;
  impl_->velocity.segment<3>(offset + 3) = angular;
}

void GeneralizedAlpha::set_velocity(int block, const Eigen::VectorXd& velocity) {
  const char* where = "solvers::GeneralizedAlpha::set_velocity";
  check_velocity_block(impl_->model, block, impl_->initialized, where);
  const core::Block& b = impl_->model.state().blocks[block];
  if (velocity.size() != b.size || !velocity.allFinite())
    throw Error("block " + std::to_string(block) + " takes " + std::to_string(b.size) +
                    " finite velocity entries, got " + std::to_string(velocity.size()),
                where, "give one finite entry per increment of the block (frames: xdot, Omega)");
  impl_->velocity.segment(b.offset, b.size) = velocity;
}

void GeneralizedAlpha::initialize() {
  const char* where = "solvers::GeneralizedAlpha::initialize";
  if (impl_->just_initialized)
    throw Error("initialize() was already called at t = " + significant(impl_->t) + ", and no step or remap followed",
                where, "call initialize() once before the first step; again only to restart after steps or a remap");
  impl_->model.check_consistent(where);
  const auto start = std::chrono::steady_clock::now();
  impl_->initialize();
  impl_->just_initialized = true;
  impl_->counters.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void GeneralizedAlpha::step() {
  impl_->model.check_consistent("solvers::GeneralizedAlpha::step");
  impl_->take_structure_changes();
  if (!impl_->initialized) initialize();
  const auto start = std::chrono::steady_clock::now();
  impl_->step_with_events();
  impl_->just_initialized = false;
  impl_->counters.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void GeneralizedAlpha::remap(const Eigen::MatrixXd& P, const Eigen::VectorXd& increment_units) {
  const int new_dofs = impl_->model.dof_count();
  const char* where = "solvers::GeneralizedAlpha::remap";
  impl_->model.check_consistent(where);
  if (P.rows() != new_dofs || P.cols() != impl_->assembly.dof_count() || !P.allFinite())
    throw Error("the map is " + std::to_string(P.rows()) + "x" + std::to_string(P.cols()) +
                    ", expected " + std::to_string(new_dofs) + "x" +
                    std::to_string(impl_->assembly.dof_count()) + " with finite entries",
                where, "give P as (new dofs) x (old dofs), after Model::replace_state");
  // The old units belong to the old layout: a run with units needs the new layout's.
  if (impl_->options.increment_units.size() != 0 || increment_units.size() != 0) {
    if (increment_units.size() != new_dofs || !(increment_units.array() > 0.0).all() || !increment_units.allFinite())
      throw Error("increment_units for the new layout has " + std::to_string(increment_units.size()) + " entries for " +
                      std::to_string(new_dofs) + " dofs, or an entry that is not positive and finite",
                  where, "give one positive unit per dof of the new layout (the run uses increment_units)");
    impl_->options.increment_units = increment_units;
  }
  impl_->rebuild(&P);
  impl_->just_initialized = false;
}

const std::vector<std::pair<double, std::string>>& GeneralizedAlpha::events() const {
  return impl_->events;
}

double GeneralizedAlpha::time() const { return impl_->t; }
const core::Configuration& GeneralizedAlpha::configuration() const { return impl_->model.state(); }
const Eigen::VectorXd& GeneralizedAlpha::velocity() const { return impl_->velocity; }
const Eigen::VectorXd& GeneralizedAlpha::acceleration() const { return impl_->acceleration; }
const Eigen::VectorXd& GeneralizedAlpha::multipliers() const { return impl_->lambda; }
const DynamicCounters& GeneralizedAlpha::counters() const { return impl_->counters; }
int GeneralizedAlpha::constraint_count() const { return static_cast<int>(impl_->constraints.size()); }

const joints::Constraint& GeneralizedAlpha::constraint(int c) const {
  if (c < 0 || c >= constraint_count())
    throw Error("constraint " + std::to_string(c) + " does not exist (" + std::to_string(constraint_count()) +
                    " constraints)",
                "solvers::GeneralizedAlpha::constraint", "give an index into the constructor's constraint list");
  return *impl_->constraints[c];
}

Eigen::VectorXd GeneralizedAlpha::multipliers(int c) const {
  const int m = constraint(c).equation_count();
  return impl_->lambda.segment(impl_->assembly.first_multiplier(c), m);
}
int GeneralizedAlpha::multiplier_count() const { return impl_->assembly.multiplier_count(); }
int GeneralizedAlpha::last_step_iterations() const { return impl_->last_iterations; }

const InitialAssembly& GeneralizedAlpha::initial_assembly() const { return impl_->assembly_report; }

double GeneralizedAlpha::constraint_residual() const {
  double norm = 0.0;
  for (const auto& constraint : impl_->constraints) {
    Eigen::VectorXd phi(constraint->equation_count());
    constraint->value(impl_->model.state(), impl_->t, phi);
    norm = std::max(norm, phi.lpNorm<Eigen::Infinity>());
  }
  return norm;
}

Energies GeneralizedAlpha::energies() const {
  // The last evaluation of every step (and of initialize) is at the accepted state; when it
  // evaluated the constraints and loads only, the elements' energies are computed now.
  if (impl_->energies_stale) impl_->evaluate_energies();
  const detail::SummedEnergies e = impl_->assembly.energies();
  Energies energies{.kinetic = e.kinetic, .strain = e.strain, .gravity = e.gravity,
                    .external_work = impl_->external_work};
  energies.numerical_dissipation =
      energies.external_work - (energies.total() - impl_->initial_energy);
  return energies;
}

}  // namespace spar::solvers
