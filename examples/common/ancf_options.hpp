#pragma once
// The element options of paper 001's examples (ancf_cantilever, ancf_pendulum,
// ancf_double_pendulum): the 3D ANCF element, 24 or 30 coordinates (or the geometrically exact
// beam to compare with), and its elastic forces, 001's methods I and II (docs/ancf.md).
#include <spar/spar.hpp>

#include <string>

namespace spar::examples {

struct AncfChoice {
  std::string element;  ///< 24 | 30 | gebt
  std::string force;    ///< invariant | gerstmayr

  bool gebt() const { return element == "gebt"; }
  core::AncfElementKind kind() const {
    return element == "24" ? core::AncfElementKind::standard_24 : core::AncfElementKind::higher_order_30;
  }
  core::AncfForceMethod method() const {
    return force == "invariant" ? core::AncfForceMethod::invariant : core::AncfForceMethod::gerstmayr;
  }
};

/// --element (24 or 30, and gebt if `with_gebt`) and --force, which only the ANCF elements take.
inline AncfChoice ancf_options(study::CommandLine& cli, bool with_gebt) {
  AncfChoice choice;
  choice.element = with_gebt ? cli.text("--element", "24", "24 | 30 (ANCF coordinates per element) | gebt", {"24", "30", "gebt"})
                             : cli.text("--element", "24", "24 | 30 (ANCF coordinates per element)", {"24", "30"});
  choice.force = cli.text("--force", "gerstmayr", "invariant (method I) | gerstmayr (method II)", {"invariant", "gerstmayr"});
  if (with_gebt) cli.applies_only_when("--force", "--element", {"24", "30"});  // the ANCF element's elastic forces
  return choice;
}

}  // namespace spar::examples
