// JSON files via nlohmann-json; private, keeping nlohmann's header out of public ones.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace crowdsim {

/// The object in a JSON file; empty when absent, unreadable or not a JSON object.
nlohmann::ordered_json ReadJsonFile(const std::filesystem::path& path);

/// Two-space indent, insertion order, trailing newline; invalid UTF-8 is replaced, not refused.
std::string FormatJson(const nlohmann::ordered_json& json);

}  // namespace crowdsim
