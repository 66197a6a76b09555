#include "spec/kinematics_reader.h"

#include "crowdsim/bench/closest_name.h"
#include "crowdsim/params.h"

namespace crowdsim::suite_internal {

namespace {

const std::vector<std::string> kModelNames = {"holonomic", "unicycle", "diff_drive"};

void ReadModel(Reader& r, const YAML::Node& n, const std::string& path, RobotKinematics* out) {
  const auto name = r.String(n, path);
  if (!name) return;
  if (!ParseKinematicsModel(*name, &out->model)) {
    r.Error(n, path,
            "value '" + *name + "' is not valid; valid: " + Join(kModelNames) +
                DidYouMean(*name, kModelNames));
  }
}

}  // namespace

void ReadKinematics(Reader& r, const YAML::Node& n, const std::string& path, RobotKinematics* out) {
  if (n.IsScalar()) {
    ReadModel(r, n, path, out);
    return;
  }
  if (!r.IsMap(n, path, "a model name, or model: and its limits")) return;
  r.CheckKeys(n, path, kKinematicsKeys);
  if (!Present(n["model"])) {
    r.Error(n, Reader::Child(path, "model"),
            "missing key 'model' (valid: " + Join(kModelNames) + ")");
    return;
  }
  ReadModel(r, n["model"], Reader::Child(path, "model"), out);
  // Limits: positive; absent: unlimited (CrowdNav), angular speed pi rad/s.
  auto limit = [&](const char* key, double* value) {
    if (!Present(n[key])) return;
    if (auto v = r.Number(n[key], Reader::Child(path, key), 0.0, 1e6, /*lo_open=*/true))
      *value = *v;
  };
  limit("angular_speed_max", &out->angular_speed_max);
  limit("accel_max", &out->accel_max);
  limit("angular_accel_max", &out->angular_accel_max);
  if (Present(n["track_velocity"])) {
    if (auto b = r.Bool(n["track_velocity"], Reader::Child(path, "track_velocity")))
      out->track_velocity = *b;
  }
  if (out->Holonomic()) {
    // A holonomic robot has no heading to turn: these would be ignored silently.
    for (const char* key : {"angular_speed_max", "angular_accel_max", "track_velocity"}) {
      if (Present(n[key])) {
        r.Error(n[key], Reader::Child(path, key),
                std::string("'") + key +
                    "' is for a unicycle or diff_drive robot; a holonomic robot takes only "
                    "accel_max");
      }
    }
  }
}

void CanonicalKinematics(const RobotKinematics& k, std::ostream& os) {
  const RobotKinematics plain;
  if (k.model == plain.model && k.angular_speed_max == plain.angular_speed_max &&
      k.accel_max == plain.accel_max && k.angular_accel_max == plain.angular_accel_max &&
      k.track_velocity == plain.track_velocity) {
    return;
  }
  os << " kinematics:" << KinematicsModelName(k.model)
     << ",angular_speed_max=" << FormatParamValue(k.angular_speed_max)
     << ",accel_max=" << FormatParamValue(k.accel_max)
     << ",angular_accel_max=" << FormatParamValue(k.angular_accel_max)
     << ",track_velocity=" << (k.track_velocity ? 1 : 0);
}

}  // namespace crowdsim::suite_internal
