#include "crowdsim/render/episode_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "crowdsim/render/figure_key.h"
#include "crowdsim/render/figure_map.h"
#include "crowdsim/render/figure_sensors.h"
#include "crowdsim/render/marks.h"
#include "crowdsim/render/palette.h"
#include "crowdsim/render/view.h"

namespace crowdsim::render {
namespace {

constexpr double kMargin = 14.0;
constexpr double kTitleLine = 22.0;
constexpr double kLegendLine = 18.0;

std::string Format(const char* fmt, double x) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), fmt, x);
  return buf;
}

void Grow(Rect* r, const Vec2& p, double pad) {
  r->min = r->min.cwiseMin(p - Vec2(pad, pad));
  r->max = r->max.cwiseMax(p + Vec2(pad, pad));
}

// The world area shown: the map bounds plus everything that moved (an agent may leave them).
Rect WorldExtent(const EpisodeFigure& fig) {
  const Scenario& sc = *fig.scenario;
  Rect r{Vec2(kInfinity, kInfinity), Vec2(-kInfinity, -kInfinity)};
  if (sc.map && sc.map->bounds.Area() > 0.0) r = sc.map->bounds;
  if (sc.map) {
    for (const Rect& o : sc.map->rectangles) {
      Grow(&r, o.min, 0.0);
      Grow(&r, o.max, 0.0);
    }
  }
  Grow(&r, sc.robot_start, 0.5);
  Grow(&r, sc.robot_goal, 0.5);
  for (const HumanSpec& h : sc.humans) {
    Grow(&r, h.start, h.radius);
    for (const Vec2& g : h.goals) Grow(&r, g, h.radius);
  }
  for (const RobotTrack& t : fig.robots) {
    for (const EpisodeFrame& f : t.result->trajectory) {
      Grow(&r, f.robot.position, f.robot.radius);
      for (const AgentState& h : f.humans) Grow(&r, h.position, h.radius);
    }
  }
  return r.Inflated(0.2);
}

// Whether an episode ended in a collision (with a human or an obstacle).
bool Collided(const EpisodeResult& r) {
  return r.status == EpisodeStatus::kCollisionHuman ||
         r.status == EpisodeStatus::kCollisionObstacle;
}

// The frame drawn of a trajectory: `frame` clamped to its end, or its end in a full figure.
size_t LastFrame(const std::vector<EpisodeFrame>& tr, std::optional<size_t> frame) {
  return frame ? std::min(*frame, tr.size() - 1) : tr.size() - 1;
}

// The humans' frames, from one track (with invisible robots they are the same in every row).
const std::vector<EpisodeFrame>& HumanFrames(const EpisodeFigure& fig) {
  return fig.robots[std::min(fig.humans_from, fig.robots.size() - 1)].result->trajectory;
}

// Whether the sensor snapshot is drawn: full figures only.
bool WithSensors(const EpisodeFigure& fig, std::optional<size_t> frame) {
  return !frame && fig.sensors.has_value();
}

// One agent's path up to `last` with a dot (and its time) every `interval` seconds.
void DrawTrack(Drawing* d, const View& v, const std::vector<Vec2>& pts,
               const std::vector<double>& times, const std::string& who, const Color& color,
               double width, const FigureOptions& opt, double label_size) {
  std::vector<Vec2> canvas;
  canvas.reserve(pts.size());
  for (const Vec2& p : pts) canvas.push_back(v.ToCanvas(p));
  d->AddPolyline("trajectory " + who, canvas,
                 Stroke(color.WithAlpha(who == "robot" ? 1.0 : 0.8), width));
  if (opt.time_mark_interval <= 0.0) return;
  double next = opt.time_mark_interval;
  std::optional<Vec2> last_label;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (times[i] + 1e-9 < next) continue;
    d->AddCircle("timemark " + who, canvas[i], who == "robot" ? 3.2 : 2.4, Filled(color));
    // An agent that waits would stack its labels into an unreadable blot: the first one stays.
    const bool crowded = last_label && (canvas[i] - *last_label).norm() < 2.5 * label_size;
    if (opt.time_labels && !crowded) {
      last_label = canvas[i];
      d->AddText("timelabel " + who, canvas[i] + Vec2(4.0, -4.0), Format("%.0fs", next), label_size,
                 color);
    }
    while (next <= times[i] + 1e-9) next += opt.time_mark_interval;
  }
}

