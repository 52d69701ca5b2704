#pragma once
// The command-line options the sliding-mass examples of paper 000 share (falling_beam,
// suspended_beam, semicircular_beam): the element kind, the mesh, the time integration.
#include <spar/spar.hpp>

#include <cli.hpp>

#include <string>

namespace spar::examples {

struct SlidingMassOptions {
  std::string kind;      ///< ale-rancf | ale-ancf
  int elements = 0;
  double h = 0.0, t_end = 0.0, rho_infinity = 1.0;
  std::string strategy;  ///< the iteration matrix: update | frozen | modified
};

/// Reads --element, --elements (at most what `memory`, the example's, lets fit), --h, --t-end,
/// --rho-inf and --strategy with the example's defaults.
inline SlidingMassOptions sliding_mass_options(CommandLine& cli, int default_elements, double default_t_end,
                                               const MemoryUse& memory) {
  SlidingMassOptions o;
  o.kind = cli.text("--element", "ale-rancf", "ale-rancf or ale-ancf", {"ale-rancf", "ale-ancf"});
  o.elements = cli.elements("--elements", default_elements, "elements", 3, memory);
  o.h = cli.number("--h", 1e-3, "time step [s]", Range::positive());
  o.t_end = cli.number("--t-end", default_t_end, "end time [s]", Range::positive());
  o.rho_infinity = cli.number("--rho-inf", 1.0, "spectral radius at infinity (1: no dissipation)", Range::between(0, 1));
  o.strategy = cli.text("--strategy", "update", "iteration matrix: update | frozen | modified",
                        {"update", "frozen", "modified"});
  return o;
}

/// The run's setup as attributes of its results file.
inline void write_attributes(core::ResultsWriter& results, const std::string& example, const SlidingMassOptions& o) {
  results.write_attribute("example", example);
  results.write_attribute("element", o.kind);
  results.write_attribute("time_step", o.h);
  results.write_attribute("rho_infinity", o.rho_infinity);
  results.write_attribute("strategy", o.strategy);
}

}  // namespace spar::examples
