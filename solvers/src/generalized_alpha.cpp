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

#include "round_off.hpp"

#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

namespace spar::solvers {

using core::dofs_per_node;

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
    throw Error("spectral radius rho_infinity = " + std::to_string(rho) + " is outside [0, 1]",
                "solvers::GeneralizedAlphaParameters", "give 0 <= rho_infinity <= 1");
  GeneralizedAlphaParameters p;
  p.alpha_m = (2 * rho - 1) / (rho + 1);
  p.alpha_f = rho / (rho + 1);
  p.gamma = 0.5 + p.alpha_f - p.alpha_m;
  p.beta = 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5);
  return p;
}

namespace {

/// Coefficients of one assembly of the iteration matrix: c_M M + c_C C + c_K (K + K_λ) T.
struct MatrixCoefficients {
  double mass = 1.0, damping = 0.0, stiffness = 0.0;
};

std::vector<int> dofs_of(const std::vector<int>& nodes) {
  std::vector<int> dofs;
  for (int node : nodes)
    for (int i = 0; i < dofs_per_node; ++i) dofs.push_back(dofs_per_node * node + i);
  return dofs;
}

/// Right-multiplies the rotational columns of a node-blocked matrix by T(ΔΘ_node) (Brüls et al.:
/// K T(h Δq)), row by row so that nothing is allocated.
void apply_increment_tangent(const std::vector<int>& nodes, const Eigen::VectorXd& increment,
                             Eigen::Ref<Eigen::MatrixXd> K) {
  for (std::size_t I = 0; I < nodes.size(); ++I) {
    const Eigen::Vector3d theta = increment.segment<3>(dofs_per_node * nodes[I] + 3);
    if (theta.squaredNorm() == 0.0) continue;
    const Eigen::Matrix3d T = lie::tangent(theta);
    const Eigen::Index column = dofs_per_node * static_cast<Eigen::Index>(I) + 3;
    for (Eigen::Index row = 0; row < K.rows(); ++row) {
      const Eigen::RowVector3d entries = K.block<1, 3>(row, column);
      K.block<1, 3>(row, column) = entries * T;
    }
  }
}

}  // namespace

struct GeneralizedAlpha::Implementation {
  /// Work of one model block (beam element, rigid body, load).
  struct BlockWork {
    core::NodalContribution internal;
    core::InertiaContribution inertia;
    Eigen::VectorXd residual;  // its part of M v̇ + f_gyr + f_int − f_ext
    std::vector<int> nodes;
    Eigen::VectorXd node_acceleration;  // scratch
  };
  /// The rotational blocks of a model block at t = 0 (frozen strategy): mass, gyroscopic and
  /// stiffness parts kept apart so they combine with the current h.
  struct FrozenBlock {
    Eigen::MatrixXd mass, damping, stiffness;
  };
  struct ConstraintWork {
    std::vector<int> nodes;
    int first_multiplier = 0;
    Eigen::VectorXd value;
    Eigen::MatrixXd jacobian;
    Eigen::VectorXd force;  // Bᵀλ (scratch)
  };

  core::Model& model;
  ConstraintList constraints;
  DynamicOptions options;
  GeneralizedAlphaParameters alpha;
  int dof_count = 0, multiplier_count = 0;
  std::vector<core::ModelBlock> model_blocks;
  std::vector<BlockWork> blocks;
  std::vector<FrozenBlock> frozen;
  std::vector<ConstraintWork> constraint_work;
  std::unique_ptr<core::SparsePattern> pattern;
  std::unique_ptr<LinearSolver> solver;
  std::vector<int> fixed_dofs;
  Eigen::VectorXd gravity;

  double t = 0.0;
  Eigen::VectorXd velocity, acceleration, algorithmic_acceleration, lambda;
  bool initialized = false;
  // Newton state of the current step.
  core::Configuration start;
  Eigen::VectorXd increment, residual, solution, scale;
  bool have_factorization = false, refactor_requested = false;
  double factorized_step = 0.0;
  int last_iterations = 0;
  DynamicCounters counters;

