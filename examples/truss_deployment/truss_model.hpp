#pragma once
// The deployable truss unit of 003 §5.3 (Table 4; its Figure 7 is not in the text, so the
// geometry below is this project's reading of it, drawn and tabulated in README.md): shared by
// the example and its tests.
//
// Geometry (inertial X along the deployment, Y across, Z up):
//   Three square frames k = 0, 1, 2 of side a = 2 m, each in a plane X = const, made of four rods
//   (bottom, top along Y; left, right along Z) clamped together at the corners. Two bays join
//   frame k to frame k + 1 (k = 0, 1), each by four cross-bars of length b = 4 m from corner to
//   corner, hinged to both frames about Y (the bars' ξ2 axis: 003, "only the rotations around the
//   ξ2-axis released"). A bay is a parallelogram linkage in the X–Z plane: the frames stay parallel
//   and translate; its cross-bars make the angle β with the frame plane, 90° when deployed.
//   The unit folds as a Z: bay 0 rises from frame 0 (bar direction (sin β, 0, cos β)), bay 1
//   descends from frame 1 (sin β, 0, −cos β), so frame 2 stays level with frame 0.
//   Each bay carries four diagonals of length √(a² + b²) = √20 m:
//   - two side diagonals (faces Y = 0 and Y = 2, the faces that shear): hinged about Y at frame
//     k's lower corner (bay 0; the upper one in bay 1) and sliding along frame k + 1's vertical
//     rod at that Y (the carrier), locking at its far end, where the face is a 2 × 4 m rectangle
//     and β = 90° (003: "locked in the top end of carrier beams");
//   - a top and a bottom diagonal (faces Z = 2 and Z = 0, rectangles that turn about Y with the
//     bars) from the corner Y = 0 of frame k to the corner Y = 2 of frame k + 1, hinged about Y
//     at both ends. 003 says these are clamped to the frames, but a member clamped to both frames
//     welds them together and the unit cannot deploy (the faces turn about Y relative to the
//     frames): the hinge about Y is the only joint that lets the mechanism move and keeps those
//     faces braced (README, "Decisions"; tests/truss_deployment checks the mobility).
//   Frame 0 is fixed. D is the upper corner Y = 0 of frame 2: (8, 0, 2) m when deployed.
//   Every member is a tube 0.060/0.055 m, E = 2.1e11 Pa, ν = 0.3, ρ = 7850 kg/m³, discretized
//   by `elements` quadratic C¹ NURBS elements (003: one; four and ten for the convergence check).
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace spar::examples {

/// 003 Table 4.
struct TrussParameters {
  double frame_side = 2.0;       ///< a [m]
  double bar_length = 4.0;       ///< b [m] (the diagonals are √(a² + b²) = √20 m)
  double outer_diameter = 0.060;
  double inner_diameter = 0.055;
  core::Material material{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  double initial_angle = 5.0 * std::numbers::pi / 180.0;  ///< β₀
  int elements = 1;  ///< NURBS elements per member
  int degree = 2;
};

/// The folding direction of bay k: +1 rises from frame k, −1 descends (the Z fold).
inline double fold_sign(int bay) { return bay == 0 ? 1.0 : -1.0; }

/// The unit direction of bay k's cross-bars at the bar angle β: (sin β, 0, ±cos β).
inline Eigen::Vector3d bar_direction(int bay, double beta) {
  return {std::sin(beta), 0.0, fold_sign(bay) * std::cos(beta)};
}

/// The lower corner Y = 0 of frame k when every bay stands at β.
inline Eigen::Vector3d frame_origin(int frame, double beta, const TrussParameters& p) {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (int bay = 0; bay < frame; ++bay) origin += p.bar_length * bar_direction(bay, beta);
  return origin;
}

/// Corner (y, z) ∈ {0, 1}² of frame k at β: frame_origin + a (0, y, z).
inline Eigen::Vector3d corner(int frame, int y, int z, double beta, const TrussParameters& p) {
  return frame_origin(frame, beta, p) + p.frame_side * Eigen::Vector3d(0.0, y, z);
}

/// How far a side diagonal's sliding end is along its carrier from the end where the bay's
/// cross-bar at that corner arrives (the lower end in bay 0): the root s of
/// |b d + s e_z|² = a² + b², i.e. s² + 2 b cos β s − a² = 0 (law of cosines in the sheared face).
/// s = a at β = 90°.
inline double slide_distance(double beta, const TrussParameters& p) {
  const double c = p.bar_length * std::cos(beta);
  return -c + std::sqrt(c * c + p.frame_side * p.frame_side);
}

/// β from a side diagonal's slide distance s, the inverse of slide_distance:
/// cos β = (a² − s²)/(2 b s).
inline double angle_from_slide(double s, const TrussParameters& p) {
  return std::acos(std::clamp((p.frame_side * p.frame_side - s * s) / (2.0 * p.bar_length * s), -1.0, 1.0));
}

/// What a member is, for drawing, output and the README's joint table.
enum class MemberKind { frame_rod, cross_bar, side_diagonal, face_diagonal };

struct Member {
  MemberKind kind;
  std::string name;  ///< e.g. "frame 1 right", "bay 0 bar y0 z1", "bay 1 side diagonal y1"
  int beam = 0;
};

/// A sliding side diagonal: its joint, and the driver of its bay's side (case 2).
struct TrussSlider {
  const joints::SlidingJoint* joint = nullptr;  ///< owned by TrussUnit::joints
  int bay = 0, side = 0;                         ///< bay k, face Y = a·side
  double stop = 0.0;                             ///< ζ where it locks (the carrier's far end)
  /// The cross-bar node whose rotation about Y is β (case 2 drives it): the bar of this face
  /// that starts at the diagonal's hinge corner.
  int driven_node = 0;
};

/// The model, its joints, and where things are.
struct TrussUnit {
  TrussParameters parameters;
  core::Model model;
  solvers::ConstraintList joints;
  std::vector<Member> members;
  std::array<TrussSlider, 4> sliders;
  int d_node = 0;  ///< the node at D (frame 2's rod end at its upper corner Y = 0)
};

/// Builds the folded unit at β₀, at rest, without gravity and without drivers (see
/// add_deployment_drivers and main.cpp for the two cases of 003).
inline TrussUnit build_truss_unit(const TrussParameters& parameters) {
  TrussUnit unit;
  unit.parameters = parameters;
  const TrussParameters& p = parameters;
  core::Model& model = unit.model;
  const double beta = p.initial_angle, a = p.frame_side;
  const core::CrossSection section =
      core::CrossSection::tube(p.outer_diameter, p.inner_diameter, p.material.poisson_ratio);
  const core::SectionStiffness stiffness = core::SectionStiffness::from(p.material, section);
  const core::SectionInertia inertia = core::SectionInertia::from(p.material, section);
  // A member from `from` to `to`; its section axes ξ2 = Y where the member is ⊥ Y (the hinge axis
  // of 003), ξ3 = Z for the rods along Y (the tube is round: the choice is for the joints' record).
  const auto add_member = [&](MemberKind kind, std::string name, const Eigen::Vector3d& from,
                              const Eigen::Vector3d& to) {
    const Eigen::Vector3d t = (to - from).normalized(), across = t.cross(Eigen::Vector3d::UnitY());
    const Eigen::Vector3d hint = across.norm() > 0.1 ? across : Eigen::Vector3d::UnitZ();
    const int beam = core::add_beam(model, {.centerline = iga::straight_line<3>(from, to, p.elements, p.degree),
                                     .stiffness = stiffness, .inertia = inertia, .section_axis_hint = hint});
    unit.members.push_back({kind, std::move(name), beam});
    return beam;
  };
  const auto first_node = [&](int beam) { return core::beam(model, beam).node(0); };
  const auto last_node = [&](int beam) {
    const core::GeometricallyExactBeam& b = core::beam(model, beam);
    return b.node(b.control_point_count() - 1);
  };
  const Eigen::Vector3d Y = Eigen::Vector3d::UnitY();

  // 1. The frames: rods bottom (z = 0) and top (z = 1) from y = 0 to 1, left (y = 0) and right
  //    (y = 1) from z = 0 to 1; the corner node of (y, z) is the vertical rod's end there.
  std::array<std::array<std::array<int, 2>, 2>, 3> corner_node{};  // [frame][y][z]
  std::array<std::array<int, 2>, 3> vertical_rod{};                // [frame][y]
  std::vector<std::pair<int, int>> frame_clamps;                   // node pairs at the corners
  for (int k = 0; k < 3; ++k) {
    const std::string frame = "frame " + std::to_string(k) + " ";
    std::array<int, 2> horizontal{};
    for (int z = 0; z < 2; ++z)
      horizontal[z] = add_member(MemberKind::frame_rod, frame + (z ? "top" : "bottom"),
                                 corner(k, 0, z, beta, p), corner(k, 1, z, beta, p));
    for (int y = 0; y < 2; ++y) {
      vertical_rod[k][y] = add_member(MemberKind::frame_rod, frame + (y ? "right" : "left"),
                                      corner(k, y, 0, beta, p), corner(k, y, 1, beta, p));
      for (int z = 0; z < 2; ++z) {
        corner_node[k][y][z] = z ? last_node(vertical_rod[k][y]) : first_node(vertical_rod[k][y]);
        frame_clamps.emplace_back(corner_node[k][y][z], y ? last_node(horizontal[z]) : first_node(horizontal[z]));
      }
    }
  }
  const core::Configuration& q0 = model.state();
  //    Frame 0 is fixed; the others are clamped rigid at their corners.
  for (int rod = 0; rod < 4; ++rod) {  // the four rods of frame 0 come first
    const core::GeometricallyExactBeam& b = core::beam(model, unit.members[rod].beam);
    for (int i = 0; i < b.control_point_count(); ++i) model.fix(b.node(i));
  }
  const auto hinge = [&](int bar_node, int frame_node) {
    unit.joints.push_back(std::make_unique<joints::RevoluteJoint>(
        joints::Attachment{bar_node}, joints::attach_at(frame_node, q0.position[bar_node], q0), Y, q0));
  };
  for (std::size_t c = 4; c < frame_clamps.size(); ++c)  // frame 0's corners are fixed already
    unit.joints.push_back(std::make_unique<joints::ClampJoint>(
        joints::Attachment{frame_clamps[c].first}, joints::Attachment{frame_clamps[c].second}, q0));

  // 2. The bays: four cross-bars hinged about Y at both frames, the face diagonals hinged about
  //    Y, the side diagonals hinged at frame k and sliding on frame k + 1's vertical rods.
  int slider = 0;
  for (int bay = 0; bay < 2; ++bay) {
    const std::string name = "bay " + std::to_string(bay) + " ";
    std::array<std::array<int, 2>, 2> bar{};  // [y][z]
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z) {
        bar[y][z] = add_member(MemberKind::cross_bar,
                               name + "bar y" + std::to_string(y) + " z" + std::to_string(z),
                               corner(bay, y, z, beta, p), corner(bay + 1, y, z, beta, p));
        hinge(first_node(bar[y][z]), corner_node[bay][y][z]);
        hinge(last_node(bar[y][z]), corner_node[bay + 1][y][z]);
      }
    for (int z = 0; z < 2; ++z) {
      const int diagonal = add_member(MemberKind::face_diagonal, name + (z ? "top" : "bottom") + " diagonal",
                                      corner(bay, 0, z, beta, p), corner(bay + 1, 1, z, beta, p));
      hinge(first_node(diagonal), corner_node[bay][0][z]);
      hinge(last_node(diagonal), corner_node[bay + 1][1][z]);
    }
    //   The side diagonals: hinged at the corner the bay's bars leave from at the "low" side of
    //   the fold (z = 0 in the rising bay 0, z = 1 in the descending bay 1); the sliding end at
    //   distance s from the carrier's end where the bar from that corner arrives.
    const int hinge_z = bay == 0 ? 0 : 1;
    const double s = slide_distance(beta, p);
    for (int y = 0; y < 2; ++y) {
      const Eigen::Vector3d start = corner(bay, y, hinge_z, beta, p);
      const Eigen::Vector3d end = corner(bay + 1, y, hinge_z, beta, p) + fold_sign(bay) * s * Eigen::Vector3d::UnitZ();
      const int diagonal = add_member(MemberKind::side_diagonal, name + "side diagonal y" + std::to_string(y), start, end);
      hinge(first_node(diagonal), corner_node[bay][y][hinge_z]);
      //   ζ runs along the carrier (frame k + 1's vertical rod, from z = 0 to z = a): the slider
      //   starts at ζ₀ = s (bay 0) or a − s (bay 1) and locks at the far end a (bay 0) or 0 (bay 1).
      const bool rising = bay == 0;
      auto joint = std::make_unique<joints::SlidingJoint>(
          joints::SlidingJointParameters{
              .slider = joints::Attachment{last_node(diagonal)},
              .carrier = core::beam_centerline(model, vertical_rod[bay + 1][y]),
              .zeta = rising ? s : a - s,
              .lower_stop = rising ? std::nullopt : std::optional<double>(0.0),
              .upper_stop = rising ? std::optional<double>(a) : std::nullopt,
              .name = name + "side diagonal y" + std::to_string(y)},
          model);
      unit.sliders[slider] = {.joint = joint.get(), .bay = bay, .side = y, .stop = rising ? a : 0.0,
                              .driven_node = first_node(bar[y][hinge_z])};
      unit.joints.push_back(std::move(joint));
      ++slider;
    }
  }
  unit.d_node = corner_node[2][0][1];
  return unit;
}

/// Case 2 of 003 §5.3: the four β_i driven synchronously by `law` from β₀ to β_f = 90° in t_f.
/// Each driver turns the cross-bar at its side diagonal's hinge about Y (in the ideal mechanism
/// the frames only translate, so the bar's rotation is the hinge angle β − β₀; bay 1 folds the
/// other way and turns by −(β − β₀)). A driver hands over to its slider's lock: it is released at
/// the step after which the slider locked at the carrier's end (joints::ActiveUntil, listed after
/// the sliding joints so both switch at the same step) — from then on the lock holds the
/// deployed shape, and a driver kept on would hold the same motion a second time.
inline void add_deployment_drivers(TrussUnit& unit, const std::string& law, double t_f) {
  const double beta0 = unit.parameters.initial_angle, beta_f = std::numbers::pi / 2.0;
  const joints::TimeFunction angle = joints::motion_law(law, beta_f - beta0, t_f);  // 003 eqs. 54-57
  for (const TrussSlider& slider : unit.sliders) {
    const double sign = fold_sign(slider.bay);
    joints::TimeFunction turn{.value = [=](double t) { return sign * angle.value(t); },
                              .first_derivative = [=](double t) { return sign * angle.first_derivative(t); },
                              .second_derivative = [=](double t) { return sign * angle.second_derivative(t); }};
    const joints::SlidingJoint* joint = slider.joint;
    unit.joints.push_back(std::make_unique<joints::ActiveUntil>(
        std::make_unique<joints::AngleDriver>(slider.driven_node, Eigen::Vector3d::UnitY(), std::move(turn),
                                              unit.model.state()),
        [joint](const core::Configuration&, double) { return joint->locked(); },
        "beta driver of " + joint->name()));
  }
}

}  // namespace spar::examples
