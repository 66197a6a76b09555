// The suite report's episode pictures: for every row of the table its first success, collision
// and timeout, replayed exactly and drawn as a thumbnail that links to the full figure.
#pragma once

#include <string>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/render/report.h"
#include "crowdsim/render/report_inputs.h"

namespace crowdsim::render {

/// The report's two sections of episode pictures, as HTML.
struct EpisodeSections {
  std::string thumbnails;  ///< per row, its three thumbnails (or why one is missing)
  std::string figures;     ///< the full figures the thumbnails link to
};

/// Replays and draws the picked episodes of every table row.
EpisodeSections EpisodePictures(const ReportInputs& in, PluginRegistry& registry,
                                const ReportOptions& options);

}  // namespace crowdsim::render
