#include "hsfm.h"

#include <algorithm>

namespace crowdsim::hsfm {

Vec2 PersonForce(const Vec2& r_ij, double radii, const Vec2& v_i, const Vec2& v_j,
                 const Constants& c) {
  const double d = r_ij.norm();
  if (d <= 0.0) return Vec2::Zero();
  const Vec2 n = r_ij / d;
  const double overlap = std::max(0.0, radii - d);
  Vec2 f = (c.a * std::exp((radii - d) / c.b) + c.k_body * overlap) * n;
  if (overlap > 0.0) {
    const Vec2 t(-n.y(), n.x());
    f += c.k_friction * overlap * (v_j - v_i).dot(t) * t;
  }
  return f;
}

Vec2 WallForce(const Vec2& r_from_wall, double radius, const Vec2& v, const Constants& c) {
  const double d = r_from_wall.norm();
  if (d <= 0.0) return Vec2::Zero();
  const Vec2 n = r_from_wall / d;
  const double overlap = std::max(0.0, radius - d);
  Vec2 f = (c.a_wall * std::exp((radius - d) / c.b_wall) + c.k_body * overlap) * n;
  if (overlap > 0.0) {
    const Vec2 t(-n.y(), n.x());
    f -= c.k_friction * overlap * v.dot(t) * t;
  }
  return f;
}

Vec2 GroupCohesion(const Vec2& to_centre, const Body& body, const GroupConstants& g) {
  const double d = to_centre.norm();
  if (d <= 0.0) return Vec2::Zero();
  const double ahead = to_centre.dot(body.Heading());
  const double left = to_centre.dot(body.Left());
  // The paper's step functions: each part acts only beyond its distance.
  return Vec2(std::abs(ahead) > g.d_forward ? g.k_forward * ahead / d : 0.0,
              std::abs(left) > g.d_sideways ? g.k_sideways * left / d : 0.0);
}

void Advance(Body* body, const Vec2& f0, const Vec2& fe, const Vec2& group, double h,
             double max_speed, const Constants& c) {
  const Vec2 total = f0 + fe;
  const double u_forward = total.dot(body->Heading()) + group.x();
  const double u_sideways = c.k_o * fe.dot(body->Left()) - c.k_d * body->sideways + group.y();
  const Vec2 turn = c.turn_to_total ? total : f0;
  const double force = turn.norm();
  const double error =
      force > 0.0 ? std::remainder(body->theta - std::atan2(turn.y(), turn.x()), 2.0 * M_PI) : 0.0;
  // Velocities first, then the pose from the new velocities (semi-implicit Euler).
  body->forward += h * u_forward / c.mass;
  body->sideways += h * u_sideways / c.mass;
  const double speed = std::hypot(body->forward, body->sideways);
  if (speed > max_speed) {
    body->forward *= max_speed / speed;
    body->sideways *= max_speed / speed;
  }
  body->omega += h * TurnAcceleration(error, body->omega, force, c);
  body->theta = std::remainder(body->theta + h * body->omega, 2.0 * M_PI);
  body->position += h * body->Velocity();
}

}  // namespace crowdsim::hsfm
