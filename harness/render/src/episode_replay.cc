#include "crowdsim/render/episode_replay.h"

#include <cstdio>
#include <stdexcept>

#include "crowdsim/render/palette.h"

namespace crowdsim::render {
namespace {

std::string RowChoices(const Suite& suite) {
  std::string s = "valid: 1.." + std::to_string(suite.rows.size()) + " or a label:";
  for (const RowSpec& r : suite.rows) s += " " + r.label;
  return s;
}

bool ParseInt(const std::string& text, long* out) {
  if (text.empty()) return false;
  size_t used = 0;
  try {
    *out = std::stol(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size();
}

}  // namespace

size_t ResolveRow(const Suite& suite, const std::string& text) {
  for (size_t i = 0; i < suite.rows.size(); ++i) {
    if (suite.rows[i].label == text) return i;
  }
  long n = 0;
  if (ParseInt(text, &n)) {
    if (n >= 1 && n <= static_cast<long>(suite.rows.size())) return static_cast<size_t>(n - 1);
    throw std::invalid_argument("row " + text + " is out of range (" + RowChoices(suite) + ")");
  }
  throw std::invalid_argument("no row labelled '" + text + "' (" + RowChoices(suite) + ")");
}

int ResolveEpisode(const Suite& suite, const std::string& text) {
  long n = 0;
  const std::string range = "valid: 0.." + std::to_string(suite.episodes - 1) + ", the suite's " +
                            std::to_string(suite.episodes) + " episodes";
  if (!ParseInt(text, &n))
    throw std::invalid_argument("--episode '" + text + "' is not a whole number (" + range + ")");
  if (n < 0 || n >= suite.episodes) {
    // A run with --episodes N played episodes past the suite's count: they replay the same with
    // the count raised.
    throw std::invalid_argument("episode " + text + " is out of range (" + range +
                                (n >= suite.episodes ? "; for an episode of a run made with "
                                                       "--episodes N, add --set episodes=N"
                                                     : "") +
                                ")");
  }
  return static_cast<int>(n);
}

ReplayedEpisode ReplayForFigure(const Suite& suite, size_t row, int episode,
                                PluginRegistry& registry, std::optional<int> sensors_at) {
  Replay replay = ReplayEpisode(suite, row, episode, registry, /*record_trajectory=*/true);
  ReplayedEpisode out;
  out.row = row;
  out.episode = episode;
  out.scenario = std::move(replay.scenario);
  out.result = std::move(replay.result);
  if (sensors_at) {
    // The row's own sensor plugins, read at the recorded state (sensors keep no state: a tracker
    // replays the frames before).
    RowInstance instance(suite.rows[row], registry);
    const EpisodeAgents& agents = instance.Agents(out.scenario.humans.size());
    out.sensors = TakeSensorSnapshot(out.scenario, out.result, *sensors_at, agents.sensors);
    // The person sensors' field of view and range, drawn as a sector.
    for (const PluginUse& use : suite.rows[row].sensors) {
      const bool person = use.loaded && std::string(use.loaded->descriptor->name) == "person";
      out.sensors->fov_deg.push_back(person ? use.params.GetDouble("fov_deg") : 360.0);
      out.sensors->range.push_back(person ? use.params.GetDouble("max_range") : 0.0);
    }
  }
  return out;
}

std::string TrackLabel(const Suite& suite, const ReplayedEpisode& replay) {
  const RowSpec& row = suite.rows[replay.row];
  char time[32];
  std::snprintf(time, sizeof(time), "%.2f", replay.result.time);
  std::string s = "row " + std::to_string(replay.row + 1) + " " + row.label + " (" +
                  row.policy.plugin + "): " + EpisodeStatusName(replay.result.status);
  s += replay.result.status == EpisodeStatus::kSuccess ? " in " : " at ";
  s += std::string(time) + " s";
  if (replay.result.collided_human >= 0) {
    s += " (human " + std::to_string(replay.result.collided_human + 1) + ")";
  }
  if (!replay.result.error.empty()) s += " (" + replay.result.error + ")";
  return s;
}

EpisodeFigure MakeFigure(const Suite& suite, const ReplayedEpisode& replay,
                         const ReplayedEpisode* compare) {
  if (compare != nullptr) {
    const Scenario& a = replay.scenario;
    const Scenario& b = compare->scenario;
    const bool same = a.seed == b.seed && a.layout == b.layout && a.robot_start == b.robot_start &&
                      a.robot_goal == b.robot_goal && a.humans.size() == b.humans.size();
    if (!same) {
      throw std::invalid_argument(
          "rows " + std::to_string(replay.row + 1) + " and " + std::to_string(compare->row + 1) +
          " do not share the scenario of episode " + std::to_string(replay.episode) +
          " (different world or humans): --compare needs two rows of the same world");
    }
  }
  EpisodeFigure fig;
  fig.scenario = &replay.scenario;
  fig.title = suite.name + " · episode " + std::to_string(replay.episode) +
              (replay.scenario.layout.empty() ? "" : " · " + replay.scenario.layout) + " · " +
              std::to_string(replay.scenario.humans.size()) + " humans";
  fig.robots.push_back(RobotTrack{TrackLabel(suite, replay), &replay.result, palette::kRobot});
  if (compare != nullptr) {
    fig.robots.push_back(
        RobotTrack{TrackLabel(suite, *compare), &compare->result, palette::kRobotCompare});
  }
  if (compare != nullptr && compare->result.trajectory.size() > replay.result.trajectory.size()) {
    fig.humans_from = 1;
  }
  if (compare != nullptr && suite.sim.robot_visible) {
    // Humans react to the robot here, so the two rows' humans differ: say whose are shown.
    fig.title +=
        " · humans of row " + std::to_string((fig.humans_from == 0 ? replay : *compare).row + 1);
  }
  fig.sensors = replay.sensors;
  return fig;
}

}  // namespace crowdsim::render