  Implementation(core::Model& m, ConstraintList c, const DynamicOptions& o)
      : model(m), constraints(std::move(c)), options(o) {
    validate_options();
    alpha = GeneralizedAlphaParameters::from_spectral_radius(options.spectral_radius);
    dof_count = model.dof_count();
    model_blocks = model.blocks();
    blocks.resize(model_blocks.size());
    std::vector<core::PatternBlock> pattern_blocks = model.pattern_blocks();
    for (auto& constraint : constraints) {
      if (!constraint) throw Error("null constraint", "solvers::GeneralizedAlpha", "pass joints");
      ConstraintWork work;
      work.nodes = constraint->nodes();
      for (int node : work.nodes)
        if (node < 0 || node >= model.node_count())
          throw Error("a constraint refers to node " + std::to_string(node) + ", which the model does not have",
                      "solvers::GeneralizedAlpha", "build joints on the model they constrain");
      work.first_multiplier = multiplier_count;
      multiplier_count += constraint->equation_count();
      // One square block per constraint over its node dofs and its multipliers.
      std::vector<int> dofs = dofs_of(work.nodes);
      for (int i = 0; i < constraint->equation_count(); ++i) dofs.push_back(dof_count + work.first_multiplier + i);
      pattern_blocks.push_back(core::PatternBlock::element(dofs));
      constraint_work.push_back(std::move(work));
    }
    pattern = std::make_unique<core::SparsePattern>(dof_count + multiplier_count, pattern_blocks);
    solver = make_linear_solver(options.linear_solver);
    solver->analyze(pattern->matrix());
    fixed_dofs = model.fixed_dofs();
    gravity = model.gravity_force();
    velocity = Eigen::VectorXd::Zero(dof_count);
    acceleration = algorithmic_acceleration = Eigen::VectorXd::Zero(dof_count);
    lambda = Eigen::VectorXd::Zero(multiplier_count);
    increment = Eigen::VectorXd::Zero(dof_count);
    residual = solution = Eigen::VectorXd::Zero(dof_count + multiplier_count);
  }

  void validate_options() const {
    const char* where = "solvers::GeneralizedAlpha";
    if (!(options.time_step > 0.0) || !std::isfinite(options.time_step))
      throw Error("time step must be positive", where, "give DynamicOptions::time_step > 0");
    if (!(options.tolerance > 0.0) || options.max_iterations < 1 || options.max_cutbacks < 0)
      throw Error("tolerance must be positive, max_iterations >= 1, max_cutbacks >= 0", where,
                  "fix the DynamicOptions");
  }

  // Evaluation -----------------------------------------------------------------------------------

  /// Fills blocks[id] (and K when given) at the model's current state, velocity, acceleration.
  void compute_model_block(int id, double time, const MatrixCoefficients& c, Eigen::MatrixXd* K) {
    const core::ModelBlock& block = model_blocks[id];
    BlockWork& w = blocks[id];
    const core::Configuration& q = model.state();
    const bool with_matrix = (K != nullptr);
    const bool frozen_now = with_matrix && options.iteration_matrix == IterationMatrix::frozen &&
                            frozen.size() == model_blocks.size();
    // Which parts this block has (its buffers keep their capacity from one call to the next).
    bool has_internal = false, has_tangent = false, has_inertia = false;
    switch (block.kind) {
      case core::ModelBlock::Kind::beam_element:
        has_tangent = with_matrix && c.stiffness != 0.0;
        core::beam_element_contribution(model, block.index, block.element, q, has_tangent, w.internal);
        core::beam_element_inertia(model.beam(block.index), block.element, velocity, w.inertia);
        has_internal = has_inertia = true;
        w.nodes = w.internal.nodes;
        break;
      case core::ModelBlock::Kind::rigid_body:
        core::rigid_body_inertia(model.rigid_body(block.index), velocity, w.inertia);
        has_inertia = true;
        w.nodes = w.inertia.nodes;
        break;
      case core::ModelBlock::Kind::load:
        core::load_contribution(model, model.loads()[block.index], q,
                                model.load_factor(block.index, time), with_matrix, w.internal,
                                block.element);
        w.internal.force = -w.internal.force;  // an external force enters the residual negatively
        has_internal = true;
        has_tangent = with_matrix && w.internal.tangent.size() > 0;
        if (has_tangent) w.internal.tangent = -w.internal.tangent;
        w.nodes = w.internal.nodes;
        break;
    }
    const int n = dofs_per_node * static_cast<int>(w.nodes.size());
    w.residual.setZero(n);
    if (has_internal) w.residual += w.internal.force;
    w.node_acceleration.resize(n);
    for (std::size_t I = 0; I < w.nodes.size(); ++I)
      w.node_acceleration.segment<dofs_per_node>(dofs_per_node * I) =
          acceleration.segment<dofs_per_node>(dofs_per_node * w.nodes[I]);
    if (has_inertia) {
      w.residual.noalias() += w.inertia.mass * w.node_acceleration;
      w.residual += w.inertia.gyroscopic;
    }
    if (!with_matrix) return;

    K->setZero(n, n);
    if (has_inertia) *K += c.mass * w.inertia.mass + c.damping * w.inertia.gyroscopic_tangent;
    if (has_tangent && c.stiffness != 0.0) {
      apply_increment_tangent(w.nodes, increment, w.internal.tangent);
      *K += c.stiffness * w.internal.tangent;
    }
    if (frozen_now) {
      // 003 §5.1: the rotation–rotation blocks J_θ stay those of t = 0.
      const FrozenBlock& f = frozen[id];
      for (std::size_t I = 0; I < w.nodes.size(); ++I)
        for (std::size_t J = 0; J < w.nodes.size(); ++J) {
          auto block_of = [&](const Eigen::MatrixXd& A) {
            return A.size() > 0 ? Eigen::Matrix3d(A.block<3, 3>(6 * I + 3, 6 * J + 3)) : Eigen::Matrix3d::Zero();
          };
          K->block<3, 3>(6 * I + 3, 6 * J + 3) = c.mass * block_of(f.mass) +
                                                  c.damping * block_of(f.damping) +
                                                  c.stiffness * block_of(f.stiffness);
        }
    }
  }

