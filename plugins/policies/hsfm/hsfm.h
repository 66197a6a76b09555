// The Headed Social Force Model (Farina et al., PLoS ONE 12(1) e0169734, 2017): Helbing 2000's
// circular forces drive a body with a heading. Pure functions, each tested by its closed form.
#pragma once

#include <cmath>

#include "crowdsim/geometry.h"

namespace crowdsim::hsfm {

/// The model's constants (README.md gives each one's source).
struct Constants {
  double mass = 75.0;         ///< kg
  double tau = 0.5;           ///< s, relaxation time towards the desired velocity
  double a = 2000.0;          ///< N, strength of another person's repulsion
  double b = 0.08;            ///< m, its range
  double a_wall = 2000.0;     ///< N, strength of a rectangle's repulsion
  double b_wall = 0.08;       ///< m, its range
  double k_body = 1.2e5;      ///< kg/s^2, body compression while overlapping
  double k_friction = 2.4e5;  ///< kg/(m s), sliding friction while overlapping
  double k_o = 1.0;           ///< share of the interaction forces that pushes sideways
  double k_d = 500.0;         ///< kg/s, damping of the sideways velocity
  double k_lambda = 0.1;      ///< 1/(kg m): turning stiffness per newton of force
  double alpha = 3.0;         ///< ratio of the heading dynamics' two time constants
  bool turn_to_total = true;  ///< turn towards the total force (false: the driving force)
};

/// The group cohesion constants: forward and sideways strength, and the distances from the
/// group's centre beyond which each acts.
struct GroupConstants {
  double k_forward = 200.0;   ///< N
  double k_sideways = 200.0;  ///< N
  double d_forward = 1.0;     ///< m
  double d_sideways = 0.5;    ///< m
};

/// A person's body: where it is, where it faces, and its velocity in its own frame.
struct Body {
  Vec2 position = Vec2::Zero();  ///< m, world frame
  double theta = 0.0;            ///< rad, heading
  double omega = 0.0;            ///< rad/s
  double forward = 0.0;          ///< m/s along the heading
  double sideways = 0.0;         ///< m/s to its left

  Vec2 Heading() const { return Vec2(std::cos(theta), std::sin(theta)); }
  Vec2 Left() const { return Vec2(-std::sin(theta), std::cos(theta)); }
  Vec2 Velocity() const { return forward * Heading() + sideways * Left(); }
};

/// Force (N) towards the desired velocity: m (desired - v) / τ.
inline Vec2 DrivingForce(const Vec2& velocity, const Vec2& desired, const Constants& c) {
  return c.mass * (desired - velocity) / c.tau;
}

/// Force (N) on person i from person j, r_ij = p_i - p_j, radii summing to `radii`:
/// [A exp((r - d)/B) + k g(r - d)] n + κ g(r - d) ((v_j - v_i) · t) t, g(x) = max(x, 0),
/// n = r_ij / d, t = n turned by +90°.
Vec2 PersonForce(const Vec2& r_ij, double radii, const Vec2& v_i, const Vec2& v_j,
                 const Constants& c);

/// Force (N) on a person of `radius` walking at `v` from a rectangle whose nearest point lies
/// `r_from_wall` away: [A_w exp((r - d)/B_w) + k g(r - d)] n - κ g(r - d) (v · t) t.
Vec2 WallForce(const Vec2& r_from_wall, double radius, const Vec2& v, const Constants& c);

/// Angular acceleration (rad/s^2) of the heading `error` rad off the force's direction under
/// force magnitude `force` (N): I θ'' = -k_θ error - k_ω ω with k_θ = I k_λ |f| and
/// k_ω = I (1 + α) sqrt(k_λ |f| / α); the inertia I cancels.
inline double TurnAcceleration(double error, double omega, double force, const Constants& c) {
  const double stiffness = c.k_lambda * force;
  return -stiffness * error - (1.0 + c.alpha) * std::sqrt(stiffness / c.alpha) * omega;
}

/// Group cohesion inputs (N; x forward, y sideways) of a member whose group's centre lies
/// p = `to_centre` away: k1g (p/|p|) · r_f when |p · r_f| > d_f; k2g (p/|p|) · r_o when
/// |p · r_o| > d_o (the authors' names).
Vec2 GroupCohesion(const Vec2& to_centre, const Body& body, const GroupConstants& g);

/// One semi-implicit Euler step of `h` s: driving force `f0`, interaction forces `fe`, group
/// inputs `group` (body frame). Forward: (f0 + fe) · heading; sideways: k_o fe · left - k_d v_o;
/// the heading turns towards f0 + fe (or f0). The body speed stays at most `max_speed`.
void Advance(Body* body, const Vec2& f0, const Vec2& fe, const Vec2& group, double h,
             double max_speed, const Constants& c);

}  // namespace crowdsim::hsfm
