#include "floorplan_world.h"

#include <cstdio>
#include <stdexcept>

#include "crowdsim/human_placement.h"
#include "crowdsim/rng.h"

namespace crowdsim::floorplan {

ParamSchema Schema() {
  return {
      {"file",
       ParamType::kString,
       std::string("worlds/gibson/easy.yaml"),
       -kInfinity,
       kInfinity,
       {},
       "world file of an imported floor plan (relative: suite folder, then data root)"},
      {"split",
       ParamType::kString,
       std::string("test"),
       -kInfinity,
       kInfinity,
       {"train", "test"},
       "which precomputed robot start/goal pairs to use"},
      {"passage_padding",
       ParamType::kDouble,
       kDefaultPassagePadding,
       0.0,
       1.0,
       {},
       "m; added to each human radius when a goal must leave room for another human to pass"},
  };
}

std::vector<std::filesystem::path> FloorplanWorld::DataFiles(const Params& params) {
  return {params.ResolvePath(params.GetString("file"))};
}

FloorplanWorld::FloorplanWorld(const Params& params)
    : split_(params.GetString("split")), passage_padding_(params.GetDouble("passage_padding")) {
  const std::string value = params.GetString("file");
  const std::filesystem::path path = params.ResolvePath(value);  // suite, working, data folder
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error("floorplan: world " + params.MissingFile(value) +
                             "; import one with `crowdsim-bench floorplan import`");
  }
  WorldFile world = ReadWorldFile(path);
  pairs_ = split_ == "train" ? world.train_pairs : world.test_pairs;
  if (pairs_.empty()) {
    throw std::invalid_argument(path.string() + ": no robot_pairs." + split_ +
                                (split_ == "train"
                                     ? " (the plan was imported for tests only: re-import it "
                                       "with `crowdsim-bench floorplan import ... --train-pairs "
                                       "500`)"
                                     : " (re-import the plan with --test-pairs 500)"));
  }
  if (world.free_points.empty()) {
    throw std::invalid_argument(path.string() +
                                ": no free_points for placing humans "
                                "(re-import the plan with `crowdsim-bench floorplan import`)");
  }
  name_ = world.name;
  free_points_ = std::move(world.free_points);
  auto map = std::make_shared<StaticMap>(world.ToStaticMap());
  map_ = std::move(map);
}

std::string FloorplanWorld::Identity() const {
  // A non-default padding changes the scenarios, so it is part of the identity (episode seeds).
  std::string id = "floorplan:" + name_ + ":" + split_;
  if (passage_padding_ != kDefaultPassagePadding) {
    char buf[40];
    std::snprintf(buf, sizeof(buf), ":passage_padding=%g", passage_padding_);
    id += buf;
  }
  return id;
}

Scenario FloorplanWorld::Make(const ScenarioRequest& request) const {
  const std::int64_t k = FrozenLayoutIndex(request, static_cast<std::int64_t>(pairs_.size()));
  Scenario s;
  s.map = map_;
  s.robot_start = pairs_[static_cast<size_t>(k)].start;
  s.robot_goal = pairs_[static_cast<size_t>(k)].goal;
  s.seed = request.seed;
  s.layout = name_ + "/" + split_ + "/" + std::to_string(k);
  // Free points were sampled with the robot's clearance against the plan's mask; the
  // predicate adds the kept rectangles for the largest person's radius.
  const double human_radius = LargestHumanRadius(request);
  const auto free = std::make_shared<DiscFreeSpace>(map_, human_radius);
  // Goals leave room to pass: a human who stays on its goal must not close a passage.
  const auto goal_space =
      std::make_shared<DiscFreeSpace>(map_, PassableGoalClearance(human_radius, passage_padding_));
  // The plan's free points first (the scenarios of every committed table); a crowd larger than
  // those points hold goes on to the whole floor.
  PlacementArea area{[free](const Vec2& p) { return free->Contains(p); }, ListSampler(free_points_),
                     [goal_space](const Vec2& p) { return goal_space->Contains(p); }, map_->bounds};
  Rng rng(request.seed);
  s.humans = PlaceHumans(area, s.robot_start, s.robot_goal, request,
                         HumanPlacementOptions::FromRequest(request), rng);
  return s;
}

}  // namespace crowdsim::floorplan