void DrawDisc(Drawing* d, const View& v, const AgentState& s, const std::string& cls,
              const Color& color, const std::string& label) {
  const Vec2 c = v.ToCanvas(s.position);
  d->AddCircle(cls, c, v.Length(s.radius), Filled(color.WithAlpha(0.3), color, 1.6));
  if (!label.empty()) {
    d->AddText("agent-id", c + Vec2(0.0, 3.5), label, 10.0, palette::kInk, TextAnchor::kMiddle);
  }
}

// The robot's heading: a wedge from its disc's edge outwards (the goal's direction for a
// holonomic robot, its body's for a unicycle).
void DrawHeading(Drawing* d, const View& v, const AgentState& s, const Color& color) {
  const Vec2 dir(std::cos(s.heading), std::sin(s.heading));
  const Vec2 side(-dir.y(), dir.x());
  const double r = s.radius;
  const std::vector<Vec2> wedge = {v.ToCanvas(s.position + dir * (r * 1.6)),
                                   v.ToCanvas(s.position + dir * (r * 0.8) + side * (r * 0.45)),
                                   v.ToCanvas(s.position + dir * (r * 0.8) - side * (r * 0.45))};
  d->AddPolygon("heading robot", wedge, Filled(color, color, 1.0));
}

// A red ring around what the robot hit: the human's disc or the obstacle's outline.
void DrawCollisionPartner(Drawing* d, const View& v, const Scenario& sc, const EpisodeResult& r,
                          const EpisodeFrame& humans_at_end) {
  if (r.collided_human >= 0 &&
      static_cast<size_t>(r.collided_human) < humans_at_end.humans.size()) {
    const AgentState& h = humans_at_end.humans[r.collided_human];
    d->AddCircle("collision-partner", v.ToCanvas(h.position), v.Length(h.radius) + 3.0,
                 Stroke(palette::kCollision, 2.6));
  }
  if (r.collided_rect >= 0 && sc.map &&
      static_cast<size_t>(r.collided_rect) < sc.map->rectangles.size()) {
    AddWorldRect(d, v, "collision-partner", sc.map->rectangles[r.collided_rect],
                 Stroke(palette::kCollision, 2.6));
  }
}

// The key's entries: the marks this figure draws.
std::vector<KeyEntry> KeyEntries(const EpisodeFigure& fig, std::optional<size_t> frame,
                                 const FigureOptions& opt) {
  const Scenario& sc = *fig.scenario;
  std::vector<KeyEntry> e = {{KeyMark::kRobotStart, "robot start"},
                             {KeyMark::kRobotGoal, "robot goal"}};
  if (!sc.humans.empty()) {
    e.push_back({KeyMark::kHumanStart, "human start"});
    e.push_back({KeyMark::kHumanGoal, "human goal"});
  }
  if (opt.time_mark_interval > 0.0) {
    char every[48];
    std::snprintf(every, sizeof(every), "path, dot every %g s", opt.time_mark_interval);
    e.push_back({KeyMark::kTimeDot, every});
  }
  e.push_back({KeyMark::kEndDisc,
               frame ? "agent now (radius to scale)" : "final position (radius to scale)"});
  if (sc.map && !sc.map->rectangles.empty()) e.push_back({KeyMark::kObstacle, "obstacle"});
  if (sc.map && sc.map->mask && sc.map->mask->width > 0) {
    e.push_back({KeyMark::kMask, "blocked in the plan (not collidable)"});
  }
  if (!frame && fig.sensors) {
    bool lidar = false, people = false;
    for (const SensorReading& r : fig.sensors->readings) {
      lidar = lidar || !r.ranges.empty();
      people = people || r.ranges.empty();
    }
    if (lidar) e.push_back({KeyMark::kLidar, "lidar beam, hit"});
    if (people) e.push_back({KeyMark::kPersonReading, "person detection, velocity 1 s"});
  }
  // Listed for every frame of an animation that ends in a collision, not only the last: all
  // frames of an animation have one size.
  bool collided = false, partner = false;
  for (const RobotTrack& t : fig.robots) {
    const bool c = Collided(*t.result);
    collided = collided || c;
    partner = partner || (c && (t.result->collided_human >= 0 || t.result->collided_rect >= 0));
  }
  if (collided) e.push_back({KeyMark::kCollision, "collision"});
  if (partner) e.push_back({KeyMark::kCollisionPartner, "what was hit"});
  return e;
}

// Throws std::invalid_argument unless the figure has a scenario and recorded robot tracks.
void CheckFigure(const EpisodeFigure& fig) {
  if (fig.scenario == nullptr || fig.robots.empty()) {
    throw std::invalid_argument("an episode figure needs a scenario and at least one robot track");
  }
  for (const RobotTrack& t : fig.robots) {
    if (t.result == nullptr || t.result->trajectory.empty()) {
      throw std::invalid_argument("robot track '" + t.label +
                                  "' has no recorded trajectory (replay with recording on)");
    }
  }
}

