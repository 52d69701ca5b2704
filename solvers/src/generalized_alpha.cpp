// GeneralizedAlpha's public methods (docs/dynamics.md): each checks its input and hands the work
// to the implementation (integrator.hpp, which lists the files of the integrator's jobs).
#include <spar/solvers/generalized_alpha.hpp>

#include <spar/error.hpp>

#include "integrator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
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

/// The model, once Model::check_consistent has passed it (for the constructor's initializer).
core::Model& consistent(core::Model& model, const char* where) {
  model.check_consistent(where);
  return model;
}

void check_velocity_block(const core::Model& model, int block, bool initialized, const char* where) {
  if (block < 0 || block >= model.block_count())
    throw Error("block " + std::to_string(block) + " does not exist", where, "give a block of the model");
  if (initialized)
    throw Error("initial velocities must be set before the first step", where,
                "call set_velocity before initialize() and step()");
}

/// Runs `job` and adds its wall-clock time to the counters (when it returns).
template <class Job>
void timed(DynamicCounters& counters, const Job& job) {
  const auto start = std::chrono::steady_clock::now();
  job();
  counters.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

GeneralizedAlpha::GeneralizedAlpha(core::Model& model, ConstraintList constraints, const DynamicOptions& options)
    : impl_(std::make_unique<Implementation>(consistent(model, "solvers::GeneralizedAlpha"), std::move(constraints),
                                             options)) {}

GeneralizedAlpha::~GeneralizedAlpha() = default;

void GeneralizedAlpha::set_velocity(int node, const Eigen::Vector3d& linear, const Eigen::Vector3d& angular) {
  const char* where = "solvers::GeneralizedAlpha::set_velocity";
  check_velocity_block(impl_->model, node, impl_->initialized, where);
  if (!impl_->model.state().is_frame(node))
    throw Error("block " + std::to_string(node) + " is a vector block", where,
                "give a vector block's velocity as one Eigen::VectorXd");
  if (!linear.allFinite() || !angular.allFinite())
    throw Error("the velocity has a NaN or infinite entry", where, "give finite velocities");
  const int offset = impl_->model.state().blocks[node].offset;
  impl_->state.velocity.segment<3>(offset) = linear;
  impl_->state.velocity.segment<3>(offset + 3) = angular;
}

void GeneralizedAlpha::set_velocity(int block, const Eigen::VectorXd& velocity) {
  const char* where = "solvers::GeneralizedAlpha::set_velocity";
  check_velocity_block(impl_->model, block, impl_->initialized, where);
  const core::Block& b = impl_->model.state().blocks[block];
  if (velocity.size() != b.size || !velocity.allFinite())
    throw Error("block " + std::to_string(block) + " takes " + std::to_string(b.size) +
                    " finite velocity entries, got " + std::to_string(velocity.size()),
                where, "give one finite entry per increment of the block (frames: xdot, Omega)");
  impl_->state.velocity.segment(b.offset, b.size) = velocity;
}

void GeneralizedAlpha::initialize() {
  const char* where = "solvers::GeneralizedAlpha::initialize";
  if (impl_->just_initialized)
    throw Error("initialize() was already called at t = " + significant(impl_->state.time) +
                    ", and no step or remap followed",
                where, "call initialize() once before the first step; again only to restart after steps or a remap");
  impl_->model.check_consistent(where);
  impl_->on_model_state([&] { timed(impl_->counters, [&] { impl_->initialize(); }); });
  impl_->just_initialized = true;
}

void GeneralizedAlpha::step() {
  impl_->model.check_consistent("solvers::GeneralizedAlpha::step");
  impl_->on_model_state([&] {
    impl_->take_structure_changes();
    if (!impl_->initialized) {  // what initialize() does, the model checked above
      timed(impl_->counters, [&] { impl_->initialize(); });
      impl_->just_initialized = true;
    }
    timed(impl_->counters, [&] { impl_->step_with_events(); });
  });
  impl_->just_initialized = false;
  if (std::isfinite(impl_->options.energy_alarm) && impl_->energy_check_due()) impl_->watch_energy(energies());
}

const std::optional<EnergyAlarm>& GeneralizedAlpha::energy_alarm() const { return impl_->alarm; }

void GeneralizedAlpha::remap(const Eigen::MatrixXd& P, const Eigen::VectorXd& increment_units) {
  const int new_dofs = impl_->model.dof_count();
  const char* where = "solvers::GeneralizedAlpha::remap";
  impl_->model.check_consistent(where);
  if (P.rows() != new_dofs || P.cols() != impl_->assembly.dof_count() || !P.allFinite())
    throw Error("the map is " + std::to_string(P.rows()) + "x" + std::to_string(P.cols()) + ", expected " +
                    std::to_string(new_dofs) + "x" + std::to_string(impl_->assembly.dof_count()) +
                    " with finite entries",
                where, "give P as (new dofs) x (old dofs), after Model::replace_state");
  // The old units belong to the old layout: a run with units needs the new layout's.
  if (impl_->options.increment_units.size() != 0 || increment_units.size() != 0) {
    if (increment_units.size() != new_dofs || !(increment_units.array() > 0.0).all() || !increment_units.allFinite())
      throw Error("increment_units for the new layout has " + std::to_string(increment_units.size()) + " entries for " +
                      std::to_string(new_dofs) + " dofs, or an entry that is not positive and finite",
                  where, "give one positive unit per dof of the new layout (the run uses increment_units)");
    impl_->options.increment_units = increment_units;
  }
  impl_->on_model_state([&] { impl_->rebuild(&P); });
  impl_->just_initialized = false;
}

const std::vector<std::pair<double, std::string>>& GeneralizedAlpha::events() const { return impl_->events; }

double GeneralizedAlpha::time() const { return impl_->state.time; }
const core::Configuration& GeneralizedAlpha::configuration() const { return impl_->model.state(); }
const Eigen::VectorXd& GeneralizedAlpha::velocity() const { return impl_->state.velocity; }
const Eigen::VectorXd& GeneralizedAlpha::acceleration() const { return impl_->state.acceleration; }
const Eigen::VectorXd& GeneralizedAlpha::multipliers() const { return impl_->state.multipliers; }
const DynamicState& GeneralizedAlpha::state() const { return impl_->state; }
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
  return impl_->state.multipliers.segment(impl_->assembly.first_multiplier(c), m);
}
int GeneralizedAlpha::multiplier_count() const { return impl_->assembly.multiplier_count(); }
int GeneralizedAlpha::last_step_iterations() const { return impl_->last_iterations; }

const InitialAssembly& GeneralizedAlpha::initial_assembly() const { return impl_->assembly_report; }

double GeneralizedAlpha::constraint_residual() const {
  double norm = 0.0;
  for (const auto& constraint : impl_->constraints) {
    Eigen::VectorXd phi(constraint->equation_count());
    constraint->value(impl_->model.state(), impl_->state.time, phi);
    norm = std::max(norm, phi.lpNorm<Eigen::Infinity>());
  }
  return norm;
}

Energies GeneralizedAlpha::energies() const {
  // The last evaluation of every step (and of initialize) is at the accepted state; when it
  // evaluated the constraints and loads only, the elements' energies are computed now, at the
  // model's configuration.
  if (impl_->energies_stale) {
    impl_->state.q = impl_->model.state();
    impl_->evaluate_energies();
  }
  return impl_->balance.energies(impl_->assembly);
}

}  // namespace spar::solvers
