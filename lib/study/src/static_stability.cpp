#include <spar/study/static_stability.hpp>

#include <cstdio>

namespace spar::study {

void warn_if_unstable(const solvers::StaticReport& report) {
  if (report.unstable_directions > 0)
    std::fprintf(stderr,
                 "warning: the static state is unstable: the tangent stiffness has %d negative "
                 "eigenvalue(s) on the constraints' null space; a real structure leaves this "
                 "equilibrium (buckles). Perturb the load or the geometry to follow a stable branch.\n",
                 report.unstable_directions);
  else if (report.unstable_directions < 0)
    std::fprintf(stderr, "note: the stability of the static state was not assessed (a non-symmetric "
                         "or singular tangent)\n");
}

}  // namespace spar::study
