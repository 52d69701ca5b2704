#include "step_check.hpp"

#include "format_double.hpp"

#include <spar/error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

namespace spar::output::detail {

namespace {

/// The checks of one step, with what their messages name.
class StepCheck {
public:
  StepCheck(const ResultsLayout& layout, const StepPosition& position)
      : layout_(layout),
        position_(position),
        nodes_(layout.node_count > 0),
        velocities_(nodes_ && layout.velocities),
        multipliers_(layout.multiplier_count > 0) {}

  void check(const ResultsStep& step) const {
    if (!std::isfinite(step.time) || (position_.index > 0 && !(step.time > position_.last_time)))
      throw Error("step.time = " + format_double(step.time) + " is not finite or not after the previous step's " +
                      (position_.index > 0 ? format_double(position_.last_time) : std::string("-")),
                  where(), "append converged steps only, in increasing time");
    const auto n = static_cast<std::size_t>(layout_.node_count);
    const core::Configuration* q = step.configuration;
    if (n > 0 && (q == nullptr || q->position.size() != n || q->rotation.size() != n))
      size_error("configuration nodes", q == nullptr ? 0 : std::min(q->position.size(), q->rotation.size()),
                 std::to_string(n) + " (layout.node_count)", "pass the model's configuration");
    const Eigen::VectorXd* v = step.velocity;
    if (velocities_ && (v == nullptr || static_cast<std::size_t>(v->size()) != 6 * n))
      size_error("velocity", v == nullptr ? 0 : static_cast<std::size_t>(v->size()),
                 "6 per node = " + std::to_string(6 * n), "pass 6 entries per node (x dot, Omega)");
    if (!velocities_ && v != nullptr)
      size_error("velocity", static_cast<std::size_t>(v->size()), "none (layout.velocities is false or no nodes)",
                 "set layout.velocities, or pass velocity = nullptr");
    const auto m = static_cast<std::size_t>(layout_.multiplier_count);
    const Eigen::VectorXd* lambda = step.multipliers;
    const std::size_t lambda_size = lambda == nullptr ? 0 : static_cast<std::size_t>(lambda->size());
    if (lambda_size != m)
      size_error("multipliers", lambda_size, std::to_string(m) + " (layout.multiplier_count)",
                 "pass the multiplier vector of the constraints, or fix layout.multiplier_count");
    if (step.scalars.size() != layout_.scalars.size())
      size_error("scalars", step.scalars.size(), std::to_string(layout_.scalars.size()) + " (layout.scalars)",
                 "pass one value per layout scalar, in the same order");
    if (step.probes.size() != layout_.probes.size())
      size_error("probes", step.probes.size(), std::to_string(layout_.probes.size()) + " (layout.probes)",
                 "pass one point per layout probe, in the same order");
    check_profiles(step);
    check_counters(step);
    check_centerlines(step);
    check_finite_values(step);
  }

private:
  std::string where() const { return position_.where + " at step " + std::to_string(position_.index); }

  [[noreturn]] void size_error(const std::string& field, std::size_t got, const std::string& expected,
                               const std::string& fix) const {
    throw Error("step." + field + " has " + std::to_string(got) + " entries, expected " + expected, where(), fix);
  }

  /// Throws spar::Error naming `field` if `values` hold a NaN or an infinity (issue 29: a NaN
  /// probe or position was written silently): the index of the first such entry, as `entry`
  /// describes it.
  void check_finite(const std::string& field, const double* values, std::size_t count,
                    const std::function<std::string(std::size_t)>& entry, bool may_be_undefined = false) const {
    const double* bad = std::find_if(values, values + count, [may_be_undefined](double x) {
      return !std::isfinite(x) && !(may_be_undefined && std::isnan(x));
    });
    if (bad != values + count)
      throw Error("step." + field + " " + entry(static_cast<std::size_t>(bad - values)) + " = " + format_double(*bad) +
                      " is not finite",
                  where(), "check the run that computed it; only a scalar, probe or profile declared may_be_undefined may be NaN");
  }

  /// Every value the step holds is finite, but NaN in a probe declared may_be_undefined (the
  /// scalars: check_counters).
  void check_finite_values(const ResultsStep& step) const {
    const auto plain = [](std::size_t i) { return "entry " + std::to_string(i); };
    const auto xyz = [](std::size_t i) { return "component " + std::to_string(i); };
    if (const core::Configuration* q = step.configuration; nodes_) {
      for (std::size_t i = 0; i < q->position.size(); ++i) {
        check_finite("configuration position of node " + std::to_string(i), q->position[i].data(), 3, xyz);
        check_finite("configuration rotation of node " + std::to_string(i), q->rotation[i].data(), 9, plain);
      }
    }
    if (velocities_) check_finite("velocity", step.velocity->data(), static_cast<std::size_t>(step.velocity->size()), plain);
    if (multipliers_)
      check_finite("multipliers", step.multipliers->data(), static_cast<std::size_t>(step.multipliers->size()), plain);
    for (std::size_t i = 0; i < step.probes.size(); ++i)
      check_finite("probes[" + std::to_string(i) + "] (" + layout_.probes[i].name + ")", step.probes[i].data(), 3, xyz,
                   layout_.probes[i].may_be_undefined);
    for (std::size_t k = 0; k < step.centerlines.size(); ++k)
      check_matrix("centerlines[" + std::to_string(k) + "]", step.centerlines[k]);
    for (std::size_t k = 0; k < step.centerline_fields.size(); ++k)
      for (std::size_t f = 0; f < step.centerline_fields[k].size(); ++f)
        check_matrix("centerline_fields[" + std::to_string(k) + "][" + std::to_string(f) + "] (" +
                         layout_.centerline_fields[f].name + ")",
                     step.centerline_fields[k][f]);
    for (std::size_t i = 0; i < step.profiles.size(); ++i)
      check_matrix("profiles[" + std::to_string(i) + "] (" + layout_.profiles[i].quantity.name + ")", step.profiles[i],
                   layout_.profiles[i].quantity.may_be_undefined);
  }

