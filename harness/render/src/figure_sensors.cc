#include "crowdsim/render/figure_sensors.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "crowdsim/render/palette.h"

namespace crowdsim::render {
namespace {

// Whether a person reading lies near human `h` (within its radius and half a metre, which
// position noise of up to ~0.15 m keeps): people without one are unseen at this step.
bool Detected(const SensorSnapshot& s, const AgentState& h) {
  bool any_person_sensor = false;
  for (const SensorReading& r : s.readings) {
    if (r.ranges.empty() && r.values.empty()) any_person_sensor = true;
    for (const PersonObservation& p : r.people) {
      const Vec2 world = s.robot.position + s.frame.VectorToWorld(p.position);
      if ((world - h.position).norm() <= h.radius + 0.5) return true;
    }
  }
  return !any_person_sensor;  // without a person sensor nobody is greyed
}

// The humans' and the robot's discs at the snapshot's step; the unseen ones grey.
void DrawSensedAgents(Drawing* d, const View& v, const SensorSnapshot& s,
                      const Color& robot_color) {
  for (size_t i = 0; i < s.humans.size(); ++i) {
    const int id = s.human_ids.empty() ? static_cast<int>(i) : s.human_ids[i];
    const Color c = Detected(s, s.humans[i]) ? palette::Human(id) : palette::kUnseen;
    d->AddCircle("sensed human", v.ToCanvas(s.humans[i].position), v.Length(s.humans[i].radius),
                 Filled(c.WithAlpha(0.15), c, 1.0));
  }
  d->AddCircle("sensed robot", v.ToCanvas(s.robot.position), v.Length(s.robot.radius),
               Filled(robot_color.WithAlpha(0.25), robot_color, 1.4));
}

// Every lidar beam from the robot, with a dot where it hit something.
void DrawBeams(Drawing* d, const View& v, const SensorSnapshot& s) {
  const Vec2 origin = v.ToCanvas(s.robot.position);
  for (const SensorReading& r : s.readings) {
    for (size_t b = 0; b < r.ranges.size() && b < r.angles.size(); ++b) {
      const double a = s.frame.heading + r.angles[b];
      const Vec2 end = s.robot.position + r.ranges[b] * Vec2(std::cos(a), std::sin(a));
      d->AddPolyline("beam", {origin, v.ToCanvas(end)},
                     Stroke(palette::kBeam.WithAlpha(0.45), 0.9));
      if (r.ranges[b] < r.max_range - 1e-9) {
        d->AddCircle("hit", v.ToCanvas(end), 2.6, Filled(palette::kBeam));
      }
    }
  }
}

// Whether a person reading lies near nobody (as Detected, the other way round): a false
// detection.
bool Phantom(const SensorSnapshot& s, const Vec2& world) {
  for (const AgentState& h : s.humans) {
    if ((world - h.position).norm() <= h.radius + 0.5) return false;
  }
  return true;
}

// Every person detected: a dashed ring and its velocity over 1 s; a false detection a hollow
// disc within its ring too; a tracked one its track id beside it.
void DrawPeople(Drawing* d, const View& v, const SensorSnapshot& s) {
  for (const SensorReading& r : s.readings) {
    for (const PersonObservation& p : r.people) {
      const Vec2 world = s.robot.position + s.frame.VectorToWorld(p.position);
      const Vec2 vel = s.frame.VectorToWorld(p.velocity);
      const Vec2 c = v.ToCanvas(world);
      d->AddCircle("person-reading", c, v.Length(p.radius) + 3.0,
                   Stroke(palette::kPersonReading, 1.6, true));
      if (Phantom(s, world)) {
        d->AddCircle("phantom-reading", c, v.Length(p.radius),
                     Stroke(palette::kPersonReading, 2.2));
      }
      d->AddPolyline("person-velocity", {c, v.ToCanvas(world + vel)},
                     Stroke(palette::kPersonReading, 1.6));
      if (p.track_id >= 0) {
        const double offset = v.Length(p.radius) + 4.0;
        d->AddText("track-id", c + Vec2(offset, -offset), std::to_string(p.track_id), 10.0,
                   palette::kPersonReading);
      }
    }
  }
}

// A person sensor's field of view narrower than all around: a sector on the heading, as far as
// its range (unlimited: 6 m).
void DrawFieldOfView(Drawing* d, const View& v, const SensorSnapshot& s) {
  for (size_t k = 0; k < s.fov_deg.size(); ++k) {
    if (s.fov_deg[k] >= 360.0) continue;
    const double half = s.fov_deg[k] * std::numbers::pi / 360.0;
    const double reach = k < s.range.size() && s.range[k] > 0.0 ? s.range[k] : 6.0;
    std::vector<Vec2> sector = {v.ToCanvas(s.robot.position)};
    constexpr int kArc = 24;
    for (int i = 0; i <= kArc; ++i) {
      const double a = s.frame.heading - half + 2.0 * half * i / kArc;
      sector.push_back(v.ToCanvas(s.robot.position + reach * Vec2(std::cos(a), std::sin(a))));
    }
    d->AddPolygon("field-of-view", sector,
                  Filled(palette::kPersonReading.WithAlpha(0.07),
                         palette::kPersonReading.WithAlpha(0.5), 0.8));
  }
}

}  // namespace

void DrawSensorSnapshot(Drawing* d, const View& v, const SensorSnapshot& s,
                        const Color& robot_color) {
  DrawFieldOfView(d, v, s);
  DrawSensedAgents(d, v, s, robot_color);
  DrawBeams(d, v, s);
  DrawPeople(d, v, s);
}

std::string SensorList(const SensorSnapshot& s) {
  std::string what;
  for (const SensorReading& r : s.readings) {
    if (!what.empty()) what += ", ";
    what += r.sensor;
    if (!r.ranges.empty()) what += " (" + std::to_string(r.ranges.size()) + " beams)";
    if (!r.values.empty()) {
      // Other sensors' features (e.g. the route's path distance and waypoint), as read.
      what += " (";
      for (size_t i = 0; i < r.values.size(); ++i) {
        char number[32];
        std::snprintf(number, sizeof number, "%.2f", r.values[i]);
        what += (i == 0 ? "" : ", ") + std::string(number);
      }
      what += ")";
    } else if (!r.people.empty() || r.ranges.empty()) {
      what += " (" + std::to_string(r.people.size()) + " people)";
    }
  }
  return what;
}

}  // namespace crowdsim::render
