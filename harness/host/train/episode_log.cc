#include "train/episode_log.h"

#include <stdexcept>
#include <system_error>

namespace crowdsim::training {

void EpisodeLog::Open(const std::filesystem::path& file, std::int64_t keep_bytes) {
  namespace fs = std::filesystem;
  file_ = file;
  std::error_code ec;
  if (keep_bytes >= 0 && fs::exists(file)) {
    if (static_cast<std::int64_t>(fs::file_size(file)) < keep_bytes) {
      throw std::runtime_error("'" + file.string() +
                               "' is shorter than its checkpoint recorded; "
                               "it was edited or cut: move it away to continue without it");
    }
    fs::resize_file(file, static_cast<std::uintmax_t>(keep_bytes), ec);
    if (ec) throw std::runtime_error("cannot cut '" + file.string() + "' back: " + ec.message());
  } else if (keep_bytes < 0) {
    fs::remove(file, ec);
  }
  const bool fresh = !fs::exists(file) || fs::file_size(file) == 0;
  out_.open(file, std::ios::app);
  if (!out_) throw std::runtime_error("cannot write '" + file.string() + "'");
  out_.precision(6);
  if (fresh) out_ << kHeader << "\n";
}

void EpisodeLog::Append(const EpisodeLogRow& r) {
  out_ << r.phase << "," << r.index << "," << r.epsilon << "," << r.outcome << ","
       << r.discounted_return << "," << r.steps << "," << r.loss << "," << r.memory_size;
  for (std::size_t m : r.memory) out_ << "," << m;
  out_ << "\n";
}

std::int64_t EpisodeLog::Flush() {
  out_.flush();
  if (!out_) throw std::runtime_error("cannot write '" + file_.string() + "'");
  return static_cast<std::int64_t>(std::filesystem::file_size(file_));
}

}  // namespace crowdsim::training
