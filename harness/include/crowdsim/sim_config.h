// Episode settings (paper defaults).
#pragma once

namespace crowdsim {

/// Simulation and reward settings; every field is a suite key under `sim:`.
struct SimConfig {
  double time_step = 0.25;         ///< s
  double time_limit = 25.0;        ///< s; the episode times out when time reaches it
  double goal_radius = 0.2;        ///< m; success when the robot centre is this close (CrowdNav: 0.3)
  double discomfort_dist = 0.2;    ///< m; surface distance counted as danger
  double robot_radius = 0.3;       ///< m
  double robot_v_pref = 1.0;       ///< m/s
  double human_radius = 0.3;       ///< m
  double human_v_pref = 1.0;       ///< m/s
  bool robot_visible = false;      ///< humans react to the robot (paper: false)
  double success_reward = 1.0;
  double collision_penalty = -0.25;
  double discomfort_penalty_factor = 0.5;
  double gamma = 0.9;              ///< discount per second at v_pref (CrowdNav: gamma^(dt*v_pref))
};

}  // namespace crowdsim
