// The generalized-α integrator's options and evaluations (docs/dynamics.md D3–D4): the residual
// [r/β′ ; Φ] and the iteration matrix at the current state, and the tests Newton applies to them.
#include "integrator.hpp"

#include "round_off.hpp"

#include <cmath>
#include <string>

namespace spar::solvers {

namespace {

std::vector<joints::Constraint*> pointers(const ConstraintList& constraints) {
  std::vector<joints::Constraint*> raw;
  for (const auto& constraint : constraints) raw.push_back(constraint.get());
  return raw;
}

}  // namespace

GeneralizedAlpha::Implementation::Implementation(core::Model& m, ConstraintList c, const DynamicOptions& o)
    : model(m),
      constraints(std::move(c)),
      options(o),
      alpha(validated_parameters(o)),
      assembly(m, pointers(constraints), o.assembly),
      matrix(options, counters),
      structure_version(m.structure_version()) {
  matrix.analyze(assembly);
  const int n = assembly.dof_count();
  state.q = model.state();
  state.velocity = state.acceleration = state.algorithmic_acceleration = increment = Eigen::VectorXd::Zero(n);
  state.multipliers = Eigen::VectorXd::Zero(assembly.multiplier_count());
  solution = Eigen::VectorXd::Zero(assembly.size());
  check_units();
}

GeneralizedAlphaParameters GeneralizedAlpha::Implementation::validated_parameters(const DynamicOptions& options) {
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
  if (!(options.energy_alarm > 0.0))
    throw Error("energy_alarm = " + significant(options.energy_alarm) + " must be positive (+inf: no alarm)", where,
                "give the fraction of the run's energy scale the integrator may create before it warns, e.g. 0.05");
  if (!(options.modified_newton_contraction > 0.0 && options.modified_newton_contraction <= 1.0))
    throw Error("modified_newton_contraction = " + significant(options.modified_newton_contraction) +
                    " is outside (0, 1]",
                where, "give the contraction factor that triggers a refactorization, e.g. 0.5");
  return GeneralizedAlphaParameters::from_spectral_radius(options.spectral_radius);
}

void GeneralizedAlpha::Implementation::check_units() const {
  const Eigen::VectorXd& units = options.increment_units;
  if (units.size() == 0) return;
  if (units.size() != assembly.dof_count() || !(units.array() > 0.0).all() || !units.allFinite())
    throw Error("increment_units has " + std::to_string(units.size()) + " entries for " +
                    std::to_string(assembly.dof_count()) + " dofs, or a non-positive entry",
                "solvers::GeneralizedAlpha", "give one positive unit per dof, or none");
}

core::ElementInput GeneralizedAlpha::Implementation::input(double time) const {
  core::ElementInput in;
  in.q = &state.q;
  in.velocity = &state.velocity;
  in.acceleration = &state.acceleration;
  in.time = time;
  in.load_factor = 1.0;
  in.gravity = model.gravity();
  return in;
}

void GeneralizedAlpha::Implementation::evaluate(double time, const detail::MatrixCoefficients* c,
                                                double residual_scale, bool exact_mass, bool with_energies) {
  ++counters.residual_evaluations;
  const bool frozen = matrix.frozen() && initialized && !exact_mass;
  const bool energies = !c && with_energies;
  assembly.evaluate(input(time), state.multipliers, c, detail::Chart::local_increment, increment, frozen, energies);
  energies_stale = !energies;
  auto dynamic = assembly.residual().head(assembly.dof_count());
  for (int dof : model.fixed_dofs()) dynamic(dof) = 0.0;
  dynamic /= residual_scale;
}

void GeneralizedAlpha::Implementation::evaluate_constraints_and_loads(double time) {
  assembly.evaluate_constraints_and_loads(input(time), state.multipliers, increment);
  energies_stale = true;
}

void GeneralizedAlpha::Implementation::evaluate_energies() {
  assembly.evaluate_energies(input(state.time));
  energies_stale = false;
}

bool GeneralizedAlpha::Implementation::dynamic_residual_small(double residual_scale) const {
  if (!std::isfinite(options.residual_tolerance)) return true;  // the test is off
  const double floor = detail::residual_round_off_floor(assembly.pattern().matrix(), state.q);
  const Eigen::VectorXd& r = assembly.residual();
  for (int i = 0; i < assembly.dof_count(); ++i)
    if (std::abs(r(i)) > options.residual_tolerance * assembly.scale()(i) / residual_scale + floor) return false;
  return true;
}

double GeneralizedAlpha::Implementation::constraint_norm() const {
  const int m = assembly.multiplier_count();
  return m ? assembly.residual().tail(m).lpNorm<Eigen::Infinity>() : 0.0;
}

double GeneralizedAlpha::Implementation::increment_norm_squared(const Eigen::Ref<const Eigen::VectorXd>& dx,
                                                                double dlambda_norm) const {
  const double dq = options.increment_units.size() ? dx.cwiseQuotient(options.increment_units).squaredNorm()
                                                   : dx.squaredNorm();
  return dq + dlambda_norm * dlambda_norm;
}

}  // namespace spar::solvers
