#include "crowdsim/bench/play_episode.h"

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/people_effect.h"
#include "crowdsim/bench/social_metrics.h"

namespace crowdsim {

EpisodeOutcome PlayEpisode(Episode& episode, unsigned social_metrics) {
  if (!social_metrics) return episode.Run();
  const SimConfig& sim = episode.sim();
  SocialMetricsAccumulator social(sim.time_step, episode.kinematics().Holonomic(), sim.goal_radius);
  social.Observe(episode.robot(), episode.present_humans(), episode.present_ids());
  const bool effect = social_metrics & kEffectMetrics;
  PeopleWalks walks(sim.time_step);
  if (effect) walks.Observe(episode.humans());
  const double shortest = ShortestFreePath(episode.world().map(), episode.robot());
  while (!episode.done()) {
    episode.Step();
    // A policy error ends the step before anybody moves.
    if (episode.result().status != EpisodeStatus::kPolicyError) {
      social.Observe(episode.robot(), episode.present_humans(), episode.present_ids());
      if (effect) walks.Observe(episode.humans());
    }
  }
  EpisodeOutcome outcome = episode.result();
  outcome.social = social.Finish(outcome.status == EpisodeStatus::kSuccess, shortest);
  if (effect) FillPeopleEffect(episode, walks, &outcome.social);
  return outcome;
}

}  // namespace crowdsim