  /// Fills constraint_work[ci] and, when given, the constraint's square block
  /// [c_K K_λ(λ) T, Bᵀ; B T, 0] over (its node dofs, its multipliers).
  void compute_constraint_block(int ci, double time, const MatrixCoefficients& c, Eigen::MatrixXd* K) {
    const joints::Constraint& constraint = *constraints[ci];
    ConstraintWork& w = constraint_work[ci];
    const int m = constraint.equation_count();
    const int n = dofs_per_node * static_cast<int>(w.nodes.size());
    const core::Configuration& q = model.state();
    w.value.resize(m);
    w.jacobian.resize(m, n);
    constraint.value(q, time, w.value);
    constraint.jacobian(q, time, w.jacobian);
    if (!K) return;
    K->setZero(n + m, n + m);
    if (c.stiffness != 0.0) {
      constraint.multiplier_tangent(q, time, lambda.segment(w.first_multiplier, m), K->topLeftCorner(n, n));
      K->topLeftCorner(n, n) *= c.stiffness;
    }
    K->topRightCorner(n, m) = w.jacobian.transpose();
    K->bottomLeftCorner(m, n) = w.jacobian;
    // Brüls et al.: the columns of the unknowns carry T(h Δq): (c_K K_λ) T and B T.
    apply_increment_tangent(w.nodes, increment, K->leftCols(n));
  }

  /// Evaluates the scaled residual [r/β′ ; Φ] at the current state (and assembles the iteration
  /// matrix when `c` is given); `residual_scale` divides the dynamic rows.
  void evaluate(double time, const MatrixCoefficients* c, double residual_scale) {
    ++counters.residual_evaluations;
    const int model_count = static_cast<int>(model_blocks.size());
    const int total = model_count + static_cast<int>(constraints.size());
    if (c) {
      pattern->assemble(
          [&](int id, Eigen::MatrixXd& K) {
            if (id < model_count)
              compute_model_block(id, time, *c, &K);
            else
              compute_constraint_block(id - model_count, time, *c, &K);
          },
          options.assembly);
    } else {
      const MatrixCoefficients none;
#pragma omp parallel for schedule(dynamic) if (options.assembly == core::AssemblyExecution::parallel)
      for (int id = 0; id < total; ++id) {
        if (id < model_count)
          compute_model_block(id, time, none, nullptr);
        else
          compute_constraint_block(id - model_count, time, none, nullptr);
      }
    }
    // Gather: dynamic rows r = Σ blocks + Σ Bᵀλ − gravity, and an elementwise scale of its terms.
    residual.setZero();
    scale = gravity.cwiseAbs();
    auto dynamic = residual.head(dof_count);
    dynamic -= gravity;
    for (const BlockWork& w : blocks)
      for (std::size_t I = 0; I < w.nodes.size(); ++I) {
        const auto part = w.residual.segment<dofs_per_node>(dofs_per_node * I);
        dynamic.segment<dofs_per_node>(dofs_per_node * w.nodes[I]) += part;
        scale.segment<dofs_per_node>(dofs_per_node * w.nodes[I]) += part.cwiseAbs();
      }
    for (std::size_t ci = 0; ci < constraints.size(); ++ci) {
      ConstraintWork& w = constraint_work[ci];
      w.force.noalias() = w.jacobian.transpose() * lambda.segment(w.first_multiplier, w.value.size());
      for (std::size_t I = 0; I < w.nodes.size(); ++I) {
        dynamic.segment<dofs_per_node>(dofs_per_node * w.nodes[I]) += w.force.segment<dofs_per_node>(dofs_per_node * I);
        scale.segment<dofs_per_node>(dofs_per_node * w.nodes[I]) += w.force.segment<dofs_per_node>(dofs_per_node * I).cwiseAbs();
      }
      residual.segment(dof_count + w.first_multiplier, w.value.size()) = w.value;
    }
    for (int dof : fixed_dofs) dynamic(dof) = 0.0;
    dynamic /= residual_scale;
  }

