// add_beam refuses a control polygon with two coincident consecutive points or one that folds
// straight back on itself (issue 29: both were accepted), leaving the model unchanged, and accepts
// the legitimate centerlines: exact arcs, repeated knots, the carriers and members of the examples.
#include <spar/core/model.hpp>
#include <spar/error.hpp>
#include <spar/iga/circular_arc.hpp>
#include <spar/iga/knot_operations.hpp>
#include <spar/iga/straight_line.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <numbers>

#include "beam_fixtures.hpp"
#include "sliding_carriers.hpp"

using namespace spar;
using Catch::Contains;

namespace {

/// add_beam must throw a spar::Error whose message holds `word`, and leave `model` as it was.
void check_refused(core::Model& model, const iga::NurbsCurve<3>& centerline, const std::string& word) {
  const int blocks = model.block_count(), elements = model.element_count();
  try {
    core::add_beam(model, {.centerline = centerline, .stiffness = test::generic_stiffness()});
    FAIL_CHECK("the centerline was accepted: " << word);
    return;
  } catch (const Error& error) {
    CHECK_THAT(error.what(), Contains(word));
    CHECK(error.where() == "core::GeometricallyExactBeam");
  }
  CHECK(model.block_count() == blocks);
  CHECK(model.element_count() == elements);
  CHECK(core::beam_count(model) == 1);
}

}  // namespace

TEST_CASE("add_beam refuses coincident consecutive control points and a folded control polygon",
          "[gebt][errors]") {
  core::Model model;
  core::add_beam(model, {.centerline = test::straight_centerline(1.0, 2, 2), .stiffness = test::generic_stiffness()});
  const Eigen::Vector3d a(1.1, 2.2, -0.3), d(0.3, -0.7, 0.2);
  const iga::KnotVector two_elements = iga::KnotVector::open_uniform(2, 2, 1);
  // Control points 1 and 2 coincide: the tangent vanishes at the knot between them.
  iga::NurbsCurve<3>::Points P(3, 4);
  P << a, a + d, a + d, a + 2 * d;
  check_refused(model, iga::NurbsCurve<3>(two_elements, P), "control points 1 and 2 coincide");
  // Folded: the polygon runs out along d and straight back (x(u) turns back inside the element).
  P << a, a + d, a + 0.4 * d, a - 0.5 * d;
  check_refused(model, iga::NurbsCurve<3>(two_elements, P), "folds back on itself at control point 1");
  // Folded at a C⁰ knot (a double knot): a hairpin of two elements on top of each other.
  iga::NurbsCurve<3>::Points H(3, 5);
  H << a, a + d, a + 2 * d, a + d, a;
  check_refused(model, iga::NurbsCurve<3>(iga::KnotVector({0, 0, 0, 0.5, 0.5, 1, 1, 1}, 2), H),
                "folds back on itself at control point 2");
}

TEST_CASE("add_beam accepts exact arcs, repeated knots and the examples' centerlines", "[gebt]") {
  core::Model model;
  const auto accepted = [&](const iga::NurbsCurve<3>& centerline) {
    CHECK_NOTHROW(core::add_beam(model, {.centerline = centerline, .stiffness = test::generic_stiffness(),
                                  .section_axis_hint = Eigen::Vector3d(0.1, 0.2, 1.0)}));
  };
  // Exact arcs of 1 to 4 pieces (legs at right angles beside the middle control points, straight
  // on through the double knots), refined and elevated as the sliding-joint carriers.
  for (const double sweep : {std::numbers::pi / 3, std::numbers::pi, 2 * std::numbers::pi})
    accepted(iga::circular_arc<3>({.radius = 1.5, .sweep = sweep}));
  accepted(test::quarter_circle_carrier(1.5, 10, 3, 1));
  // A straight line with a C⁰ knot (legs along the line through the repeated knot).
  iga::NurbsCurve<3>::Points S(3, 5);
  S << Eigen::Vector3d::Zero(), Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1.5, 0, 0),
      Eigen::Vector3d(2, 0, 0);
  accepted(iga::NurbsCurve<3>(iga::KnotVector({0, 0, 0, 0.5, 0.5, 1, 1, 1}, 2), S));
  // A polygon that turns by 150° (a sharp bend, not a fold) and the truss's 1 cm elements 10 m out.
  iga::NurbsCurve<3>::Points B(3, 3);
  B << Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1 - std::sqrt(3.0) / 2, 0.5, 0);
  accepted(iga::NurbsCurve<3>(iga::KnotVector({0, 0, 0, 1, 1, 1}, 2), B));
  accepted(iga::straight_line<3>(Eigen::Vector3d(8, 2, 2), Eigen::Vector3d(8, 0, 0), 400, 2));
  CHECK(core::beam_count(model) == 7);
}
