// Horizontal bar charts as inline SVG text for the HTML report (no scripts, no fonts to load).
#pragma once

#include <string>
#include <vector>

#include "crowdsim/render/drawing.h"

namespace crowdsim::render {

/// One coloured part of a bar.
struct BarSegment {
  std::string name;  ///< legend entry, e.g. "success"
  double value = 0.0;
  Color color;
};

/// One labelled bar (one segment: a plain bar; more: stacked).
struct Bar {
  std::string label;
  std::vector<BarSegment> segments;
};

/// Chart layout and number format.
struct BarChartOptions {
  std::string title;
  double max_value = 0.0;  ///< axis end; 0 = the longest bar
  int decimals = 2;        ///< of the value printed after each bar
  std::string unit;        ///< appended to printed values, e.g. " s"
  bool legend = false;     ///< a legend of the first bar's segment names
};

/// The chart as an <svg> element (deterministic text).
std::string BarChartSvg(const std::vector<Bar>& bars, const BarChartOptions& options);

}  // namespace crowdsim::render