  bool dynamic_residual_small(double residual_scale) const {
    const double floor = detail::residual_round_off_floor(pattern->matrix(), model.state());
    for (int i = 0; i < dof_count; ++i)
      if (std::abs(residual(i)) > options.residual_tolerance * scale(i) / residual_scale + floor)
        return false;
    return true;
  }

  double constraint_norm() const {
    return multiplier_count ? residual.tail(multiplier_count).lpNorm<Eigen::Infinity>() : 0.0;
  }

  /// Factorizes the assembled matrix after the Dirichlet conditions; a singular matrix is a
  /// modelling error that no smaller step repairs.
  void factorize(double time) {
    Eigen::VectorXd unused = Eigen::VectorXd::Zero(dof_count + multiplier_count);
    pattern->apply_dirichlet(fixed_dofs, unused);
    try {
      solver->factorize(pattern->matrix());
    } catch (const Error& error) {
      std::ostringstream what;
      what << "the iteration matrix is singular at t = " << time << " (step " << counters.steps + 1
           << "): " << error.what();
      throw Error(what.str(), "solvers::GeneralizedAlpha",
                  "check for a redundant constraint (e.g. two joints fixing the same freedom) or a "
                  "freedom with neither mass nor constraint (e.g. a massless body's rotation)");
    }
    ++counters.factorizations;
    have_factorization = true;
  }

  // Initial conditions ---------------------------------------------------------------------------

  /// M v̇₀ + Bᵀλ₀ = −(f_gyr + f_int − f_ext − f_g), B v̇₀ = −c(q₀, v₀, 0).
  void initialize() {
    acceleration.setZero();
    lambda.setZero();
    const MatrixCoefficients mass_only{.mass = 1.0, .damping = 0.0, .stiffness = 0.0};
    evaluate(t, &mass_only, 1.0);
    for (std::size_t ci = 0; ci < constraints.size(); ++ci) {
      const ConstraintWork& w = constraint_work[ci];
      Eigen::VectorXd c(w.value.size());
      constraints[ci]->acceleration_terms(model.state(), velocity, t, c);
      residual.segment(dof_count + w.first_multiplier, w.value.size()) = c;
    }
    solution = -residual;
    pattern->apply_dirichlet(fixed_dofs, solution);
    factorize(t);
    have_factorization = false;  // this matrix is not an iteration matrix
    solver->solve(solution);
    acceleration = solution.head(dof_count);
    algorithmic_acceleration = acceleration;
    lambda = solution.tail(multiplier_count);
    if (options.iteration_matrix == IterationMatrix::frozen) freeze();
    initialized = true;
  }

  /// Stores every model block's mass, gyroscopic and stiffness matrices at t = 0.
  void freeze() {
    std::vector<FrozenBlock> initial(model_blocks.size());
    for (std::size_t id = 0; id < model_blocks.size(); ++id) {
      Eigen::MatrixXd K;
      compute_model_block(static_cast<int>(id), t, {.mass = 0.0, .damping = 0.0, .stiffness = 1.0}, &K);
      initial[id].stiffness = K;
      initial[id].mass = blocks[id].inertia.mass;
      initial[id].damping = blocks[id].inertia.gyroscopic_tangent;
    }
    frozen = std::move(initial);
  }

  // One step -------------------------------------------------------------------------------------

