#include "orca/yielding.h"

#include <algorithm>

namespace crowdsim::orca {
namespace {

// An agent this close to its goal is standing on it: stepping aside costs it nothing, so it
// gives way to anybody still walking.
constexpr double kSettledDistance = 0.5;
// A neighbour of higher rank closer than this (surface gap, m) and coming at the agent keeps
// it backing off: in a passage the other follows it out.
constexpr double kFollowGap = 1.0;
// Below this share of its preferred speed a neighbour counts as jammed too.
constexpr double kSlowShare = 0.5;

double Gap(const Vec2& position, const YieldNeighbour& n, double own_radius) {
  return (n.position - position).norm() - n.radius - own_radius;
}

bool Slow(const YieldNeighbour& n) {
  return n.velocity.squaredNorm() < kSlowShare * kSlowShare * n.v_pref * n.v_pref;
}

}  // namespace

std::int64_t YieldRank(const AgentState& agent, int index) {
  const bool walking =
      (agent.goal - agent.position).squaredNorm() >= kSettledDistance * kSettledDistance;
  return (walking ? (std::int64_t{1} << 32) : 0) + index;
}

Yielding::Yielding(const YieldSettings& settings) : settings_(settings) {
  history_.assign(static_cast<std::size_t>(std::max(1, settings_.jam_steps)), Vec2::Zero());
}

void Yielding::Reset() {
  trail_.clear();
  ClearHistory();
  stuck_ = false;
  yielding_ = false;
  finished_ = false;
  elapsed_ = 0.0;
  yields_ = 0;
}

void Yielding::ClearHistory() {
  history_next_ = 0;
  history_count_ = 0;
}

bool Yielding::Observe(const Vec2& position) {
  finished_ = false;
  // While backing off the trail is being walked back, not extended.
  if (!yielding_ && (trail_.empty() ||
                     (position - trail_.back()).squaredNorm() >= kTrailSpacing * kTrailSpacing)) {
    if (trail_.size() == kTrailCapacity) trail_.erase(trail_.begin());
    trail_.push_back(position);
  }
  // The oldest remembered position is overwritten by this one: compare before writing.
  const bool full = history_count_ == history_.size();
  const bool stuck = full && (position - history_[history_next_]).squaredNorm() <
                                 settings_.stuck_distance * settings_.stuck_distance;
  stuck_ = stuck;
  history_[history_next_] = position;
  history_next_ = (history_next_ + 1) % history_.size();
  if (!full) ++history_count_;
  return yielding_ || stuck;
}

bool Yielding::JamHasHigherRank(const Vec2& position, double radius, std::int64_t rank,
                                std::span<const YieldNeighbour> neighbours) {
  in_jam_.assign(neighbours.size(), 0);
  bool higher = false;
  // Breadth first from the agent itself (-1); k-nearest lists are short (<= max_neighbors).
  thread_local std::vector<int> queue;
  queue.assign(1, -1);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int m = queue[head];
    const Vec2& p = m < 0 ? position : neighbours[m].position;
    const double r = m < 0 ? radius : neighbours[m].radius;
    for (std::size_t k = 0; k < neighbours.size(); ++k) {
      const YieldNeighbour& n = neighbours[k];
      if (in_jam_[k] || !Slow(n) || Gap(p, n, r) >= settings_.contact_gap) continue;
      in_jam_[k] = 1;
      higher = higher || n.rank > rank;
      queue.push_back(static_cast<int>(k));
    }
  }
  return higher;
}

bool Yielding::Pressed(const Vec2& position, double radius, std::int64_t rank,
                       std::span<const YieldNeighbour> neighbours) const {
  for (const YieldNeighbour& n : neighbours) {
    if (n.rank <= rank) continue;
    const double gap = Gap(position, n, radius);
    if (gap >= kFollowGap) continue;
    const bool coming = (position - n.position).dot(n.velocity) > 0.0;
    if (coming || (gap < settings_.contact_gap && Slow(n))) return true;
  }
  return false;
}

void Yielding::Start(const Vec2& position, double radius, std::int64_t rank,
                     std::span<const YieldNeighbour> neighbours) {
  yielding_ = true;
  elapsed_ = 0.0;
  ++yields_;
  // The agents to make way for: those of higher rank in the jam or close by.
  auto superior = [&](std::size_t k) {
    return neighbours[k].rank > rank &&
           (in_jam_[k] || Gap(position, neighbours[k], radius) < kFollowGap);
  };
  // Away from all of them; used when there is no trail to walk back or when the trail leads
  // into one of them (it came from where this agent came from).
  Vec2 away = Vec2::Zero();
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    if (!superior(k)) continue;
    const Vec2 d = position - neighbours[k].position;
    const double len = d.norm();
    if (len > 0.0) away += d / len;
  }
  const double away_len = away.norm();
  away_ = away_len > 1e-9 ? Vec2(away / away_len) : Vec2::Zero();

  while (!trail_.empty() &&
         (trail_.back() - position).squaredNorm() < kTrailSpacing * kTrailSpacing) {
    trail_.pop_back();
  }
  along_trail_ = !trail_.empty();
  if (along_trail_) {
    const Vec2 back = (trail_.back() - position).normalized();
    for (std::size_t k = 0; k < neighbours.size() && along_trail_; ++k) {
      // Within 60 degrees of an agent to make way for: walking back would push into it.
      if (superior(k) && back.dot((neighbours[k].position - position).normalized()) > 0.5) {
        along_trail_ = false;
      }
    }
  }
}

bool Yielding::Step(const Vec2& position, double radius, std::int64_t rank, double time_step,
                    std::span<const YieldNeighbour> neighbours, Vec2* target) {
  if (yielding_) {
    elapsed_ += time_step;
    if (elapsed_ >= settings_.max_time ||
        (elapsed_ >= settings_.min_time && !Pressed(position, radius, rank, neighbours))) {
      yielding_ = false;
      finished_ = true;
      ClearHistory();  // a fresh jam_steps window before yielding again
      return false;
    }
  } else {
    if (!stuck_ || !JamHasHigherRank(position, radius, rank, neighbours)) return false;
    Start(position, radius, rank, neighbours);
  }

  if (along_trail_) {
    while (!trail_.empty() &&
           (trail_.back() - position).squaredNorm() < kTrailSpacing * kTrailSpacing) {
      trail_.pop_back();
    }
    if (!trail_.empty()) {
      *target = trail_.back();
      return true;
    }
    along_trail_ = false;  // walked all the way back to the start
  }
  *target = position + away_;
  return true;
}

}  // namespace crowdsim::orca
