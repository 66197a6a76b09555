#include "random_rect_world.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "crowdsim/data_root.h"
#include "crowdsim/human_placement.h"
#include "crowdsim/rng.h"
#include "frozen_sets.h"
#include "rect_layout.h"

namespace crowdsim::random_rect {
namespace {

namespace fs = std::filesystem;

constexpr ScenarioOptions kDefaults{};

std::string Number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", x);
  return buf;
}

ScenarioOptions OptionsFrom(const Params& params) {
  ScenarioOptions o;
  o.min_start_goal_dist = params.GetDouble("min_start_goal_dist");
  o.human_goal_min_dist = params.GetDouble("human_goal_min_dist");
  o.new_goal_count = static_cast<int>(params.GetInt("new_goal_count"));
  o.clearance_margin = params.GetDouble("clearance_margin");
  o.passage_padding = params.GetDouble("passage_padding");
  return o;
}

// Options that change the scenarios are part of the identity (and so of the episode seeds
// and the manifest); defaults are left out to keep the usual identities short.
std::string OptionSuffix(const ScenarioOptions& o) {
  std::string s;
  if (o.min_start_goal_dist != kDefaults.min_start_goal_dist) {
    s += ":min_start_goal_dist=" + Number(o.min_start_goal_dist);
  }
  if (o.human_goal_min_dist != kDefaults.human_goal_min_dist) {
    s += ":human_goal_min_dist=" + Number(o.human_goal_min_dist);
  }
  if (o.new_goal_count != kDefaults.new_goal_count) {
    s += ":new_goal_count=" + std::to_string(o.new_goal_count);
  }
  if (o.clearance_margin != kDefaults.clearance_margin) {
    s += ":clearance_margin=" + Number(o.clearance_margin);
  }
  if (o.passage_padding != kDefaults.passage_padding) {
    s += ":passage_padding=" + Number(o.passage_padding);
  }
  return s;
}

std::vector<WorldFile> ReadLayouts(const fs::path& path, const std::string& fix) {
  if (!fs::exists(path)) {
    throw std::runtime_error("random_rect: world set file " + path.string() +
                             " does not exist. Fix: " + fix);
  }
  std::vector<WorldFile> layouts;
  try {
    layouts = ReadWorldSet(path);
  } catch (const WorldFileError& e) {
    throw std::runtime_error(std::string("random_rect: malformed world set: ") + e.what() +
                             ". Fix: " + fix);
  }
  if (layouts.empty()) {
    throw std::runtime_error("random_rect: world set file " + path.string() +
                             " holds no worlds. Fix: " + fix);
  }
  return layouts;
}

/// The committed set of `obstacles`-obstacle rooms of `split` under the data root.
fs::path FrozenSetPath(int obstacles, const std::string& split) {
  SetSpec spec;
  spec.obstacles = obstacles;
  spec.split = split;
  return DataRoot() / "worlds" / "random_rect" / spec.FileName();
}

}  // namespace

ParamSchema Schema() {
  // One parameter per entry reads as a table.
  // clang-format off
  return {
      {"obstacles", ParamType::kInt, std::int64_t{1}, 0, 20, {},
       "obstacles per room; 0 = empty 10 x 10 m room, else the frozen set obstacles_<N>_<split>"},
      {"split", ParamType::kString, std::string("test"), 0, 0, {"train", "test"},
       "which frozen set of layouts: train or test"},
      {"file", ParamType::kString, std::string(""), 0, 0, {},
       "world set file; empty = <data root>/worlds/random_rect/obstacles_<N>_<split>.yaml"},
      {"min_start_goal_dist", ParamType::kDouble, kDefaults.min_start_goal_dist, 0.0, 100.0, {},
       "m; smallest distance between the robot's start and goal"},
      {"human_goal_min_dist", ParamType::kDouble, kDefaults.human_goal_min_dist, 0.0, 100.0, {},
       "m; a human's goal is at least this far from its start (previous goal) if room allows"},
      {"new_goal_count", ParamType::kInt, std::int64_t{kDefaults.new_goal_count}, 1, 1000, {},
       "goals per human when the suite gives humans new goals"},
      {"clearance_margin", ParamType::kDouble, kDefaults.clearance_margin, 0.0, 2.0, {},
       "m; free space beyond an agent's radius required at starts and goals"},
      {"passage_padding", ParamType::kDouble, kDefaultPassagePadding, 0.0, 1.0, {},
       "m; added to each human radius when a goal must leave room for another human to pass"},
  };
  // clang-format on
}

