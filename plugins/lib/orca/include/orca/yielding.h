// Deadlock resolution for ORCA agents in narrow passages: ORCA keeps agents apart but has no
// notion of taking turns, so two agents meeting in a 1 m passage (or three or four meeting at
// a junction) press against each other and freeze. People settle it by one of them stepping
// back; here the agent of lower priority backs off along the way it came until the other has
// gone by. The priority is a strict order every agent computes alike from what it sees, so
// exactly one side of every meeting gives way and nobody needs to talk.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "crowdsim/agent_state.h"
#include "crowdsim/geometry.h"

namespace crowdsim::orca {

/// Right of way of `agent` (index `index` >= 0 in the agent list all humans share): the higher
/// rank goes first. An agent still walking to its goal outranks one already standing on it
/// (within 0.5 m), and otherwise the higher index wins. Distinct for distinct indices and the
/// same for every observer, so in any jam exactly one agent, the highest, never yields.
std::int64_t YieldRank(const AgentState& agent, int index);

/// A neighbour as the yielding rule sees it (world frame).
struct YieldNeighbour {
  Vec2 position = Vec2::Zero();  ///< m
  Vec2 velocity = Vec2::Zero();  ///< m/s
  double radius = 0.3;           ///< m
  double v_pref = 1.0;           ///< m/s
  std::int64_t rank = 0;         ///< its YieldRank
};

/// When and for how long an agent gives way.
struct YieldSettings {
  /// Decisions (>= 1) over which an agent must have moved less than `stuck_distance` to be
  /// stuck.
  int jam_steps = 8;
  double stuck_distance = 0.5;  ///< m; net displacement over jam_steps that counts as stuck
  double contact_gap = 0.3;     ///< m; surface gap under which a neighbour blocks the agent
  double min_time = 2.0;        ///< s; a yield lasts at least this long
  double max_time = 8.0;        ///< s (>= min_time); and never longer than this
};

/// The yielding state of one agent (one per policy instance; not shared).
class Yielding {
 public:
  explicit Yielding(const YieldSettings& settings = YieldSettings());

  /// Forgets the trail, the jam history and any yield in progress (a new episode).
  void Reset();

  /// Records this decision's position (once per decision, before Step). Returns true when
  /// the agent is stuck or yielding, i.e. when Step needs its neighbours; false in the common
  /// case, where Step need not be called.
  bool Observe(const Vec2& position);

  /// Decides whether the agent gives way this decision. True: `*target` receives the point to
  /// back off towards (an intermediate waypoint). False: follow the path as usual;
  /// `finished()` then tells whether a yield just ended (the path should be planned afresh).
  /// `radius` (m) and `rank` (YieldRank): the agent's own; `time_step` (s, > 0) advances the
  /// yield clock.
  bool Step(const Vec2& position, double radius, std::int64_t rank, double time_step,
            std::span<const YieldNeighbour> neighbours, Vec2* target);

  /// True while backing off.
  bool yielding() const { return yielding_; }
  /// True right after a yield ended (until the next Step).
  bool finished() const { return finished_; }
  /// Number of yields since Reset.
  int yields() const { return yields_; }

 private:
  // Spacing (m) of the remembered trail and the number of points kept (~16 m).
  static constexpr double kTrailSpacing = 0.25;
  static constexpr std::size_t kTrailCapacity = 64;

  // The agent's jam: the slow neighbours linked to it by chains of contacts (gap below
  // contact_gap). Marks them in in_jam_; true when one of them outranks the agent.
  bool JamHasHigherRank(const Vec2& position, double radius, std::int64_t rank,
                        std::span<const YieldNeighbour> neighbours);
  // A neighbour of higher rank is still jammed against the agent or coming at it.
  bool Pressed(const Vec2& position, double radius, std::int64_t rank,
               std::span<const YieldNeighbour> neighbours) const;
  // Begins a yield: picks the way back (trail or straight away from the higher ranks).
  void Start(const Vec2& position, double radius, std::int64_t rank,
             std::span<const YieldNeighbour> neighbours);
  void ClearHistory();

  YieldSettings settings_;
  std::vector<Vec2> trail_;    // where the agent walked, oldest first
  std::vector<char> in_jam_;   // scratch of JamHasHigherRank, per neighbour
  std::vector<Vec2> history_;  // ring of the last jam_steps positions
  std::size_t history_next_ = 0;
  std::size_t history_count_ = 0;
  bool stuck_ = false;  // moved less than stuck_distance over the last jam_steps decisions
  bool yielding_ = false;
  bool finished_ = false;
  bool along_trail_ = true;   // back off along the trail, else straight away from the others
  Vec2 away_ = Vec2::Zero();  // unit direction away from the blocking neighbours
  double elapsed_ = 0.0;      // s since the yield started
  int yields_ = 0;
};

}  // namespace crowdsim::orca
