#include "floorplan_dataset.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>

#include "crowdsim/bench/csv.h"
#include "floorplan_error.h"
#include "floorplan_import.h"

namespace crowdsim::floorplan {
namespace {

struct Entry {
  std::filesystem::path image;
  std::string source;  // gibson or hm3d
  bool ok = false;
  std::string error;
  WorldFile world;
  bool curated = false;
  std::string reason;  // why not curated
};

std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.4f", x);
  return buf;
}

std::string Curate(const WorldFile& w, const CurationRules& rules) {
  std::ostringstream why;
  if (StatValue(w, "free_area_m2") < rules.min_free_area_m2) {
    why << "free area < " << rules.min_free_area_m2 << " m2; ";
  }
  if (StatValue(w, "component_share") < rules.min_component_share) {
    why << "largest component < " << rules.min_component_share << " of the free area; ";
  }
  if (StatValue(w, "kept_coverage_pct") < rules.min_kept_coverage_pct) {
    why << "kept rectangles cover < " << rules.min_kept_coverage_pct << "%; ";
  }
  std::string s = why.str();
  if (!s.empty()) s.resize(s.size() - 2);
  return s;
}

void WriteText(const std::string& text, const std::filesystem::path& path) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) throw FloorplanError(path.string() + ": cannot write (check the folder is writable)");
}

}  // namespace

std::vector<std::filesystem::path> ListSourcePlans(const std::filesystem::path& source) {
  std::vector<std::filesystem::path> gibson, hm3d;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(source / "gibson" / "maps", ec)) {
    if (e.path().extension() == ".png") gibson.push_back(e.path());
  }
  for (const auto& e : std::filesystem::directory_iterator(source / "hm3d", ec)) {
    const std::string n = e.path().filename().string();
    if (n.size() > 9 && n.compare(n.size() - 9, 9, "_0.1m.png") == 0) hm3d.push_back(e.path());
  }
  std::sort(gibson.begin(), gibson.end());
  std::sort(hm3d.begin(), hm3d.end());
  gibson.insert(gibson.end(), hm3d.begin(), hm3d.end());
  return gibson;
}

int BuildDataset(const DatasetOptions& o, std::ostream& log) {
  const auto plans = ListSourcePlans(o.source);
  if (plans.empty()) {
    throw FloorplanError(o.source.string() +
                         ": no floor plans (expected gibson/maps/*.png and "
                         "hm3d/*_0.1m.png; pass --source ../shared/floorplans)");
  }
  std::vector<Entry> entries;
  double slowest = 0.0;
  std::string slowest_name;
  for (const auto& image : plans) {
    Entry e;
    e.image = image;
    e.source = image.parent_path().filename() == "maps" ? "gibson" : "hm3d";
    ImportOptions io;
    io.seed = o.seed;
    io.train_pairs = o.train_pairs;
    try {
      ImportResult r = ImportFloorplan(image, io);
      e.ok = true;
      e.world = std::move(r.world);
      e.reason = Curate(e.world, o.rules);
      e.curated = e.reason.empty();
      if (r.seconds > slowest) slowest = r.seconds, slowest_name = e.world.name;
      log << (e.curated ? "curated  " : "dropped  ") << e.world.name << "  (" << Num(r.seconds)
          << " s)" << (e.curated ? "" : ": " + e.reason) << "\n";
    } catch (const FloorplanError& err) {
      e.error = err.what();
      log << "failed   " << image.filename().string() << ": " << e.error << "\n";
    }
    entries.push_back(std::move(e));
  }

  // index.csv: every plan, its status and statistics (the keys of the first import).
  std::vector<std::string> keys;
  for (const auto& e : entries) {
    if (!e.ok) continue;
    for (const auto& kv : e.world.stats) keys.push_back(kv.first);
    break;
  }
  std::ostringstream index, curated;
  index << "name,source,status,curated,reason";
  curated << "name,source,free_area_m2,rectangles_kept,kept_coverage_pct,difficulty,world_file\n";
  for (const auto& k : keys) index << "," << k;
  index << "\n";
  int n_curated = 0, n_ok = 0;
  for (const auto& e : entries) {
    const std::string name = e.ok ? e.world.name : e.image.stem().string();
    index << CsvField(name) << "," << e.source << "," << (e.ok ? "ok" : "error") << ","
          << (e.curated ? 1 : 0) << "," << CsvField(e.ok ? e.reason : e.error);
    for (const auto& k : keys) index << "," << (e.ok ? Num(StatValue(e.world, k)) : "");
    index << "\n";
    n_ok += e.ok;
    if (!e.curated) continue;
    ++n_curated;
    curated << CsvField(name) << "," << e.source << "," << Num(StatValue(e.world, "free_area_m2"))
            << "," << Num(StatValue(e.world, "rectangles_kept")) << ","
            << Num(StatValue(e.world, "kept_coverage_pct")) << ","
            << Num(StatValue(e.world, "difficulty")) << "," << name << ".yaml\n";
  }
  // Remove world files of plans no longer curated, then write the curated ones.
  std::error_code ec;
  for (const auto& f : std::filesystem::directory_iterator(o.out, ec)) {
    if (f.path().extension() == ".yaml") std::filesystem::remove(f.path());
  }
  WriteText(index.str(), o.out / "index.csv");
  WriteText(curated.str(), o.out / "curated.csv");
  for (const auto& e : entries) {
    if (e.curated) WriteWorldFile(e.world, o.out / (e.world.name + ".yaml"));
  }
  log << "imported " << n_ok << " of " << entries.size() << " plans, curated " << n_curated
      << "; slowest import " << slowest_name << " " << Num(slowest) << " s\n";

  if (o.gibson_out.empty()) return 0;
  // Easy / medium / hard: curated Gibson plans whose rectangles model the plan well, ranked
  // by difficulty, taken at fixed quantiles.
  std::vector<const Entry*> pool;
  for (const auto& e : entries) {
    if (!e.curated || e.source != "gibson") continue;
    const double area = StatValue(e.world, "free_area_m2");
    if (StatValue(e.world, "kept_coverage_pct") < o.pick.min_kept_coverage_pct) continue;
    if (area < o.pick.min_free_area_m2 || area > o.pick.max_free_area_m2) continue;
    pool.push_back(&e);
  }
  if (pool.size() < 3) {
    throw FloorplanError("only " + std::to_string(pool.size()) +
                         " plans qualify for easy/medium/"
                         "hard; relax the pick rules in floorplan_dataset.h");
  }
  std::stable_sort(pool.begin(), pool.end(), [](const Entry* a, const Entry* b) {
    return StatValue(a->world, "difficulty") < StatValue(b->world, "difficulty");
  });
  static const char* kLevels[3] = {"easy", "medium", "hard"};
  for (int k = 0; k < 3; ++k) {
    const size_t at = static_cast<size_t>(o.pick.quantiles[k] * double(pool.size() - 1) + 0.5);
    const Entry& e = *pool[at];
    ImportOptions io;
    io.seed = o.seed;
    io.train_pairs = o.picked_train_pairs;
    const ImportResult r = ImportFloorplan(e.image, io);
    WriteWorldFile(r.world, o.gibson_out / (std::string(kLevels[k]) + ".yaml"));
    log << kLevels[k] << ": " << r.world.name << " (rank " << at + 1 << " of " << pool.size()
        << ", difficulty " << Num(StatValue(r.world, "difficulty")) << ")\n";
  }
  return 0;
}

}  // namespace crowdsim::floorplan
