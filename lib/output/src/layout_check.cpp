#include "layout_check.hpp"

#include "format_double.hpp"

#include <spar/error.hpp>

#include <set>

namespace spar::output::detail {

namespace {

/// A quantity of layout.`field`: a name that is non-empty, has no '/' (it becomes a dataset name)
/// and is unique within `seen`; a unit and a description.
void check_quantity(const ResultsQuantity& quantity, const std::string& field, std::set<std::string>& seen,
                    const std::string& where) {
  const std::string& name = quantity.name;
  if (name.empty() || name.find('/') != std::string::npos)
    throw Error("layout." + field + " holds the name \"" + name + "\", which is empty or contains '/'", where,
                "use plain names such as kinetic_energy");
  if (!seen.insert(name).second)
    throw Error("layout." + field + " holds \"" + name + "\" twice", where,
                "give every " + field + " entry a distinct name");
  if (quantity.unit.empty() || quantity.description.empty())
    throw Error("layout." + field + " entry \"" + name + "\" has no " + (quantity.unit.empty() ? "unit" : "description"),
                where, "state its SI unit (\"1\" for ratios and counts) and what it is: the file carries both");
}

/// Shapes drawn at nodes that exist, of sizes a shape can have: a box's edges and given axis
/// lengths positive, unset axis lengths all zero; every number finite.
void check_rigid_bodies(const ResultsLayout& layout, const std::string& where) {
  for (std::size_t k = 0; k < layout.rigid_bodies.size(); ++k) {
    const RigidBodyShape& shape = layout.rigid_bodies[k];
    const std::string entry = "layout.rigid_bodies[" + std::to_string(k) + "]";
    if (shape.node < 0 || shape.node >= layout.node_count)
      throw Error(entry + ".node = " + std::to_string(shape.node) + " is not a node of the layout (node_count = " +
                      std::to_string(layout.node_count) + ")",
                  where, "pass the body's node, e.g. core::rigid_body(model, b).node, and the model's node count");
    const bool box = shape.kind == RigidBodyShape::Kind::box;
    const bool positive = (shape.size.array() > 0.0).all() && shape.size.allFinite();
    if (!shape.offset.allFinite() || !(positive || (!box && shape.size.isZero(0.0))))
      throw Error(entry + " has size (" + format_double(shape.size.x()) + ", " + format_double(shape.size.y()) + ", " +
                      format_double(shape.size.z()) + ") m or an offset that is not finite",
                  where,
                  box ? "give the box's three edge lengths in m, all positive"
                      : "give the three axis lengths in m, all positive, or leave them all zero for a tenth of the "
                        "model's extent");
  }
}

}  // namespace

void check_layout(const ResultsLayout& layout, int flush_every, const std::string& where) {
  if (layout.node_count < 0 || layout.multiplier_count < 0)
    throw Error("layout.node_count = " + std::to_string(layout.node_count) + " and layout.multiplier_count = " +
                    std::to_string(layout.multiplier_count) + " must not be negative",
                where, "pass the model's node and multiplier counts");
  if (flush_every < 1)
    throw Error("flush_every = " + std::to_string(flush_every) + " must be at least 1", where,
                "pass the number of steps per block write, e.g. 100");
  std::set<std::string> scalars, probes;
  for (const ResultsQuantity& scalar : layout.scalars) check_quantity(scalar, "scalars", scalars, where);
  for (const ResultsQuantity& probe : layout.probes) {
    check_quantity(probe, "probes", probes, where);
    if (probe.integer)
      throw Error("layout.probes entry \"" + probe.name + "\" is marked integer", where,
                  "probes are 3-vectors of doubles; declare counters as scalars");
  }
  for (std::size_t k = 0; k < layout.centerline_points.size(); ++k)
    if (layout.centerline_points[k] < 2)
      throw Error("layout.centerline_points[" + std::to_string(k) + "] = " + std::to_string(layout.centerline_points[k]) +
                      " is below 2",
                  where, "sample each beam's centerline at 2 points or more (e.g. 10 per element + 1)");
  std::set<std::string> fields;
  for (const CenterlineField& field : layout.centerline_fields) {
    check_quantity({.name = field.name, .unit = field.unit, .description = field.description}, "centerline_fields",
                   fields, where);
    if (field.name.find_first_of(":|") != std::string::npos)
      throw Error("layout.centerline_fields entry \"" + field.name + "\" contains ':' or '|'", where,
                  "name the field without the characters XDMF references reserve, e.g. axial_strain");
    if (field.components != 1 && field.components != 3)
      throw Error("layout.centerline_fields entry \"" + field.name + "\" has " + std::to_string(field.components) +
                      " components",
                  where, "give a scalar (1 component) or a vector (3 components) per point");
  }
  std::set<std::string> profiles;
  for (const ResultsProfile& profile : layout.profiles) {
    check_quantity(profile.quantity, "profiles", profiles, where);
    if (profile.quantity.integer || profile.points < 1 || profile.components < 1)
      throw Error("layout.profiles entry \"" + profile.quantity.name + "\" has " + std::to_string(profile.points) +
                      " points of " + std::to_string(profile.components) + " components" +
                      (profile.quantity.integer ? " and is marked integer" : ""),
                  where, "give at least one point of at least one component, stored as doubles");
  }
  check_rigid_bodies(layout, where);
}

}  // namespace spar::output::detail