// Where things go: the world fitted below the header and above the key (when shown).
struct Layout {
  View view;
  std::optional<FigureKey> key;
};

// Sizes the header (title, a line per robot, the sensor or clock line) and the key.
Layout LayOut(const EpisodeFigure& fig, std::optional<size_t> frame, const FigureOptions& opt) {
  const int header_lines =
      static_cast<int>(fig.robots.size()) + (WithSensors(fig, frame) || frame ? 1 : 0);
  const double header = kTitleLine + kLegendLine * header_lines + 6.0;
  const Rect extent = WorldExtent(fig);
  // The key's height depends on the canvas width, which the footer does not change.
  const View fitted = View::Fit(extent, opt.max_side, kMargin, header);
  std::optional<FigureKey> key;
  if (opt.key) key.emplace(KeyEntries(fig, frame, opt), fitted.scale(), fitted.width(), kMargin);
  return {View::Fit(extent, opt.max_side, kMargin, header, key ? key->height() : 0.0),
          std::move(key)};
}

// Every human's goals, start and path up to the frame drawn.
void DrawHumanPaths(Drawing* d, const View& v, const EpisodeFigure& fig,
                    std::optional<size_t> frame, const FigureOptions& opt) {
  const Scenario& sc = *fig.scenario;
  const std::vector<EpisodeFrame>& hframes = HumanFrames(fig);
  const size_t hlast = LastFrame(hframes, frame);
  FigureOptions human_opt = opt;
  if (frame) human_opt.time_labels = false;
  for (size_t i = 0; i < hframes[0].humans.size(); ++i) {
    const Color c = palette::Human(static_cast<int>(i));
    std::vector<Vec2> pts;
    std::vector<double> times;
    for (size_t f = 0; f <= hlast; ++f) {
      if (!hframes[f].Present(i)) continue;  // a recorded person before or after its track
      pts.push_back(hframes[f].humans[i].position);
      times.push_back(hframes[f].time);
    }
    if (pts.empty()) continue;
    if (i < sc.humans.size()) {
      for (const Vec2& g : sc.humans[i].goals) {
        d->AddPolygon("goal human", Diamond(v.ToCanvas(g), 4.5), Stroke(c, 1.4));
      }
    }
    d->AddCircle("start human", v.ToCanvas(pts.front()), 3.0, Stroke(c, 1.4));
    DrawTrack(d, v, pts, times, "human", c, 1.6, human_opt, 8.5);
  }
}

// The robots' shared start and goal, and each robot's path up to the frame drawn.
void DrawRobotPaths(Drawing* d, const View& v, const EpisodeFigure& fig,
                    std::optional<size_t> frame, const FigureOptions& opt) {
  const Scenario& sc = *fig.scenario;
  d->AddPolygon("start robot", Square(v.ToCanvas(sc.robot_start), 5.0),
                Filled(Color{255, 255, 255, 1.0}, palette::kInk, 1.6));
  d->AddPolygon("goal robot", Star(v.ToCanvas(sc.robot_goal), 9.0),
                Filled(Color{255, 215, 0, 1.0}, palette::kInk, 1.2));
  for (const RobotTrack& t : fig.robots) {
    const auto& tr = t.result->trajectory;
    const size_t last = LastFrame(tr, frame);
    std::vector<Vec2> pts;
    std::vector<double> times;
    for (size_t f = 0; f <= last; ++f) {
      pts.push_back(tr[f].robot.position);
      times.push_back(tr[f].time);
    }
    FigureOptions robot_opt = opt;
    if (frame) robot_opt.time_labels = false;
    DrawTrack(d, v, pts, times, "robot", t.color, 2.6, robot_opt, 10.5);
  }
}

// A dashed line through the members of each walking group (consecutive in the list), closed
// for three or more: who walks with whom.
void DrawGroupLinks(Drawing* d, const View& v, const std::vector<AgentState>& people) {
  for (size_t first = 0; first < people.size();) {
    size_t end = first + 1;
    if (people[first].group >= 0) {
      while (end < people.size() && people[end].group == people[first].group) ++end;
    }
    if (end - first >= 2) {
      std::vector<Vec2> pts;
      for (size_t i = first; i < end; ++i) pts.push_back(v.ToCanvas(people[i].position));
      if (end - first >= 3) pts.push_back(pts.front());
      d->AddPolyline("group", std::move(pts), Stroke(palette::kGroupLink, 1.4, true));
    }
    first = end;
  }
}

