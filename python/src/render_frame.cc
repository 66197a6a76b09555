#include "render_frame.h"

#include "crowdsim/render/episode_figure.h"
#include "crowdsim/render/palette.h"

namespace crowdsim::python {

render::RgbImage RenderEpisodeFrame(const Scenario& scenario, const EpisodeResult& result,
                                    const std::string& title, double scale) {
  render::EpisodeFigure figure;
  figure.scenario = &scenario;
  figure.title = title;
  const std::string outcome = EpisodeStatusName(result.status);
  figure.robots.push_back(
      render::RobotTrack{"robot: " + outcome, &result, render::palette::kRobot});
  const render::Drawing frame = render::DrawEpisodeFrame(figure, render::FrameCount(figure) - 1);
  return render::Rasterize(frame, scale);
}

}  // namespace crowdsim::python
