// Text made safe for XML and HTML: SVG figures, the HTML reports, the floor-plan preview.
#pragma once

#include <string>

namespace crowdsim::render {

/// `s` with &, <, > and " escaped for XML/HTML text and attribute values.
std::string XmlEscape(const std::string& s);

}  // namespace crowdsim::render
