#pragma once
// The energy balance every dynamic example writes (docs/dynamics.md D8), so a user sees at a
// glance whether a run is physical: the energies, the work of the external loads and drivers,
// and what the integrator dissipated. tests/examples/check_results reads these names.
#include <spar/spar.hpp>

#include <ostream>
#include <vector>

namespace spar::examples {

/// The scalars of the balance, in the order energy_balance_values() gives them.
inline std::vector<core::ResultsQuantity> energy_balance_layout() {
  return {{.name = "kinetic_energy", .unit = "J", .description = "kinetic energy, 1/2 v^T M v"},
          {.name = "strain_energy", .unit = "J", .description = "strain energy of the beams"},
          {.name = "gravity_potential", .unit = "J", .description = "potential of gravity, -sum m g . x"},
          {.name = "external_work", .unit = "J",
           .description = "work done since t = 0 by the external loads without a potential and by the "
                          "drivers, trapezoidal along the increments"},
          {.name = "numerical_dissipation", .unit = "J",
           .description = "energy removed by the integrator since t = 0: external_work - (E - E(0)), "
                          "E = kinetic + strain + gravity"}};
}

inline std::vector<double> energy_balance_values(const solvers::Energies& e) {
  return {e.kinetic, e.strain, e.gravity, e.external_work, e.numerical_dissipation};
}

/// The CSV columns of the work and the dissipation (appended after an example's own columns).
inline constexpr const char* energy_balance_csv_columns = "external_work,numerical_dissipation";

/// Writes ",W,D" for energy_balance_csv_columns.
inline void write_energy_balance_csv(std::ostream& csv, const solvers::Energies& e) {
  csv << ',' << e.external_work << ',' << e.numerical_dissipation;
}

/// `own` followed by `balance` (a layout or a row of values).
template <class T>
std::vector<T> followed_by(std::vector<T> own, const std::vector<T>& balance) {
  own.insert(own.end(), balance.begin(), balance.end());
  return own;
}

}  // namespace spar::examples