// Discs where everybody ended (or is, in an animation frame); a collision ringed at its end.
void DrawDiscs(Drawing* d, const View& v, const EpisodeFigure& fig, std::optional<size_t> frame) {
  const std::string disc = frame ? "agent" : "final";
  const std::vector<EpisodeFrame>& hframes = HumanFrames(fig);
  const EpisodeFrame& humans_now = hframes[LastFrame(hframes, frame)];
  DrawGroupLinks(d, v, humans_now.humans);
  for (size_t i = 0; i < hframes[0].humans.size(); ++i) {
    if (!humans_now.Present(i)) continue;
    DrawDisc(d, v, humans_now.humans[i], disc + " human", palette::Human(static_cast<int>(i)),
             std::to_string(i + 1));
  }
  for (const RobotTrack& t : fig.robots) {
    const auto& tr = t.result->trajectory;
    const EpisodeFrame& f = tr[LastFrame(tr, frame)];
    DrawDisc(d, v, f.robot, disc + " robot", t.color, "R");
    DrawHeading(d, v, f.robot, t.color);
    if (Collided(*t.result) && (!frame || *frame + 1 >= tr.size())) {
      d->AddCircle("collision-mark", v.ToCanvas(f.robot.position), v.Length(f.robot.radius) + 5.0,
                   Stroke(palette::kCollision, 2.2, true));
      DrawCollisionPartner(d, v, *fig.scenario, *t.result, f);
    }
  }
}

// The animation's clock: the longest track keeps it running after the other ended.
double Clock(const EpisodeFigure& fig, size_t frame) {
  double clock = 0.0;
  for (const RobotTrack& t : fig.robots)
    clock = std::max(clock, t.result->trajectory[LastFrame(t.result->trajectory, frame)].time);
  return clock;
}

// Header: title, one legend line per robot, then the sensor or clock line.
void DrawHeader(Drawing* d, const EpisodeFigure& fig, std::optional<size_t> frame) {
  double y = kMargin + 14.0;
  d->AddText("title", Vec2(kMargin, y), fig.title, 14.0, palette::kInk, TextAnchor::kStart, true);
  y += kTitleLine - 2.0;
  for (const RobotTrack& t : fig.robots) {
    d->AddPolyline("legend-swatch", {Vec2(kMargin, y - 4.0), Vec2(kMargin + 22.0, y - 4.0)},
                   Stroke(t.color, 3.0));
    d->AddText("legend", Vec2(kMargin + 30.0, y), t.label, 12.0, palette::kInk);
    y += kLegendLine;
  }
  if (WithSensors(fig, frame)) {
    const SensorSnapshot& s = *fig.sensors;
    d->AddText("sensor-caption", Vec2(kMargin, y),
               "sensors at step " + std::to_string(s.step) + ", t = " + Format("%.2f", s.time) +
                   " s: " + SensorList(s),
               12.0, palette::kMutedInk);
  } else if (frame) {
    d->AddText("clock", Vec2(kMargin, y), "t = " + Format("%.2f", Clock(fig, *frame)) + " s", 12.0,
               palette::kMutedInk);
  }
}

// Shared by the full figure (frame = none) and the animation frames: the layers bottom to top.
Drawing Build(const EpisodeFigure& fig, std::optional<size_t> frame, const FigureOptions& opt) {
  CheckFigure(fig);
  const Layout layout = LayOut(fig, frame, opt);
  const View& v = layout.view;
  Drawing d;
  d.width = std::round(v.width());
  d.height = std::round(v.height());
  if (fig.scenario->map) DrawMap(&d, v, *fig.scenario->map);
  DrawHumanPaths(&d, v, fig, frame, opt);
  DrawRobotPaths(&d, v, fig, frame, opt);
  DrawDiscs(&d, v, fig, frame);
  if (WithSensors(fig, frame)) DrawSensorSnapshot(&d, v, *fig.sensors, fig.robots[0].color);
  DrawHeader(&d, fig, frame);
  if (layout.key) layout.key->Draw(&d, v.height() - kMargin - layout.key->height() + 6.0);
  return d;
}

}  // namespace

Drawing DrawEpisode(const EpisodeFigure& figure, const FigureOptions& options) {
  return Build(figure, std::nullopt, options);
}

Drawing DrawEpisodeFrame(const EpisodeFigure& figure, size_t frame, const FigureOptions& options) {
  return Build(figure, frame, options);
}

size_t FrameCount(const EpisodeFigure& figure) {
  size_t n = 0;
  for (const RobotTrack& t : figure.robots)
    n = std::max(n, t.result ? t.result->trajectory.size() : 0);
  return n;
}

}  // namespace crowdsim::render
