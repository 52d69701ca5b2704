#pragma once
// The flexible slider-crank of 003 §5.1, Table 1: shared by the example and its validation test.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <algorithm>
#include <memory>

namespace spar::examples {

/// The mechanism: its model (two rods and the slider), its joints, and where things are.
struct SliderCrank {
  static constexpr double crank_length = 0.3;    // Rod I [m]
  static constexpr double coupler_length = 0.6;  // Rod II [m]
  static constexpr double slider_mass = 0.1;     // [kg]
  static constexpr double driving_moment = 500;  // M about Z on Rod I [N m]

  core::Model model;
  solvers::ConstraintList joints;
  int crank = 0, coupler = 0;  // beam indices
  int slider_node = 0;
};

/// 003 §5.1: Rod I from the origin to (0.3, 0, 0) and Rod II on to (0.9, 0, 0), steel
/// 0.03 × 0.03 m (E = 2.1e11 Pa, ν = 0.3, ρ = 7850 kg/m³), `elements` cubic C² elements each;
/// spherical joints ground–Rod I, Rod I–Rod II, Rod II–slider; the slider (0.1 kg; the inertia of
/// a 2 cm cube, irrelevant since its rotation is locked) on the X axis; M = 500 N·m about Z on
/// Rod I's root section; gravity 9.81 m/s² along −Y (our reading: in the plane of motion).
/// `drive_rise_time` > 0 ramps the moment linearly from 0 to M over that time instead of
/// switching it on at t = 0 as the paper does: a step moment on the root section, whose rotary
/// inertia is tiny, rings its rotation mode (ω ≈ 2.6e5 rad/s, unresolved by any step here), and
/// the stored angular velocity of that control point samples the ringing (docs/dynamics.md D9).
inline SliderCrank build_slider_crank(int elements, double drive_rise_time = 0.0) {
  SliderCrank s;
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection square = core::CrossSection::rectangle(0.03, 0.03, 0.3);
  const core::SectionStiffness stiffness = core::SectionStiffness::from(steel, square);
  const core::SectionInertia inertia = core::SectionInertia::from(steel, square);
  const Eigen::Vector3d origin(0, 0, 0), elbow(SliderCrank::crank_length, 0, 0),
      end(SliderCrank::crank_length + SliderCrank::coupler_length, 0, 0);
  s.crank = core::add_beam(s.model, {.centerline = iga::straight_line<3>(origin, elbow, elements, 3),
                              .stiffness = stiffness, .inertia = inertia});
  s.coupler = core::add_beam(s.model, {.centerline = iga::straight_line<3>(elbow, end, elements, 3),
                                .stiffness = stiffness, .inertia = inertia});
  const core::GeometricallyExactBeam& crank = core::beam(s.model, s.crank);
  const core::GeometricallyExactBeam& coupler = core::beam(s.model, s.coupler);
  const int crank_root = crank.node(0), crank_tip = crank.node(crank.control_point_count() - 1);
  const int coupler_root = coupler.node(0), coupler_tip = coupler.node(coupler.control_point_count() - 1);
  s.slider_node = core::rigid_body(s.model, core::add_rigid_body(s.model,
      {.center_of_mass = end, .mass = SliderCrank::slider_mass,
       .inertia = Eigen::Matrix3d::Identity() * SliderCrank::slider_mass * 0.02 * 0.02 / 6})).node;

  core::LoadHistory rise;
  if (drive_rise_time > 0.0)
    rise = [drive_rise_time](double t) { return std::min(1.0, t / drive_rise_time); };
  core::add_load(s.model, core::NodalMoment{.node = crank_root,
                                     .moment = Eigen::Vector3d(0, 0, SliderCrank::driving_moment),
                                     .frame = core::MomentFrame::inertial},
                   rise);
  s.model.set_gravity(Eigen::Vector3d(0, -9.81, 0));

  const core::Configuration& q0 = s.model.state();
  using joints::Attachment;
  s.joints.push_back(std::make_unique<joints::SphericalJoint>(Attachment{crank_root}, Attachment{-1, origin}, q0));
  s.joints.push_back(std::make_unique<joints::SphericalJoint>(Attachment{crank_tip}, Attachment{coupler_root}, q0));
  s.joints.push_back(std::make_unique<joints::SphericalJoint>(Attachment{coupler_tip}, Attachment{s.slider_node}, q0));
  s.joints.push_back(std::make_unique<joints::PrismaticJoint>(Attachment{s.slider_node}, origin,
                                                              Eigen::Vector3d::UnitX(), true, q0));
  return s;
}

/// A rod's deformation rate (003 §5.1): the distance of its midpoint from the midpoint of its
/// chord, over its length. The NURBS basis at the root, the middle and the tip is computed once
/// (the example takes the rate at every step); the positions are position_at's.
class DeformationRate {
public:
  DeformationRate(const core::GeometricallyExactBeam& rod, double length)
      : rod_(&rod), length_(length), root_(rod.centerline_point(0.0, 0)), middle_(rod.centerline_point(0.5, 0)),
        tip_(rod.centerline_point(1.0, 0)) {}

  /// The rod's midpoint x(u = 1/2).
  Eigen::Vector3d midpoint(const core::Configuration& q) const { return rod_->centerline_derivative(q, middle_, 0); }
  double operator()(const core::Configuration& q) const {
    const Eigen::Vector3d chord_middle =
        0.5 * (rod_->centerline_derivative(q, root_, 0) + rod_->centerline_derivative(q, tip_, 0));
    return (midpoint(q) - chord_middle).norm() / length_;
  }

private:
  const core::GeometricallyExactBeam* rod_;
  double length_;
  core::CenterlinePoint root_, middle_, tip_;
};

}  // namespace spar::examples
