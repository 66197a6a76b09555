// Base64 for data: URIs (self-contained SVG figures and HTML reports).
#pragma once

#include <string>
#include <string_view>

namespace crowdsim::render {

/// Standard base64 (RFC 4648, with padding).
std::string Base64(std::string_view bytes);

}  // namespace crowdsim::render
