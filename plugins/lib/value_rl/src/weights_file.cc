#include "value_rl/weights_file.h"

#include <torch/serialize/input-archive.h>
#include <torch/serialize/output-archive.h>

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "atomic_file.h"
#include "crowdsim/input_file.h"
#include "value_rl/zip_crc_check.h"

namespace crowdsim::value_rl {
namespace fs = std::filesystem;

namespace {

constexpr int64_t kFormatVersion = 1;

std::string Found(torch::serialize::InputArchive& archive, const std::string& key) {
  c10::IValue v;
  if (!archive.try_read(key, v)) return "(missing)";
  if (v.isString()) return v.toStringRef();
  if (v.isInt()) return std::to_string(v.toInt());
  return "(unreadable)";
}

/// The route prior as written in files and messages: "0" for none, the weight for the linear
/// shape (as files before the shapes have it), "<weight> discounted" for the other.
std::string PriorText(double w, RoutePriorShape shape) {
  if (w == 0.0) return "0";
  std::ostringstream s;
  s << std::setprecision(15) << w;
  if (shape != RoutePriorShape::kLinear) s << ' ' << RoutePriorShapeName(shape);
  return s.str();
}

}  // namespace

WeightsMeta MetaOf(const ValueRlConfig& config) {
  return WeightsMeta{ModelName(config.model),
                     SensorsLabel(config),
                     config.ActionCount(),
                     config.LidarInputs(),
                     config.route_prior,
                     config.route_prior_shape,
                     config.unicycle_actions ? "unicycle" : "holonomic"};
}

void SaveWeightsFile(const ValueNetwork& net, const WeightsMeta& meta, const fs::path& file) {
  torch::serialize::OutputArchive archive;
  archive.write("crowdsim_format", c10::IValue(kFormatVersion));
  archive.write("crowdsim_model", c10::IValue(meta.model));
  archive.write("crowdsim_sensors", c10::IValue(meta.sensors));
  archive.write("crowdsim_actions", c10::IValue(meta.actions));
  archive.write("crowdsim_lidar_beams", c10::IValue(meta.lidar_beams));
  if (meta.route_prior != 0.0)
    archive.write("crowdsim_route_prior",
                  c10::IValue(PriorText(meta.route_prior, meta.route_prior_shape)));
  if (meta.action_space != "holonomic")
    archive.write("crowdsim_action_space", c10::IValue(meta.action_space));
  net.save(archive);
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  SaveArchive(archive, file);
}

void SaveArchive(torch::serialize::OutputArchive& archive, const fs::path& file) {
  // In memory first: libtorch's file writer aborts the process when the disk fills.
  std::ostringstream bytes;
  archive.save_to(bytes);
  common::WriteFileAtomically(file, bytes.str());
}

void LoadWeightsFile(const WeightsMeta& expected, const fs::path& file, ValueNetwork* net) {
  if (const std::string why = NotARegularFile(file); !why.empty()) {
    throw std::runtime_error("weights file '" + file.string() + "' " + why +
                             (fs::exists(file) ? "" : " (train one with `crowdsim-bench train`)"));
  }
  if (const std::optional<ZipDamage> damage = FindZipDamage(file)) {
    throw std::runtime_error(
        "weights file '" + file.string() +
        "' is damaged: " + (damage->entry.empty() ? "" : "entry '" + damage->entry + "': ") +
        damage->problem + "; train it again (`crowdsim-bench train`) or download it again");
  }
  torch::serialize::InputArchive archive;
  try {
    archive.load_from(file.string());
  } catch (const c10::Error& e) {
    throw std::runtime_error("weights file '" + file.string() +
                             "' is not a libtorch archive written by crowdsim-bench train");
  }
  const std::pair<std::string, std::string> checks[] = {
      {"model", expected.model},
      {"sensors", expected.sensors},
      {"actions", std::to_string(expected.actions)},
      {"lidar_beams", std::to_string(expected.lidar_beams)},
      {"route_prior", PriorText(expected.route_prior, expected.route_prior_shape)},
      {"action_space", expected.action_space},
  };
  std::string mismatch;
  for (const auto& [key, want] : checks) {
    std::string got = Found(archive, "crowdsim_" + key);
    if (key == "route_prior" && got == "(missing)") got = "0";  // older files
    if (key == "action_space" && got == "(missing)") got = "holonomic";
    if (got != want) {
      mismatch += (mismatch.empty() ? "" : "; ") + key + ": expected " + want + ", found " + got;
    }
  }
  if (!mismatch.empty()) {
    throw std::runtime_error("weights file '" + file.string() +
                             "' was trained for another configuration (" + mismatch +
                             "); use weights trained with these parameters or change them");
  }
  try {
    net->load(archive);
  } catch (const c10::Error& e) {
    throw std::runtime_error("weights file '" + file.string() +
                             "' does not fit the network: " + e.what_without_backtrace());
  }
}

}  // namespace crowdsim::value_rl
