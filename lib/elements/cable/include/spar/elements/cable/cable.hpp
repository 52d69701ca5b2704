#pragma once
/// \file
/// The cable family's mesh builder, the counterpart of core::add_beam: a straight cable of equal
/// RANCF elements (000 §2, unit weights: the plain ANCF cable) or ALE-RANCF elements (000 §3,
/// material coordinates as scalar blocks), with nodes [r, r_x] as vector blocks of 2·Dim entries.

#include <spar/core/model.hpp>
#include <spar/elements/cable/rancf_cable_element.hpp>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::core {

/// A straight cable from `start` to `end` (for Dim = 2 the points' z must be 0).
struct CableParameters {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d end = Eigen::Vector3d::UnitX();
  int elements = 1;
  RancfSection section;
  /// ALE-RANCF elements with the nodes' material coordinates x_i = i L/elements as scalar blocks
  /// (000 eq. (11)); false: fixed-length RANCF elements.
  bool ale = false;
  int quadrature_points = 5;  ///< Gauss points in u per element, 2 … 16
  std::string name = "cable";
};

/// The blocks of a cable built by add_cable.
struct Cable {
  std::vector<int> nodes;      ///< [r, r_x] vector blocks, from start to end
  std::vector<int> materials;  ///< the nodes' material coordinates x (ALE only; else empty)
  std::vector<int> elements;   ///< the elements' indices in the model
  double element_length = 0.0;
};

/// Adds a straight cable to `model`: elements + 1 nodes with r on the line and r_x the unit
/// direction (stress-free: the parameterization is by arc length), and one element per span
/// named "<name> element <i>". Throws spar::Error for fewer than one element, coincident or
/// non-finite end points, a planar cable (Dim = 2) with a z coordinate, or what the elements
/// refuse (non-positive section values, a quadrature outside 2 … 16).
template <int Dim>
Cable add_cable(Model& model, const CableParameters& parameters);

extern template Cable add_cable<2>(Model&, const CableParameters&);
extern template Cable add_cable<3>(Model&, const CableParameters&);

}  // namespace spar::core