RandomRectWorld::RandomRectWorld(const Params& params) : options_(OptionsFrom(params)) {
  const int obstacles = static_cast<int>(params.GetInt("obstacles"));
  const std::string& split = params.GetString("split");
  const std::string& file = params.GetString("file");
  std::vector<WorldFile> layouts;
  if (!file.empty()) {
    const fs::path path = params.ResolvePath(file);
    layouts = ReadLayouts(path,
                          "set 'file' to an existing crowdsim-world-set/1 file (relative "
                          "paths are resolved against the suite's folder), or remove "
                          "'file' to use the frozen sets");
    identity_ = "random_rect:file=" + path.filename().string();
  } else if (obstacles == 0) {
    layouts = {EmptyRoom(RectLayoutConfig{}, "rect0")};
    identity_ = "random_rect:obstacles=0:split=" + split;
  } else {
    const fs::path path = FrozenSetPath(obstacles, split);
    layouts = ReadLayouts(
        path, "the frozen sets ship with 1 and 3 obstacles; for " + std::to_string(obstacles) +
                  " run `crowdsim-make-rect-worlds --obstacles " + std::to_string(obstacles) +
                  " --split " + split + " --out " + path.string() +
                  "` (in a build tree it is in the build folder's bin/, e.g. "
                  "build/bin/crowdsim-make-rect-worlds), or set "
                  "CROWDSIM_DATA_DIR to the project's root folder");
    for (const WorldFile& w : layouts) {
      if (static_cast<int>(w.rectangles.size()) != kWallCount + obstacles) {
        throw std::runtime_error("random_rect: " + path.string() + ": layout '" + w.name +
                                 "' has " + std::to_string(w.rectangles.size()) +
                                 " rectangles, expected 4 walls + " + std::to_string(obstacles) +
                                 " obstacles. Fix: regenerate the file with "
                                 "crowdsim-make-rect-worlds");
      }
    }
    identity_ = "random_rect:obstacles=" + std::to_string(obstacles) + ":split=" + split;
  }
  identity_ += OptionSuffix(options_);
  BuildMaps(layouts);
}

std::vector<fs::path> RandomRectWorld::DataFiles(const Params& params) {
  const int obstacles = static_cast<int>(params.GetInt("obstacles"));
  if (!params.GetString("file").empty() || obstacles == 0) return {};
  return {FrozenSetPath(obstacles, params.GetString("split"))};
}

RandomRectWorld::RandomRectWorld(std::vector<WorldFile> layouts, ScenarioOptions options,
                                 std::string identity)
    : options_(options), identity_(std::move(identity)) {
  if (layouts.empty()) throw std::invalid_argument("RandomRectWorld: no layouts");
  BuildMaps(layouts);
}

void RandomRectWorld::BuildMaps(const std::vector<WorldFile>& layouts) {
  maps_.reserve(layouts.size());
  for (const WorldFile& w : layouts) {
    maps_.push_back(std::make_shared<const StaticMap>(w.ToStaticMap()));
  }
}

Scenario RandomRectWorld::Make(const ScenarioRequest& request) const {
  const std::int64_t index = FrozenLayoutIndex(request, static_cast<std::int64_t>(maps_.size()));
  const std::shared_ptr<const StaticMap>& map = maps_[static_cast<size_t>(index)];

  Scenario s;
  s.map = map;
  s.seed = request.seed;
  s.layout = map->name;
  Rng rng(request.seed);
  const PointSampler sample = UniformSampler(map->bounds);

  const DiscFreeSpace robot_space(map, request.sim.robot_radius + options_.clearance_margin);
  bool found = false;
  for (int t = 0; t < options_.max_tries && !found; ++t) {
    s.robot_start = sample(rng);
    s.robot_goal = sample(rng);
    found = robot_space.Contains(s.robot_start) && robot_space.Contains(s.robot_goal) &&
            (s.robot_goal - s.robot_start).norm() >= options_.min_start_goal_dist;
  }
  if (!found) {
    throw PlacementError("random_rect: layout '" + map->name + "': no robot start and goal " +
                         Number(options_.min_start_goal_dist) + " m apart found in " +
                         std::to_string(options_.max_tries) +
                         " draws. Fix: lower min_start_goal_dist or check the layout");
  }

  // Free space for the largest person: it holds every smaller one too.
  const double human_radius = LargestHumanRadius(request);
  const auto human_space =
      std::make_shared<const DiscFreeSpace>(map, human_radius + options_.clearance_margin);
  // Goals leave room to pass: a human who stays on its goal must not close a passage.
  const auto goal_space = std::make_shared<const DiscFreeSpace>(
      map, PassableGoalClearance(human_radius, options_.passage_padding));
  const PlacementArea area{[human_space](const Vec2& p) { return human_space->Contains(p); },
                           sample, [goal_space](const Vec2& p) { return goal_space->Contains(p); },
                           map->bounds};
  HumanPlacementOptions placement = HumanPlacementOptions::FromRequest(request);
  placement.goal_min_dist = options_.human_goal_min_dist;
  placement.new_goal_count = options_.new_goal_count;
  try {
    s.humans = PlaceHumans(area, s.robot_start, s.robot_goal, request, placement, rng);
  } catch (const PlacementError& e) {
    throw PlacementError("random_rect: layout '" + map->name + "': " + e.what());
  }
  return s;
}

}  // namespace crowdsim::random_rect
