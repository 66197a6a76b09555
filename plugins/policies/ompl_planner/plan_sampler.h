// OMPL samplers drawing from the harness's portable Rng, so that a plan depends on its seed
// only (OMPL's own RNGs are seeded from a process-wide generator in creation order, which
// differs between threads), and that count every sample against the plan's budget.
#pragma once

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/samplers/InformedStateSampler.h>

#include <atomic>
#include <cstdint>
#include <memory>

#include "crowdsim/geometry.h"
#include "crowdsim/rng.h"

namespace crowdsim::ompl_planner {

/// Samples drawn by one planning attempt; read by its termination condition. Atomic because
/// some OMPL planners (PRM) evaluate the condition from a second thread.
struct SampleBudget {
  std::atomic<std::int64_t> drawn{0};
  std::atomic<std::int64_t> evaluations{0};  ///< of the termination condition
};

/// Where the samplers of one planning attempt come from: the plane's box, a seed, and the
/// budget they count against. Samplers get streams 0, 1, 2... in allocation order, which is
/// fixed for a single-threaded planner.
class SampleSource {
 public:
  SampleSource(const Rect& box, std::uint64_t seed, std::shared_ptr<SampleBudget> budget)
      : box_(box), seed_(seed), budget_(std::move(budget)) {}
  const Rect& box() const { return box_; }
  SampleBudget& budget() const { return *budget_; }
  /// A generator for the next sampler.
  Rng NextStream() { return Rng(SplitMix64(seed_ + 0x9E3779B97F4A7C15ull * ++streams_)); }

 private:
  Rect box_;
  std::uint64_t seed_;
  std::shared_ptr<SampleBudget> budget_;
  std::uint64_t streams_ = 0;
};

/// Uniform, near and Gaussian samples of a 2D RealVectorStateSpace from the portable Rng.
class SeededStateSampler final : public ::ompl::base::StateSampler {
 public:
  SeededStateSampler(const ::ompl::base::StateSpace* space, std::shared_ptr<SampleSource> source);
  void sampleUniform(::ompl::base::State* state) override;
  void sampleUniformNear(::ompl::base::State* state, const ::ompl::base::State* near,
                         double distance) override;
  void sampleGaussian(::ompl::base::State* state, const ::ompl::base::State* mean,
                      double std_dev) override;

 private:
  void Set(::ompl::base::State* state, Vec2 p) const;
  std::shared_ptr<SampleSource> source_;
  Rng rng_;
};

/// Informed sampling for path length (the ellipse whose foci are start and goal), from the
/// portable Rng; replaces OMPL's PathLengthDirectInfSampler, whose RNG cannot be seeded.
class SeededInformedSampler final : public ::ompl::base::InformedSampler {
 public:
  SeededInformedSampler(const ::ompl::base::ProblemDefinitionPtr& problem, unsigned int max_calls,
                        std::shared_ptr<SampleSource> source);
  bool sampleUniform(::ompl::base::State* state, const ::ompl::base::Cost& max_cost) override;
  bool sampleUniform(::ompl::base::State* state, const ::ompl::base::Cost& min_cost,
                     const ::ompl::base::Cost& max_cost) override;
  bool hasInformedMeasure() const override { return true; }
  double getInformedMeasure(const ::ompl::base::Cost& current_cost) const override;

 private:
  /// A point inside the ellipse of transverse diameter `cost` (uniform), or of the box when
  /// the cost is infinite; false if it falls outside the box.
  bool Draw(double cost, Vec2* p);
  std::shared_ptr<SampleSource> source_;
  Rng rng_;
  Vec2 start_ = Vec2::Zero();
  Vec2 goal_ = Vec2::Zero();
};

/// Path length, with the seeded informed sampler (used by informed RRT* and BIT*).
class PlanObjective final : public ::ompl::base::PathLengthOptimizationObjective {
 public:
  PlanObjective(const ::ompl::base::SpaceInformationPtr& si, std::shared_ptr<SampleSource> source)
      : PathLengthOptimizationObjective(si), source_(std::move(source)) {}
  ::ompl::base::InformedSamplerPtr allocInformedStateSampler(
      const ::ompl::base::ProblemDefinitionPtr& problem, unsigned int max_calls) const override;

 private:
  std::shared_ptr<SampleSource> source_;
};

}  // namespace crowdsim::ompl_planner
