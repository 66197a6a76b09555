// Episode settings (paper defaults) and kSimFields, the one list `sim:` reading, the config hash
// and manifest.json follow.
#pragma once

#include <variant>

#include "crowdsim/export.h"
#include "crowdsim/geometry.h"  // kInfinity

namespace crowdsim {

/// Simulation and reward settings, each a suite key under `sim:`. Other defaults take these as
/// SimConfig{}.<member>.
struct CROWDSIM_SDK_API SimConfig {
  double time_step = 0.25;       ///< s
  double time_limit = 25.0;      ///< s; the episode times out when time reaches it
  double goal_radius = 0.2;      ///< m; success when the robot centre is this close (CrowdNav: 0.3)
  double discomfort_dist = 0.2;  ///< m; surface distance counted as danger
  double robot_radius = 0.3;     ///< m
  double robot_v_pref = 1.0;     ///< m/s
  double human_radius = 0.3;     ///< m
  double human_v_pref = 1.0;     ///< m/s
  bool robot_visible = false;    ///< humans react to the robot (paper: false)
  double success_reward = 1.0;
  double collision_penalty = -0.25;
  double discomfort_penalty_factor = 0.5;
  double gamma = 0.9;  ///< discount per second at v_pref (CrowdNav: gamma^(dt*v_pref))
};

/// One `sim:` setting: its key, its member and, for a number, the values a file may give it.
struct CROWDSIM_SDK_API SimField {
  const char* key;
  std::variant<double SimConfig::*, bool SimConfig::*> member;
  double lo = 0.0;  ///< numbers: the valid range [lo, hi]
  double hi = 0.0;
  bool lo_open = false;  ///< numbers: lo itself is not valid
};

/// Every setting, in canonical-text and manifest order. Changing an order or key changes every
/// config hash: stored results cannot resume.
inline constexpr SimField kSimFields[] = {
    {"time_step", &SimConfig::time_step, 0.0, 10.0, true},
    {"time_limit", &SimConfig::time_limit, 0.0, 1e6, true},
    {"goal_radius", &SimConfig::goal_radius, 0.0, 10.0, true},
    {"discomfort_dist", &SimConfig::discomfort_dist, 0.0, 10.0},
    {"robot_radius", &SimConfig::robot_radius, 0.0, 10.0, true},
    {"robot_v_pref", &SimConfig::robot_v_pref, 0.0, 100.0, true},
    {"human_radius", &SimConfig::human_radius, 0.0, 10.0, true},
    {"human_v_pref", &SimConfig::human_v_pref, 0.0, 100.0, true},
    {"robot_visible", &SimConfig::robot_visible},
    {"success_reward", &SimConfig::success_reward, -kInfinity, kInfinity},
    {"collision_penalty", &SimConfig::collision_penalty, -kInfinity, kInfinity},
    {"discomfort_penalty_factor", &SimConfig::discomfort_penalty_factor, 0.0, kInfinity},
    {"gamma", &SimConfig::gamma, 0.0, 1.0, true},
};

}  // namespace crowdsim
