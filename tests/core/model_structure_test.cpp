// Model structure changes: removing an element.
#include <spar/elements/rigid_body/point_mass_element.hpp>
#include <spar/core/model.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <memory>

using namespace spar;

TEST_CASE("remove_element shifts the later elements and marks the structure changed", "[core]") {
  core::Model model;
  const int block = model.add_vector(Eigen::VectorXd::Zero(2));
  for (const char* name : {"a", "b", "c"})
    model.add_element(std::make_unique<core::PointMassElement>(
        core::PointMassParameters{.block = block, .dimension = 2, .mass = 1.0, .name = name}));
  const long version = model.structure_version();
  model.remove_element(1);
  CHECK(model.element_count() == 2);
  CHECK(model.element(0).name() == "a");
  CHECK(model.element(1).name() == "c");
  CHECK(model.structure_version() > version);
  CHECK_THROWS_AS(model.remove_element(2), Error);
}