  /// The Newton starting point of a step. `extrapolated` is Brüls et al.'s (v̇_{n+1} = 0, which
  /// carries a_n into the step); `velocity_only` picks v̇_{n+1} so that the motion starts as
  /// q_n ⊕ h v_n, the better guess after an impulsive start (a concentrated moment on a section
  /// of tiny rotary inertia has a huge, short-lived initial acceleration). Both keep the update
  /// relations of eq. 49, so the converged step is the same.
  enum class Predictor { extrapolated, velocity_only };
  Predictor predictor = Predictor::extrapolated;

  /// Tries one step of size h from the current state; on failure restores it and returns false.
  bool try_step(double h, Predictor predictor) {
    const double t_next = t + h;
    const double beta_prime = (1 - alpha.alpha_m) / (h * h * alpha.beta * (1 - alpha.alpha_f));
    const double gamma_prime = alpha.gamma / (h * alpha.beta);
    const MatrixCoefficients coefficients{.mass = 1.0, .damping = gamma_prime / beta_prime,
                                          .stiffness = 1.0 / beta_prime};
    start = model.state();
    const Eigen::VectorXd v0 = velocity, vdot0 = acceleration, a0 = algorithmic_acceleration,
                          lambda0 = lambda;
    if (h != factorized_step) have_factorization = false;

    // Predictor (Brüls et al. 2012, Algorithm 1): a_{n+1} = base + (1 − α_f)/(1 − α_m) v̇_{n+1}.
    const Eigen::VectorXd a = (alpha.alpha_f * vdot0 - alpha.alpha_m * a0) / (1 - alpha.alpha_m);
    acceleration.setZero();
    if (predictor == Predictor::velocity_only)  // (½ − β) a_n + β a_{n+1} = 0
      acceleration = (-(0.5 - alpha.beta) / alpha.beta * a0 - a) * (1 - alpha.alpha_m) / (1 - alpha.alpha_f);
    const Eigen::VectorXd a_next = a + (1 - alpha.alpha_f) / (1 - alpha.alpha_m) * acceleration;
    velocity = v0 + h * (1 - alpha.gamma) * a0 + h * alpha.gamma * a_next;
    increment = h * v0 + h * h * (0.5 - alpha.beta) * a0 + h * h * alpha.beta * a_next;
    for (int dof : fixed_dofs) velocity(dof) = increment(dof) = acceleration(dof) = 0.0;
    move_to_increment();

    double previous_norm = INFINITY, increment_norm_squared = INFINITY;
    for (int iteration = 0;; ++iteration) {
      // Once the increment is below the tolerance the next evaluation is most likely the last:
      // it computes the residual only, and the matrix follows if the residual check fails.
      const bool expect_convergence = increment_norm_squared <= options.tolerance;
      bool need_matrix = options.iteration_matrix != IterationMatrix::modified ||
                         !have_factorization || refactor_requested;
      evaluate(t_next, need_matrix && !expect_convergence ? &coefficients : nullptr, beta_prime);
      if (!residual.allFinite()) break;
      if (iteration > 0 && increment_norm_squared <= options.tolerance &&
          constraint_norm() <= options.constraint_tolerance && dynamic_residual_small(beta_prime)) {
        algorithmic_acceleration = a + (1 - alpha.alpha_f) / (1 - alpha.alpha_m) * acceleration;
        t = t_next;
        last_iterations = iteration;
        return true;
      }
      if (iteration == options.max_iterations) break;
      if (need_matrix && expect_convergence) evaluate(t_next, &coefficients, beta_prime);
      if (need_matrix) {
        if (options.iteration_matrix != IterationMatrix::frozen) ++counters.jtheta_evaluations;
        factorize(t_next);
        factorized_step = h;
        refactor_requested = false;
      }
      solution = -residual;
      for (int dof : fixed_dofs) solution(dof) = 0.0;
      solver->solve(solution);
      ++counters.newton_iterations;
      if (!solution.allFinite()) break;  // a failed iteration: the step is cut back
      const auto dx = solution.head(dof_count);
      const auto dlambda = solution.tail(multiplier_count);
      increment += dx;
      velocity += gamma_prime * dx;
      acceleration += beta_prime * dx;
      lambda += beta_prime * dlambda;
      move_to_increment();
      // 003 §5.1: D = [Δq, h²β Δλ].
      const double dlambda_norm = h * h * alpha.beta * beta_prime * dlambda.norm();
      increment_norm_squared = dx.squaredNorm() + dlambda_norm * dlambda_norm;
      const double norm = std::sqrt(increment_norm_squared);
      if (options.iteration_matrix == IterationMatrix::modified &&
          norm > options.modified_newton_contraction * previous_norm)
        refactor_requested = true;
      previous_norm = norm;
    }
    // Not converged: restore the step's start.
    model.state() = start;
    velocity = v0;
    acceleration = vdot0;
    algorithmic_acceleration = a0;
    lambda = lambda0;
    refactor_requested = true;
    return false;
  }

