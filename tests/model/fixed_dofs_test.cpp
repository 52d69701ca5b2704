// Model::fix keeps the fixed dofs sorted and without duplicates whatever the order of the calls
// (it inserts in place since issue 29, instead of sorting the whole list at every call).
#include <spar/core/model.hpp>
#include <spar/lie/exp.hpp>

#include <catch2/catch.hpp>

#include <vector>

using namespace spar;

TEST_CASE("fixed dofs stay sorted and unique under fixes in any order, repeated and partial", "[model]") {
  core::Model model;
  for (int k = 0; k < 4; ++k) model.add_frame(Eigen::Vector3d(k, 0, 0), Eigen::Matrix3d::Identity());
  const int vector = model.add_vector(Eigen::VectorXd::Zero(2));
  model.fix(vector);
  model.fix(2, core::Fix::rotations);
  model.fix(0, core::Fix::translations);
  model.fix(2);  // its rotations again, and its translations
  model.fix(0, core::Fix::translations);
  model.fix(1, core::Fix::rotations);
  // Frames at offsets 0, 6, 12, 18; the vector block at 24.
  const std::vector<int> expected{0, 1, 2, 9, 10, 11, 12, 13, 14, 15, 16, 17, 24, 25};
  CHECK(model.fixed_dofs() == expected);
}