  /// check_finite for a matrix of points, its entries named by row and column.
  void check_matrix(const std::string& field, const Eigen::MatrixXd& values, bool may_be_undefined = false) const {
    const auto rows = static_cast<std::size_t>(values.rows());
    check_finite(field, values.data(), static_cast<std::size_t>(values.size()), [rows](std::size_t i) {
      return "row " + std::to_string(i % rows) + ", column " + std::to_string(i / rows);
    }, may_be_undefined);
  }

  /// One matrix per layout profile, of its points × components.
  void check_profiles(const ResultsStep& step) const {
    if (step.profiles.size() != layout_.profiles.size())
      size_error("profiles", step.profiles.size(), std::to_string(layout_.profiles.size()) + " (layout.profiles)",
                 "pass one matrix per layout profile, in the same order");
    for (std::size_t i = 0; i < step.profiles.size(); ++i) {
      const ResultsProfile& profile = layout_.profiles[i];
      const Eigen::MatrixXd& values = step.profiles[i];
      if (values.rows() != profile.points || values.cols() != profile.components)
        size_error("profiles[" + std::to_string(i) + "] (" + profile.quantity.name + ")",
                   static_cast<std::size_t>(values.size()),
                   std::to_string(profile.points) + " × " + std::to_string(profile.components) + ", got " +
                       std::to_string(values.rows()) + " × " + std::to_string(values.cols()),
                   "evaluate the profile at the layout's points, one row each");
    }
  }

  /// Scalars are finite (NaN only where declared may_be_undefined); the values of integer
  /// scalars are whole numbers that fit in 32 bits.
  void check_counters(const ResultsStep& step) const {
    for (std::size_t i = 0; i < step.scalars.size(); ++i) {
      const double value = step.scalars[i];
      if (!std::isfinite(value) && !(std::isnan(value) && layout_.scalars[i].may_be_undefined))
        throw Error("step.scalars[" + std::to_string(i) + "] (" + layout_.scalars[i].name + ") = " + format_double(value) +
                        " is not finite",
                    where(),
                    "check the run that computed it, or declare the scalar may_be_undefined if NaN marks "
                    "a step where it has no value");
      if (layout_.scalars[i].integer &&
          !(value == std::trunc(value) && std::abs(value) <= std::numeric_limits<std::int32_t>::max()))
        throw Error("step.scalars[" + std::to_string(i) + "] = " + format_double(value) + " for the integer scalar " +
                        layout_.scalars[i].name + " is not a whole number of 32 bits",
                    where(), "pass the counter's value, or declare the scalar without `integer`");
    }
  }

  void check_centerlines(const ResultsStep& step) const {
    const std::vector<int>& points = layout_.centerline_points;
    if (step.centerlines.size() != points.size())
      size_error("centerlines", step.centerlines.size(), std::to_string(points.size()) + " beams (layout.centerline_points)",
                 "pass one sampled centerline per beam");
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Eigen::MatrixXd& c = step.centerlines[k];
      if (c.rows() != points[k] || c.cols() != 3)
        size_error("centerlines[" + std::to_string(k) + "]", static_cast<std::size_t>(c.size()),
                   std::to_string(points[k]) + " × 3 (layout.centerline_points[" + std::to_string(k) +
                       "] rows of x, y, z), got " + std::to_string(c.rows()) + " × " + std::to_string(c.cols()),
                   "sample the beam at the layout's number of points");
    }
    check_centerline_fields(step);
  }

  void check_centerline_fields(const ResultsStep& step) const {
    const std::vector<CenterlineField>& fields = layout_.centerline_fields;
    const std::size_t beams = fields.empty() ? 0 : layout_.centerline_points.size();
    if (step.centerline_fields.size() != beams)
      size_error("centerline_fields", step.centerline_fields.size(),
                 fields.empty() ? std::string("none (layout.centerline_fields is empty)")
                                : std::to_string(beams) + " beams (layout.centerline_points)",
                 "pass per beam one matrix per layout.centerline_fields entry");
    for (std::size_t k = 0; k < beams; ++k) {
      const std::string entry = "centerline_fields[" + std::to_string(k) + "]";
      if (step.centerline_fields[k].size() != fields.size())
        size_error(entry, step.centerline_fields[k].size(), std::to_string(fields.size()) + " (layout.centerline_fields)",
                   "pass one matrix per field, in the layout's order");
      for (std::size_t f = 0; f < fields.size(); ++f) {
        const Eigen::MatrixXd& values = step.centerline_fields[k][f];
        if (values.rows() != layout_.centerline_points[k] || values.cols() != fields[f].components)
          size_error(entry + "[" + std::to_string(f) + "] (" + fields[f].name + ")", static_cast<std::size_t>(values.size()),
                     std::to_string(layout_.centerline_points[k]) + " × " + std::to_string(fields[f].components) +
                         " (a row per centerline point), got " + std::to_string(values.rows()) + " × " +
                         std::to_string(values.cols()),
                     "sample the field at the beam's centerline points");
      }
    }
  }

  const ResultsLayout& layout_;
  const StepPosition& position_;
  const bool nodes_;        ///< the layout has node series (positions, quaternions)
  const bool velocities_;   ///< ... and their velocities
  const bool multipliers_;  ///< the layout has multipliers
};

}  // namespace

void check_step(const ResultsLayout& layout, const ResultsStep& step, const StepPosition& position) {
  StepCheck(layout, position).check(step);
}

}  // namespace spar::output::detail
