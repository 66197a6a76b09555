// score: the social navigation metrics of episode logs, by the code a suite run uses.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "crowdsim/bench/csv.h"
#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/episode_log.h"
#include "crowdsim/cli/args.h"

namespace crowdsim::cli {

namespace {

namespace fs = std::filesystem;

bool IsLog(const fs::path& p) {
  const std::string name = p.filename().string();
  return name.ends_with(".jsonl.gz") || name.ends_with(".jsonl");
}

// The logs an argument names: the file, or a folder's logs (searched through), sorted.
std::vector<fs::path> LogsOf(const fs::path& arg) {
  if (!fs::is_directory(arg)) {
    if (!fs::exists(arg)) throw UsageError("score: no file or folder '" + arg.string() + "'");
    return {arg};
  }
  std::vector<fs::path> logs;
  for (const auto& entry : fs::recursive_directory_iterator(arg)) {
    if (entry.is_regular_file() && IsLog(entry.path())) logs.push_back(entry.path());
  }
  std::sort(logs.begin(), logs.end());
  if (logs.empty())
    throw UsageError("score: the folder '" + arg.string() + "' holds no *.jsonl.gz or *.jsonl");
  return logs;
}

}  // namespace

int ScoreCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out"}, {});
  if (a.positional.empty()) throw UsageError("score needs episode logs or folders of them");
  std::vector<fs::path> logs;
  for (const std::string& arg : a.positional) {
    for (fs::path& p : LogsOf(arg)) logs.push_back(std::move(p));
  }
  const std::vector<const EpisodeColumn*> columns = [] {
    std::vector<const EpisodeColumn*> social;
    for (const EpisodeColumn* c : EpisodeColumnsOf(kLogMetrics)) {
      if (Social(*c)) social.push_back(c);
    }
    return social;
  }();
  std::ostringstream csv;
  csv << "log,status";
  for (const EpisodeColumn* c : columns) csv << ',' << c->name;
  csv << '\n';
  int failed = 0;
  for (const fs::path& path : logs) {
    EpisodeLine line;
    try {
      const EpisodeLog log = ReadEpisodeLog(path);
      line.outcome.status = *log.status;
      line.outcome.social = ScoreEpisodeLog(log);
    } catch (const std::exception& e) {
      std::cerr << "score: " << e.what() << "\n";
      ++failed;
      continue;
    }
    csv << CsvField(path.string()) << ',' << EpisodeStatusName(line.outcome.status);
    for (const EpisodeColumn* c : columns) csv << ',' << FormatEpisodeCell(*c, line);
    csv << '\n';
  }
  if (const auto out = a.Get("--out")) {
    std::ofstream f(*out, std::ios::binary);
    f << csv.str();
    if (!f.flush()) throw UsageError("score: cannot write --out '" + *out + "'");
    std::cerr << "wrote " << *out << "\n";
  } else {
    std::cout << csv.str();
  }
  std::cerr << "score: " << logs.size() - failed << " of " << logs.size() << " log(s) scored"
            << (failed ? "; the others are named above and left out" : "") << "\n";
  return failed ? 1 : 0;
}

}  // namespace crowdsim::cli
