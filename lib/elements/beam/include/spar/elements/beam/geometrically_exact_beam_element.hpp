#pragma once
/// \file
/// One knot span of a geometrically exact beam as an Element (003 §3; docs/beam.md): the strain
/// energy's force and exact stiffness (elements/beam/beam_element.hpp), the constant consistent mass with
/// its gyroscopic terms (elements/beam/beam_inertia.hpp), and gravity as the consistent nodal forces
/// f_I = ∫ N_I ρA g dS.

#include <spar/elements/beam/beam.hpp>
#include <spar/elements/beam/beam_element.hpp>
#include <spar/core/element.hpp>
#include <spar/elements/beam/beam_inertia.hpp>

#include <string>
#include <vector>

namespace spar::core {

class GeometricallyExactBeamElement final : public Element {
public:
  /// Element e of `beam` (which must outlive this element); `beam_index` names it in messages.
  GeometricallyExactBeamElement(const GeometricallyExactBeam& beam, int beam_index, int e);

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override;
  std::string mass_defect() const override;

private:
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
  const GeometricallyExactBeam* beam_;
  int beam_index_;
  int element_;
  std::vector<int> blocks_;
  /// ∫ N_I dS over the element (part-0 Gauss points): consistent nodal weights of a uniform load.
  std::vector<double> shape_integrals_;
  /// The constant consistent mass in factored form (elements/beam/beam_inertia.hpp), computed once.
  FrameInertia inertia_;
};

/// ∫ N_I dS over element e of a beam, one entry per control point of the element: the consistent
/// nodal weights of a load per unit reference length (003 eq. 33).
std::vector<double> beam_shape_integrals(const GeometricallyExactBeam& beam, int e);

}  // namespace spar::core
