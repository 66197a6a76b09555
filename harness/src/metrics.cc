#include "crowdsim/metrics.h"

namespace crowdsim {

EpisodeRecord ToRecord(const EpisodeResult& r) {
  return EpisodeRecord{r.status,       r.time,
                       r.steps,        r.danger_steps,
                       r.path_length,  r.min_human_distance,
                       r.discounted_return, r.decision_time_us};
}

RowMetrics Aggregate(std::span<const EpisodeRecord> episodes, double time_limit) {
  RowMetrics m;
  m.episodes = static_cast<int>(episodes.size());
  if (episodes.empty()) return m;
  int success = 0, coll_h = 0, coll_o = 0, timeout = 0, error = 0;
  long long steps = 0, danger = 0;
  double nav_time = 0.0, path = 0.0, ret = 0.0, decision = 0.0, min_dist = 0.0;
  int with_humans = 0;
  for (const auto& e : episodes) {
    switch (e.status) {
      case EpisodeStatus::kSuccess:
        ++success;
        nav_time += e.time;
        path += e.path_length;
        break;
      case EpisodeStatus::kCollisionHuman: ++coll_h; break;
      case EpisodeStatus::kCollisionObstacle: ++coll_o; break;
      case EpisodeStatus::kTimeout: ++timeout; break;
      default: ++error; break;
    }
    steps += e.steps;
    danger += e.danger_steps;
    ret += e.discounted_return;
    decision += e.decision_time_us;
    if (e.min_human_distance < kInfinity) {
      min_dist += e.min_human_distance;
      ++with_humans;
    }
  }
  const double n = static_cast<double>(episodes.size());
  m.success_rate = success / n;
  m.collision_human_rate = coll_h / n;
  m.collision_obstacle_rate = coll_o / n;
  m.collision_rate = (coll_h + coll_o) / n;
  m.timeout_rate = timeout / n;
  m.policy_error_rate = error / n;
  m.nav_time = success > 0 ? nav_time / success : time_limit;
  m.path_length = success > 0 ? path / success : 0.0;
  m.danger_frequency = steps > 0 ? static_cast<double>(danger) / static_cast<double>(steps) : 0.0;
  m.discounted_return = ret / n;
  m.decision_time_us = decision / n;
  m.min_human_distance = with_humans > 0 ? min_dist / with_humans : 0.0;
  return m;
}

}  // namespace crowdsim
