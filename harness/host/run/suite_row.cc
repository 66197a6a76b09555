#include "run/suite_row.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>

#include "crowdsim/bench/episode_log.h"
#include "crowdsim/bench/play_episode.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/version.h"
#include "run/slow_episode_watch.h"
#include "spec/config_text.h"
#include "spec/human_attributes_reader.h"

namespace crowdsim {

std::string SuiteRow::Place() const {
  return "row '" + spec().label + "' (rows[" + std::to_string(index_) + "])";
}

std::string SuiteRow::Where(int episode) const {
  return "row '" + spec().label + "', episode " + std::to_string(episode);
}

void SuiteRow::Preflight(PluginRegistry& registry, int episodes, IsolationMode mode,
                         std::set<std::string>* checked, double slow_note_s) {
  const RowSpec& row = spec();
  const bool isolated = RowNeedsIsolation(suite_, row, mode);
  std::unique_ptr<RowInstance> instance;
  Scenario episode0;
  try {
    world_ = registry.MakeWorld(*row.world.loaded, row.world.params);
    if (isolated) {
      MakePluginsInWorker(registry);
    } else {
      // Made here, where nothing can stop a plugin that never returns: name a slow one.
      SlowEpisodeWatch watch(1, slow_note_s);
      watch.Began(0, Place() + ", making its plugins,");
      instance = MakePlugins(registry);
    }
    try {
      episode0 = MakeEpisodeScenario(suite_, row, *world_, 0);
      CheckScenario(episode0, suite_.sim);
    } catch (const std::exception& e) {
      throw RunError(Place() + ": the scenario of episode 0 (world '" +
                     row.world.loaded->descriptor->name + "') cannot be made: " + e.what());
    }
  } catch (const RunError&) {
    throw;
  } catch (const std::exception& e) {
    // A plugin's error, or its own exception outside its factory (Needs()): the row named.
    throw RunError(Place() + ": " + e.what());
  }
  CheckEveryLayout(episodes, checked);
  if (instance) CheckFirstStep(*instance, episode0);
}

std::unique_ptr<RowInstance> SuiteRow::MakePlugins(PluginRegistry& registry) const {
  auto instance = std::make_unique<RowInstance>(spec(), registry);
  instance->Agents(1);
  if (const std::string unmet = instance->UnmetSensorNeed(); !unmet.empty()) {
    throw RunError(Place() + ": " + unmet + "; add it to the row's sensors list");
  }
  if (const std::string unmet = instance->UnmetKinematicsNeed(); !unmet.empty()) {
    throw RunError(Place() + ": " + unmet);
  }
  if (const std::string unmet = instance->HumansNeedRobotOnly(); !unmet.empty()) {
    throw RunError(Place() + ": " + unmet + " (a human sees the others through the neighbour " +
                   "index); " + kPlainHumansPolicy);
  }
  return instance;
}

// An isolated row's plugins are made in a worker under the episodes' timeout: one that hangs or
// crashes while it is made (e.g. probing its model) is an error naming the row, not a stuck run.
void SuiteRow::MakePluginsInWorker(PluginRegistry& registry) const {
  const OnceInWorker made = RunOnceInWorker(IsolatedEpisodeTimeoutS(suite_), [&]() -> std::string {
    try {
      MakePlugins(registry);
    } catch (const RunError& e) {
      return e.what();
    } catch (const std::exception& e) {
      return Place() + ": " + e.what();
    }
    return "";
  });
  if (made.loss) {
    throw RunError(Place() + ": making its plugins " +
                   (made.loss->Interrupted() ? "was stopped from outside (the worker process "
                                             : "failed (the worker process that made them ") +
                   made.loss->Describe() + " while making " + Suspects() + ")");
  }
  if (!made.bytes.empty()) throw RunError(made.bytes);
}

// The first scenario of each other frozen layout among the first `episodes`: a crowd may fit one
// room and not a smaller. Harness worlds only: a foreign one that fails costs only its episodes,
// isolated.
void SuiteRow::CheckEveryLayout(int episodes, std::set<std::string>* checked) const {
  const RowSpec& row = spec();
  if (!PluginRegistry::IsHarnessPlugin(*row.world.loaded)) return;
  const int layouts = std::min(episodes, world_->LayoutCount());
  if (layouts < 2) return;
  // A world is keyed by its canonical text, not Identity(), which names a world set by file name
  // alone.
  std::ostringstream crowd;
  suite_internal::Canonical(row.world, crowd);
  crowd << " " << row.humans.count << " " << static_cast<int>(row.humans.goal_mode) << " ";
  suite_internal::CanonicalHumanAttributes(row.humans, crowd);
  if (checked->count(crowd.str())) return;
  for (int k = 1; k < layouts; ++k) {
    try {
      CheckScenario(MakeEpisodeScenario(suite_, row, *world_, k), suite_.sim);
    } catch (const std::exception& e) {
      throw RunError(Place() + ": the scenario of episode " + std::to_string(k) + " (world '" +
                     row.world.loaded->descriptor->name + "') cannot be made: " + e.what());
    }
  }
  checked->insert(crowd.str());
}

// Episode 0's first step, so what fails every step fails before the run. Only for rows of the
// harness's own plugins: another's crash would end this process.
void SuiteRow::CheckFirstStep(RowInstance& instance, const Scenario& episode0) const {
  if (!AllHarnessPlugins(spec())) return;
  try {
    Episode episode(episode0, suite_.sim, instance.Agents(episode0.humans.size()));
    if (!episode.done()) episode.Step();
    if (episode.result().status == EpisodeStatus::kPolicyError) {
      throw RunError(Place() + ": the first step of episode 0 fails: " + episode.result().error);
    }
  } catch (const RunError&) {
    throw;
  } catch (const std::exception& e) {
    throw RunError(Place() + ": episode 0 cannot start: " + e.what());
  }
}

EpisodeLine SuiteRow::Run(RowInstance& instance, int episode) const {
  EpisodeLine line;
  line.row = spec().label;
  line.episode = episode;
  ScenarioRequest req;
  const Scenario scenario = MakeEpisodeScenario(suite_, spec(), *world_, episode, &req);
  Episode played(scenario, suite_.sim, instance.Agents(scenario.humans.size()),
                 !record_dir_.empty());
  line.seed = req.seed;
  line.layout = scenario.layout;
  line.outcome = PlayEpisode(played, suite_.social_metrics);
  if (!record_dir_.empty()) WriteLog(played, episode);
  return line;
}

void SuiteRow::WriteLog(const Episode& played, int episode) const {
  // A label as a folder name: a swept label's braces, spaces and slashes become '_'.
  std::string folder = std::to_string(index_ + 1) + "_";
  for (char c : spec().label)
    folder +=
        std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_' ? c : '_';
  char name[32];
  std::snprintf(name, sizeof(name), "%06d.jsonl.gz", episode);
  EpisodeLog log;
  log.source = "crowdsim-bench " + std::string(Version()) + ", suite " + suite_.name + ", row " +
               spec().label + ", episode " + std::to_string(episode);
  log.dt = suite_.sim.time_step;
  log.holonomic = spec().kinematics.Holonomic();
  log.goal_radius = suite_.sim.goal_radius;
  log.map = played.world().map();
  log.frames = played.result().trajectory;
  log.status = played.result().status;
  const std::filesystem::path dir = record_dir_ / folder;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  WriteEpisodeLog(dir / name, log);
}

// The plugins a crash is laid to: those not of the harness, or the robot's policy when all are.
std::string SuiteRow::Suspects() const {
  auto name = [](const std::string& role, const PluginUse& u) {
    return role + " '" + std::string(u.loaded->descriptor->name) + "' (" + u.loaded->path.string() +
           ")";
  };
  std::string named;
  for (const auto& [role, use] : RowPlugins(spec())) {
    if (!PluginRegistry::IsHarnessPlugin(*use->loaded))
      named += (named.empty() ? "" : ", ") + name(role, *use);
  }
  return named.empty() ? name("policy", spec().policy) : named;
}

EpisodeLine SuiteRow::Lost(int episode, const WorkerLoss& loss) const {
  EpisodeLine line;
  line.row = spec().label;
  line.episode = episode;
  line.seed = MakeEpisodeRequest(suite_, spec(), *world_, episode).seed;
  line.outcome.status = loss.kind == WorkerLoss::Kind::kTimeout ? EpisodeStatus::kPolicyTimeout
                                                                : EpisodeStatus::kPolicyCrash;
  line.outcome.error = "worker process " + loss.Describe() + " while running " + Suspects();
  return line;
}

}  // namespace crowdsim
