#include "planner_factory.h"

#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include <stdexcept>

#include "planner_config.h"

namespace crowdsim::ompl_planner {

namespace ob = ::ompl::base;
namespace og = ::ompl::geometric;

namespace {

// OMPL keeps each planner's RNG a protected member seeded from a process-wide generator in
// creation order; a subclass is the only way to give it a seed of our own.
template <class P>
class Seeded final : public P {
 public:
  Seeded(const ob::SpaceInformationPtr& si, std::uint32_t seed) : P(si) {
    this->rng_.setLocalSeed(seed);
  }
};

// OMPL's default neighbour structure (GNAT) picks its pivots with an unseeded RNG; a linear
// scan is exact, ties broken by insertion order, and cheap for a few thousand 2D samples.
template <class P>
ob::PlannerPtr WithLinearNeighbours(std::shared_ptr<P> planner) {
  planner->template setNearestNeighbors<::ompl::NearestNeighborsLinear>();
  return planner;
}

// OMPL 1.5's PRM::setup and LazyPRM::setup give their distance function only to a neighbour
// structure they made themselves, so a structure set beforehand must get it here.
template <class P>
class RoadmapWithDistance : public P {
 public:
  using P::P;
  void setup() override {
    P::setup();
    this->nn_->setDistanceFunction([this](const typename P::Vertex a, const typename P::Vertex b) {
      return this->distanceFunction(a, b);
    });
  }
};

class SeededPrmStar final : public RoadmapWithDistance<og::PRMstar> {
 public:
  SeededPrmStar(const ob::SpaceInformationPtr& si, std::uint32_t seed) : RoadmapWithDistance(si) {
    rng_.setLocalSeed(seed);
  }
};

}  // namespace

ob::PlannerPtr MakePlanner(const std::string& name, const ob::SpaceInformationPtr& si,
                           std::uint32_t seed) {
  if (name == "rrtstar")
    return WithLinearNeighbours(std::make_shared<Seeded<og::RRTstar>>(si, seed));
  if (name == "informed_rrtstar") {
    return WithLinearNeighbours(std::make_shared<Seeded<og::InformedRRTstar>>(si, seed));
  }
  if (name == "rrtconnect") {
    return WithLinearNeighbours(std::make_shared<Seeded<og::RRTConnect>>(si, seed));
  }
  if (name == "rrt") return WithLinearNeighbours(std::make_shared<Seeded<og::RRT>>(si, seed));
  // LazyPRM* and BIT* own no RNG of their own: their samples come from our samplers.
  if (name == "lazyprmstar")
    return WithLinearNeighbours(std::make_shared<RoadmapWithDistance<og::LazyPRMstar>>(si));
  // BIT*'s neighbour structure cannot be replaced in OMPL 1.5 (the template is not
  // instantiated in the library); GNAT answers exactly, so only equal distances could differ.
  if (name == "bitstar") return std::make_shared<og::BITstar>(si);
  // PRM* grows its roadmap while a second thread looks for solutions (README: determinism).
  if (name == "prmstar") return WithLinearNeighbours(std::make_shared<SeededPrmStar>(si, seed));
  throw std::invalid_argument("ompl_planner: planner: '" + name +
                              "' is not valid; valid planners: " + PlannerNameList());
}

}  // namespace crowdsim::ompl_planner
