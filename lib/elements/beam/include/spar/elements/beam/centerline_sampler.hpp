#pragma once
/// \file
/// A beam's centerline at fixed parameters, evaluated at every recorded state of a run (results
/// files, plots): the NURBS basis of every point is computed once, so a state costs
/// Σ_I N_I(u_i) x_I per point — 3(p + 1) products — instead of a knot-span search and a basis
/// evaluation per point and state.

#include <spar/elements/beam/beam.hpp>
#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::core {

class CenterlineSampler {
public:
  /// `points` ≥ 2 parameters equally spaced over the beam's knot range (spar::Error otherwise).
  /// The beam must outlive the sampler.
  CenterlineSampler(const GeometricallyExactBeam& beam, int points);

  /// The number of points.
  int size() const { return static_cast<int>(first_node_.size()); }
  /// The centerline x(u_i) = Σ_I N_I(u_i) x_I (003 eq. 39), one row per point.
  Eigen::MatrixXd positions(const Configuration& q) const;
  /// Its velocity ẋ(u_i) = Σ_I N_I(u_i) ẋ_I (x is linear in the node positions), one row per
  /// point, from the global tangent-layout velocity of the model (the first 3 entries of a node).
  Eigen::MatrixXd velocities(const Configuration& q, const Eigen::VectorXd& velocity) const;

private:
  /// Σ_I N_I(u_i) value(node_I) for every point i.
  template <class NodeValue>
  Eigen::MatrixXd combine(const NodeValue& value) const;

  const GeometricallyExactBeam* beam_;
  int degree_;
  /// Per point i: the global node of its first control point, and N_{first+I}(u_i) for
  /// I = 0 … degree at shape_[i (degree + 1) + I] — the values alone, not a whole CenterlinePoint
  /// (whose basis table is sized for the highest degree and every derivative: ~1 KB a point).
  std::vector<int> first_node_;
  std::vector<double> shape_;
};

}  // namespace spar::core
