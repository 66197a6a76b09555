// JSON files the harness writes and reads back (manifest.json, a training's summary.json),
// through nlohmann-json. Private to the core: nlohmann's header stays out of the public ones.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace crowdsim {

/// The object in a JSON file; an empty object when the file is absent, unreadable, not JSON
/// or not an object (callers treat every field as absent then).
nlohmann::ordered_json ReadJsonFile(const std::filesystem::path& path);

/// Indented by two spaces, keys in insertion order, newline-terminated; invalid UTF-8 in a
/// string (a user's label or path) is replaced rather than refused.
std::string FormatJson(const nlohmann::ordered_json& json);

}  // namespace crowdsim
