// Env.render(): the current state of an episode drawn as the CLI's animation frames are
// (map, trails so far, everybody's disc, clock, key), rasterised for an RGB array.
#pragma once

#include <string>

#include "crowdsim/bench/episode.h"
#include "crowdsim/render/cairo_backend.h"
#include "crowdsim/scenario.h"

namespace crowdsim::python {

/// `result` must hold a recorded trajectory; `scale` px per drawing px.
render::RgbImage RenderEpisodeFrame(const Scenario& scenario, const EpisodeResult& result,
                                    const std::string& title, double scale);

}  // namespace crowdsim::python
