// An outside driver built against the installed package: the README's minimal model, as written
// there (keep the two in step). A steel cantilever with a small tip load must bend as
// Euler–Bernoulli theory says, δ = F L³ / (3 E I), to the shear and geometric nonlinearity of
// the load (relative 1e-3).
#include <spar/spar.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace spar;
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection square = core::CrossSection::rectangle(0.01, 0.01, 0.3);
  const int elements = 8, degree = 3;

  core::Model model;
  const int b = core::add_beam(model,
      {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0), elements, degree),
       .stiffness = core::SectionStiffness::from(steel, square)});
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  const int tip = beam.node(beam.control_point_count() - 1);
  model.fix(beam.node(0));  // clamp the root
  core::add_load(model, core::NodalForce{.node = tip, .force = {0, 1, 0}});
  solvers::solve_static(model, {.load_steps = 1});

  const double EI = 2.1e11 * std::pow(0.01, 4) / 12;
  const double expected = 1.0 / (3 * EI);
  const double deflection = model.state().position[tip].y();
  std::printf("outside driver: tip deflection %.6e m, Euler-Bernoulli %.6e m\n", deflection, expected);
  return std::abs(deflection - expected) <= 1e-3 * expected ? 0 : 1;
}
