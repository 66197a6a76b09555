#include "validation_table.h"

#include <cstdio>

#include "crowdsim/bench/csv.h"

namespace crowdsim::crowds {

ValidationRow Summarise(const std::string& scene, const std::string& model,
                        std::span<const PersonValidation> people) {
  ValidationRow row{scene, model, static_cast<int>(people.size())};
  if (people.empty()) return row;
  for (const PersonValidation& p : people) {
    row.ade += p.comparison.ade;
    row.fde += p.comparison.fde;
    row.collision_rate += p.collided ? 1.0 : 0.0;
    row.simulated_speed += p.comparison.simulated_speed;
    row.recorded_speed += p.comparison.recorded_speed;
  }
  const double n = static_cast<double>(people.size());
  for (double* v :
       {&row.ade, &row.fde, &row.collision_rate, &row.simulated_speed, &row.recorded_speed})
    *v /= n;
  return row;
}

namespace {

// The row's numbers after its scene, model and count, `digits` decimals, `separator` between.
std::string Numbers(const ValidationRow& r, int digits, const char* separator) {
  char buf[256];
  std::snprintf(buf, sizeof(buf), "%d%s%.*f%s%.*f%s%.*f%s%.*f%s%.*f", r.people, separator, digits,
                r.ade, separator, digits, r.fde, separator, digits, r.collision_rate, separator,
                digits, r.simulated_speed, separator, digits, r.recorded_speed);
  return buf;
}

}  // namespace

std::string ValidationCsv(std::span<const ValidationRow> rows) {
  std::string out =
      "scene,model,people,ade_m,fde_m,collision_rate,simulated_speed_mps,recorded_speed_mps\n";
  for (const ValidationRow& r : rows)
    out += CsvField(r.scene) + "," + CsvField(r.model) + "," + Numbers(r, 4, ",") + "\n";
  return out;
}

std::string ValidationMarkdown(std::span<const ValidationRow> rows) {
  std::string out =
      "| scene | model | people | ADE (m) | FDE (m) | collision rate | simulated speed (m/s) | "
      "recorded speed (m/s) |\n|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const ValidationRow& r : rows)
    out += "| " + r.scene + " | " + r.model + " | " + Numbers(r, 3, " | ") + " |\n";
  return out;
}

}  // namespace crowdsim::crowds
