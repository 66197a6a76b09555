#include "crowdsim/render/sensor_snapshot.h"

#include <stdexcept>
#include <string>

#include "crowdsim/collision_world.h"
#include "crowdsim/sensor.h"

namespace crowdsim::render {

SensorSnapshot TakeSensorSnapshot(const Scenario& scenario, const EpisodeResult& result, int step,
                                  std::span<const MountedSensor> sensors) {
  const int frames = static_cast<int>(result.trajectory.size());
  if (step < 0 || step >= frames) {
    throw std::out_of_range(
        "--sensors-at " + std::to_string(step) + " is outside the episode: valid steps are 0.." +
        std::to_string(frames - 1) + " (" + std::to_string(frames) + " recorded frames)");
  }
  const EpisodeFrame& f = result.trajectory[static_cast<size_t>(step)];
  SensorSnapshot snap;
  snap.step = step;
  snap.time = f.time;
  // The recorded heading is the one it senses with: its goal's (holonomic) or its body's.
  snap.robot = f.robot;
  snap.frame = Frame::Make(snap.robot.position, snap.robot.heading);
  PresentPeople(f, &snap.humans, &snap.human_ids);
  const CollisionWorld world(scenario.map);
  // The frames before: a tracking sensor replays them (as in the episode, which held the same).
  std::vector<SensedFrame> past(static_cast<size_t>(step));
  for (size_t k = 0; k < past.size(); ++k) {
    const EpisodeFrame& e = result.trajectory[k];
    past[k] = SensedFrame{e.robot, Frame::Make(e.robot.position, e.robot.heading), {}, {}};
    PresentPeople(e, &past[k].humans, &past[k].human_ids);
  }
  // Frames lie one time step apart (time = step x time_step).
  const double time_step = frames > 1 ? result.trajectory[1].time - result.trajectory[0].time : 0.0;
  SenseInput input{snap.robot, snap.frame, snap.humans, world, SensorNoiseSeed(scenario.seed),
                   step,       time_step,  past};
  input.human_ids = snap.human_ids;
  snap.readings.resize(sensors.size());
  for (size_t s = 0; s < sensors.size(); ++s) {
    snap.readings[s].sensor = sensors[s].name;
    sensors[s].sensor->Sense(input, &snap.readings[s]);
  }
  return snap;
}

}  // namespace crowdsim::render
