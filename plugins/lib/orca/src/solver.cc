#include "orca/solver.h"

#include <algorithm>
#include <cmath>

#include "orca/agent_lines.h"
#include "orca/geometry.h"

namespace crowdsim::orca {
namespace {

// Left normal: the feasible side of a line through `point` along `direction`, moved out by
// `offset`.
OrcaLine ShiftedLine(const Vec2& point, const Vec2& direction, double offset) {
  return OrcaLine{point + offset * Vec2(-direction.y(), direction.x()), direction};
}

void AddObstacleLines(const OrcaAgent& self, const OrcaObstacles& obstacles,
                      const OrcaParams& params, std::vector<ObstacleNeighbor>* near_scratch,
                      std::vector<OrcaLine>* lines) {
  std::vector<ObstacleNeighbor>& near = *near_scratch;
  obstacles.Query(self.position, ObstacleRange(params, self.radius), &near);
  if (near.empty()) return;

  const std::span<const ObstacleVertex> verts = obstacles.vertices();
  const double inv_tau = 1.0 / params.time_horizon_obst;
  const double r = self.radius;
  const double r_sq = r * r;
  const Vec2& v = self.velocity;

  for (const ObstacleNeighbor& n : near) {
    const ObstacleVertex* v1 = &verts[n.vertex];
    const ObstacleVertex* v2 = &verts[v1->next];
    const Vec2 rp1 = v1->point - self.position;
    const Vec2 rp2 = v2->point - self.position;

    // Skip an edge whose velocity obstacle an earlier (nearer) line already excludes.
    bool covered = false;
    for (const OrcaLine& line : *lines) {
      if (Det(inv_tau * rp1 - line.point, line.direction) - inv_tau * r >= -kEpsilon &&
          Det(inv_tau * rp2 - line.point, line.direction) - inv_tau * r >= -kEpsilon) {
        covered = true;
        break;
      }
    }
    if (covered) continue;

    const double dist_sq1 = rp1.squaredNorm();
    const double dist_sq2 = rp2.squaredNorm();
    const Vec2 edge = v2->point - v1->point;
    const double s = (-rp1).dot(edge) / edge.squaredNorm();
    const double dist_sq_line = (-rp1 - s * edge).squaredNorm();

    // Already touching: forbid any velocity with a component into the obstacle.
    if (s < 0.0 && dist_sq1 <= r_sq) {
      if (v1->convex) lines->push_back({Vec2::Zero(), Vec2(-rp1.y(), rp1.x()).normalized()});
      continue;
    }
    if (s > 1.0 && dist_sq2 <= r_sq) {
      // The next edge handles this vertex unless it faces away from the agent.
      if (v2->convex && Det(rp2, v2->direction) >= 0.0) {
        lines->push_back({Vec2::Zero(), Vec2(-rp2.y(), rp2.x()).normalized()});
      }
      continue;
    }
    if (s >= 0.0 && s <= 1.0 && dist_sq_line <= r_sq) {
      lines->push_back({Vec2::Zero(), -v1->direction});
      continue;
    }

    // No collision: the legs of the truncated velocity obstacle.
    Vec2 left_leg;
    Vec2 right_leg;
    if (s < 0.0 && dist_sq_line <= r_sq) {
      // Seen obliquely, only the left vertex matters.
      if (!v1->convex) continue;
      v2 = v1;
      left_leg = LeftTangent(rp1, r);
      right_leg = RightTangent(rp1, r);
    } else if (s > 1.0 && dist_sq_line <= r_sq) {
      if (!v2->convex) continue;
      v1 = v2;
      left_leg = LeftTangent(rp2, r);
      right_leg = RightTangent(rp2, r);
    } else {
      left_leg = v1->convex ? LeftTangent(rp1, r) : Vec2(-v1->direction);
      right_leg = v2->convex ? RightTangent(rp2, r) : Vec2(v1->direction);
    }

    // A leg pointing into the neighbouring edge is replaced by that edge ("foreign"): the
    // neighbouring edge's own line is the binding one there.
    const ObstacleVertex& left_neighbour = verts[v1->prev];
    bool left_foreign = false;
    bool right_foreign = false;
    if (v1->convex && Det(left_leg, -left_neighbour.direction) >= 0.0) {
      left_leg = -left_neighbour.direction;
      left_foreign = true;
    }
    if (v2->convex && Det(right_leg, v2->direction) <= 0.0) {
      right_leg = v2->direction;
      right_foreign = true;
    }

    const Vec2 left_cutoff = inv_tau * (v1->point - self.position);
    const Vec2 right_cutoff = inv_tau * (v2->point - self.position);
    const Vec2 cutoff_vec = right_cutoff - left_cutoff;
    const bool same_vertex = v1 == v2;
    const double t =
        same_vertex ? 0.5 : (v - left_cutoff).dot(cutoff_vec) / cutoff_vec.squaredNorm();
    const double t_left = (v - left_cutoff).dot(left_leg);
    const double t_right = (v - right_cutoff).dot(right_leg);

    // Project the current velocity on the nearest part of the truncated obstacle boundary.
    if ((t < 0.0 && t_left < 0.0) || (same_vertex && t_left < 0.0 && t_right < 0.0)) {
      const Vec2 d = v - left_cutoff;
      const Vec2 w = UnitOr(d, d.norm());
      lines->push_back({left_cutoff + r * inv_tau * w, Vec2(w.y(), -w.x())});
      continue;
    }
    if (t > 1.0 && t_right < 0.0) {
      const Vec2 d = v - right_cutoff;
      const Vec2 w = UnitOr(d, d.norm());
      lines->push_back({right_cutoff + r * inv_tau * w, Vec2(w.y(), -w.x())});
      continue;
    }

    const double dist_sq_cutoff = (t < 0.0 || t > 1.0 || same_vertex)
                                      ? kInfinity
                                      : (v - (left_cutoff + t * cutoff_vec)).squaredNorm();
    const double dist_sq_left =
        t_left < 0.0 ? kInfinity : (v - (left_cutoff + t_left * left_leg)).squaredNorm();
    const double dist_sq_right =
        t_right < 0.0 ? kInfinity : (v - (right_cutoff + t_right * right_leg)).squaredNorm();

    if (dist_sq_cutoff <= dist_sq_left && dist_sq_cutoff <= dist_sq_right) {
      lines->push_back(ShiftedLine(left_cutoff, -v1->direction, r * inv_tau));
    } else if (dist_sq_left <= dist_sq_right) {
      if (!left_foreign) lines->push_back(ShiftedLine(left_cutoff, left_leg, r * inv_tau));
    } else {
      if (!right_foreign) lines->push_back(ShiftedLine(right_cutoff, -right_leg, r * inv_tau));
    }
  }
}

void FillLines(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
               const OrcaObstacles& obstacles, const OrcaParams& params, double time_step,
               std::vector<ObstacleNeighbor>* near_scratch, std::vector<OrcaLine>* lines,
               std::size_t* num_obstacle_lines) {
  if (obstacles.empty()) {
    // Not cleared first: the size mostly repeats from decision to decision, so the resize
    // rarely constructs lines only to have them overwritten.
    lines->resize(neighbours.size());
    *num_obstacle_lines = 0;
    AddAgentLines(self, neighbours, params, time_step, lines->data());
    return;
  }
  lines->clear();
  AddObstacleLines(self, obstacles, params, near_scratch, lines);
  *num_obstacle_lines = lines->size();
  lines->resize(*num_obstacle_lines + neighbours.size());
  AddAgentLines(self, neighbours, params, time_step, lines->data() + *num_obstacle_lines);
}

}  // namespace

void BuildOrcaLines(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                    const OrcaObstacles& obstacles, const OrcaParams& params, double time_step,
                    std::vector<OrcaLine>* lines, std::size_t* num_obstacle_lines) {
  std::vector<ObstacleNeighbor> near;
  FillLines(self, neighbours, obstacles, params, time_step, &near, lines, num_obstacle_lines);
}

Vec2 ComputeOrcaVelocity(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                         const OrcaObstacles& obstacles, const OrcaParams& params,
                         const Vec2& pref_velocity, double time_step, OrcaSolveInfo* info) {
  thread_local OrcaSolveScratch scratch;
  return ComputeOrcaVelocity(self, neighbours, obstacles, params, pref_velocity, time_step,
                             &scratch, info);
}

Vec2 ComputeOrcaVelocity(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                         const OrcaObstacles& obstacles, const OrcaParams& params,
                         const Vec2& pref_velocity, double time_step, OrcaSolveScratch* scratch,
                         OrcaSolveInfo* info) {
  const std::vector<OrcaLine>& lines = scratch->lines;
  std::size_t num_obstacle_lines = 0;
  FillLines(self, neighbours, obstacles, params, time_step, &scratch->near, &scratch->lines,
            &num_obstacle_lines);
  Vec2 result = Vec2::Zero();
  const std::size_t fail =
      SolveLinearProgram2(lines, params.max_speed, pref_velocity, false, &result);
  if (fail < lines.size()) {
    SolveLinearProgram3(lines, num_obstacle_lines, fail, params.max_speed, &result);
  }
  if (info != nullptr) *info = {lines.size(), num_obstacle_lines, fail == lines.size()};
  return result;
}

}  // namespace crowdsim::orca
