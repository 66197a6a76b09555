// The forces of Helbing & Molnár's social force model (Phys. Rev. E 51, 4282, 1995): pure
// functions of one pedestrian's surroundings, each tested against its closed form.
#pragma once

#include <cmath>
#include <span>

#include "crowdsim/geometry.h"
#include "walking/contact.h"

namespace crowdsim::social_force {

/// The model's constants (README.md gives each one's source).
struct Constants {
  double tau = 0.5;               ///< s, relaxation time towards the desired velocity
  double v0_ped = 2.1;            ///< m^2/s^2, strength of another pedestrian's potential
  double sigma = 0.3;             ///< m, range of that potential
  double step_time = 2.0;         ///< s, Δt: another's step width is its speed times this
  double u0_wall = 10.0;          ///< m^2/s^2, strength of an obstacle's potential
  double r_wall = 0.2;            ///< m, range of that potential
  double cos_view = -0.17364817;  ///< cos(φ), φ = 100°: half the field of view (2φ = 200°)
  double out_of_view = 0.5;       ///< c, weight of a pedestrian outside the field of view
};

/// The group forces' constants: Moussaïd et al. 2010's forces (PLoS ONE 5(4) e10047) with
/// PySocialForce's factors (README.md).
struct GroupConstants {
  double coherence = 2.0;       ///< m/s^2, pull towards the group's centre beyond (N - 1) / 2 m
  double repulsion = 1.0;       ///< m/s^2, push from each member closer than repulsion_dist
  double repulsion_dist = 0.5;  ///< m between centres
  double gaze = 3.0;            ///< m/s^2 per rad, turn towards the others beyond half_view
  double half_view = 1.7453292519943295;  ///< rad (100°) between walking direction and them
};

/// The group forces on a member at `position` walking along unit `e` (its desired direction;
/// zero: no gaze force), with the group's other members at `others` (empty: no force):
///  - coherence: g.coherence towards the centre of all N members when farther than (N - 1) / 2;
///  - repulsion: g.repulsion away from each other member closer than g.repulsion_dist;
///  - gaze: -g.gaze (α - half_view) e when the others' centre is α > half_view off e.
Vec2 GroupForce(const Vec2& position, const Vec2& e, std::span<const Vec2> others,
                const GroupConstants& g);

/// Acceleration towards `desired` (velocity, m/s) from `velocity` within `tau`: (v0 e - v) / τ.
inline Vec2 DrivingForce(const Vec2& velocity, const Vec2& desired, double tau) {
  return (desired - velocity) / tau;
}

/// Repulsion on pedestrian a from pedestrian b: -∇ of V0 exp(-b/σ), where the semi-minor axis b
/// of the ellipse through a, with foci at b and at b's next step s = |v_b| Δt along e_b, is
/// 2b = sqrt((|r| + |r - s e_b|)^2 - s^2), r = r_a - r_b.
Vec2 PedestrianRepulsion(const Vec2& r_ab, const Vec2& velocity_b, const Constants& c);

/// Weight of a force `f` felt by a pedestrian heading along unit `e`: 1 when its source lies
/// within the field of view (e · (-f) >= |f| cos φ), else c.
inline double ViewWeight(const Vec2& e, const Vec2& f, const Constants& c) {
  return e.dot(-f) >= f.norm() * c.cos_view ? 1.0 : c.out_of_view;
}

/// Repulsion from an obstacle: -∇ of U0 exp(-|r|/R), r from the obstacle's nearest point to the
/// pedestrian (zero when the pedestrian stands on it).
inline Vec2 WallRepulsion(const Vec2& r_from_wall, const Constants& c) {
  const double d = r_from_wall.norm();
  if (d <= 0.0) return Vec2::Zero();
  return r_from_wall * (c.u0_wall / c.r_wall * std::exp(-d / c.r_wall) / d);
}

using walking::NearestPoint;

}  // namespace crowdsim::social_force