  /// q = q_n ⊕ increment.
  void move_to_increment() {
    core::Configuration& q = model.state();
    for (int k = 0; k < q.node_count(); ++k) {
      q.position[k] = start.position[k] + increment.segment<3>(dofs_per_node * k);
      q.rotation[k] = lie::right_plus(start.rotation[k], increment.segment<3>(dofs_per_node * k + 3));
    }
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
           << ", h = " << h << ") after " << depth << " halvings of the time step";
      throw Error(what.str(), "solvers::GeneralizedAlpha",
                  "reduce the time step, raise max_iterations, or check the model: a diverging "
                  "Newton often means an unrealistic load or an inconsistent initial state");
    }
    ++counters.cutbacks;
    advance(h / 2, depth + 1);
    advance(h / 2, depth + 1);
  }
};

GeneralizedAlpha::GeneralizedAlpha(core::Model& model, ConstraintList constraints,
                                   const DynamicOptions& options)
    : impl_(std::make_unique<Implementation>(model, std::move(constraints), options)) {}

GeneralizedAlpha::~GeneralizedAlpha() = default;

void GeneralizedAlpha::set_velocity(int node, const Eigen::Vector3d& linear, const Eigen::Vector3d& angular) {
  if (node < 0 || node >= impl_->model.node_count())
    throw Error("node " + std::to_string(node) + " does not exist", "solvers::GeneralizedAlpha::set_velocity",
                "give a node of the model");
  if (impl_->initialized)
    throw Error("initial velocities must be set before the first step", "solvers::GeneralizedAlpha::set_velocity",
                "call set_velocity before initialize() and step()");
  impl_->velocity.segment<3>(dofs_per_node * node) = linear;
  impl_->velocity.segment<3>(dofs_per_node * node + 3) = angular;
}

void GeneralizedAlpha::initialize() {
  const auto start = std::chrono::steady_clock::now();
  impl_->initialize();
  impl_->counters.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void GeneralizedAlpha::step() {
  if (!impl_->initialized) initialize();
  const auto start = std::chrono::steady_clock::now();
  impl_->advance(impl_->options.time_step, 0);
  impl_->counters.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double GeneralizedAlpha::time() const { return impl_->t; }
const core::Configuration& GeneralizedAlpha::configuration() const { return impl_->model.state(); }
const Eigen::VectorXd& GeneralizedAlpha::velocity() const { return impl_->velocity; }
const Eigen::VectorXd& GeneralizedAlpha::acceleration() const { return impl_->acceleration; }
const Eigen::VectorXd& GeneralizedAlpha::multipliers() const { return impl_->lambda; }
const DynamicCounters& GeneralizedAlpha::counters() const { return impl_->counters; }
int GeneralizedAlpha::multiplier_count() const { return impl_->multiplier_count; }
int GeneralizedAlpha::last_step_iterations() const { return impl_->last_iterations; }

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
  Energies e;
  const core::Model& model = impl_->model;
  const core::Configuration& q = model.state();
  for (const core::ModelBlock& block : impl_->model_blocks) {
    core::InertiaContribution inertia;
    if (block.kind == core::ModelBlock::Kind::beam_element) {
      core::beam_element_inertia(model.beam(block.index), block.element, impl_->velocity, inertia);
      core::NodalContribution internal;
      core::beam_element_contribution(model, block.index, block.element, q, false, internal);
      e.strain += internal.energy;
    } else if (block.kind == core::ModelBlock::Kind::rigid_body) {
      core::rigid_body_inertia(model.rigid_body(block.index), impl_->velocity, inertia);
    } else {
      continue;
    }
    e.kinetic += core::kinetic_energy(inertia, impl_->velocity);
  }
  e.gravity = model.gravity_potential(q);
  return e;
}

}  // namespace spar::solvers
