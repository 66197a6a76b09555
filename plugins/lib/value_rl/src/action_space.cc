#include "value_rl/action_space.h"

#include <cmath>
#include <numbers>

namespace crowdsim::value_rl {

std::vector<double> ExponentialSpeeds(int speed_samples, double v_pref) {
  std::vector<double> speeds;
  for (int i = 0; i < speed_samples; ++i) {
    speeds.push_back((std::exp((i + 1.0) / speed_samples) - 1.0) / (std::numbers::e - 1.0) *
                     v_pref);
  }
  return speeds;
}

std::vector<Action> BuildActionSpace(int speed_samples, int rotation_samples, bool stop_action,
                                     double v_pref) {
  std::vector<Action> actions;
  if (stop_action) actions.push_back(Action{});
  const std::vector<double> speeds = ExponentialSpeeds(speed_samples, v_pref);
  for (int k = 0; k < rotation_samples; ++k) {
    const double rot = 2.0 * std::numbers::pi * k / rotation_samples;
    for (double speed : speeds) {
      actions.push_back(Action{Vec2(speed * std::cos(rot), speed * std::sin(rot))});
    }
  }
  return actions;
}

std::vector<Action> BuildUnicycleActionSpace(int speed_samples, int rotation_samples,
                                             bool stop_action, double v_pref, double time_step) {
  std::vector<Action> actions;
  if (stop_action) actions.push_back(Action::Command(0.0, 0.0));
  const std::vector<double> speeds = ExponentialSpeeds(speed_samples, v_pref);
  const double quarter = std::numbers::pi / 4.0;
  for (int k = 0; k < rotation_samples; ++k) {
    const double rot =
        rotation_samples == 1 ? 0.0 : -quarter + 2.0 * quarter * k / (rotation_samples - 1);
    for (double speed : speeds) actions.push_back(Action::Command(speed, rot / time_step));
  }
  return actions;
}

}  // namespace crowdsim::value_rl
