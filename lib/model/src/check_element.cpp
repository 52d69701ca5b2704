#include <spar/core/check_element.hpp>
#include <spar/error.hpp>

#include <cmath>
#include <string>

namespace spar::core {

namespace {

constexpr const char* where = "core::check_element";

void check_options(const ElementCheckOptions& options, const ElementInput& in) {
  const auto refuse = [](const std::string& what, const char* fix) { throw InputError(what, where, fix); };
  if (!(options.step > 0.0 && std::isfinite(options.step)) ||
      !(options.rate_step > 0.0 && std::isfinite(options.rate_step)))
    refuse("the steps are " + significant(options.step) + " and " + significant(options.rate_step),
           "give positive, finite steps (ElementCheckOptions::step, rate_step)");
  if (!(options.tolerance >= 0.0) || !(options.scale_floor >= 0.0))
    refuse("the tolerance is " + significant(options.tolerance) + ", the scale floor " +
               significant(options.scale_floor),
           "give a tolerance and a scale floor ≥ 0");
  if (options.potential && in.dynamic())
    refuse("a potential check of a dynamic evaluation (its residual holds inertia forces)",
           "check the potential with a static ElementInput (no velocity, no acceleration)");
  if (in.q == nullptr) refuse("ElementInput::q is null", "point it at the configuration to check at");
}

/// The element's residual and potential (strain + gravity energy) at an input, into a reused output.
class Evaluation {
public:
  Evaluation(const Element& element, int dofs, bool potential)
      : element_(element), dofs_(dofs), request_{.residual = true, .energy = potential} {}

  const ElementOutput& operator()(const ElementInput& in) {
    out_.reset(dofs_, request_);
    element_.evaluate(in, request_, out_);
    return out_;
  }

private:
  const Element& element_;
  int dofs_;
  ElementRequest request_;
  ElementOutput out_;
};

double potential(const ElementOutput& out) { return out.energy.strain + out.energy.gravity; }

}  // namespace

DerivativeCheck check_element(const Element& element, const ElementInput& in, const ElementCheckOptions& options) {
  check_options(options, in);
  const Configuration& q = *in.q;
  // The local size, counting only the blocks q has: evaluate reports a block it lacks.
  int n = 0;
  for (const int b : element.blocks())
    if (b >= 0 && b < q.block_count()) n += q.blocks[b].size;
  const bool dynamic = in.dynamic();
  const ElementRequest request{.residual = true, .stiffness = true, .damping = dynamic, .mass = dynamic};
  ElementOutput analytic;
  analytic.reset(n, request);
  element.evaluate(in, request, analytic);

  // The state the differences move: q ⊕ Δ, and copies of the velocity and acceleration.
  Configuration moved = q;
  Eigen::VectorXd increment = Eigen::VectorXd::Zero(q.dof_count());
  Eigen::VectorXd velocity, acceleration;
  ElementInput at = in;
  at.q = &moved;
  if (dynamic) {
    velocity = *in.velocity;
    acceleration = *in.acceleration;
    at.velocity = &velocity;
    at.acceleration = &acceleration;
  }
  Evaluation evaluate(element, n, options.potential);
  Eigen::VectorXd plus(n);
  // Column `column` of `derivative`: (r(+h) − r(−h)) / 2h with `move(h)` moving one entry of the
  // state by h (move(0) puts it back); the same of the potential into `slope` when asked.
  const auto difference = [&](double h, const auto& move, Eigen::MatrixXd& derivative, int column,
                              double* slope) {
    move(h);
    const ElementOutput& forward = evaluate(at);
    plus = forward.residual;
    const double forward_potential = potential(forward);
    move(-h);
    const ElementOutput& backward = evaluate(at);
    derivative.col(column) = (plus - backward.residual) / (2 * h);
    if (slope) *slope = (forward_potential - potential(backward)) / (2 * h);
    move(0.0);
  };

  const std::vector<int> dofs = block_dofs(q, element.blocks());
  Eigen::MatrixXd K(n, n), C(n, dynamic ? n : 0), M(n, dynamic ? n : 0);
  Eigen::VectorXd gradient(options.potential ? n : 0);
  for (int i = 0; i < n; ++i) {
    const int dof = dofs[static_cast<std::size_t>(i)];
    const auto move_coordinate = [&](double h) {  // q ⊕ h eᵢ (docs/model.md eq. M1)
      increment(dof) = h;
      moved.assign_increment(q, increment);
      increment(dof) = 0.0;
    };
    difference(options.step, move_coordinate, K, i, options.potential ? &gradient(i) : nullptr);
    if (!dynamic) continue;
    difference(options.rate_step, [&](double h) { velocity(dof) = (*in.velocity)(dof) + h; }, C, i, nullptr);
    difference(options.rate_step, [&](double h) { acceleration(dof) = (*in.acceleration)(dof) + h; }, M, i,
               nullptr);
  }

  DerivativeCheck check{.subject = std::string(where) + ", element '" + element.name() + "'"};
  const auto compare = [&](const char* name, const Eigen::MatrixXd& derivative, const Eigen::MatrixXd& reference) {
    check.comparisons.push_back(
        compare_derivative(name, derivative, reference, options.tolerance, options.scale_floor));
  };
  compare("stiffness K", analytic.stiffness, K);
  if (dynamic) {
    compare("damping C", analytic.damping, C);
    compare("mass M", analytic.mass, M);
  }
  if (options.potential) compare("residual r (gradient of strain + gravity energy)", analytic.residual, gradient);
  return check;
}

}  // namespace spar::core
