#include "episode_wire.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace crowdsim {
namespace {

// The record's numbers travel as their bytes: parent and worker are one program.
static_assert(std::is_trivially_copyable_v<EpisodeRecord>, "EpisodeRecord is sent as raw bytes");

template <typename T>
void PutRaw(const T& value, std::string* out) {
  static_assert(std::is_trivially_copyable_v<T>);
  out->append(reinterpret_cast<const char*>(&value), sizeof(T));
}

void PutText(const std::string& s, std::string* out) {
  PutRaw(static_cast<std::uint64_t>(s.size()), out);
  out->append(s);
}

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}

  template <typename T>
  T Raw() {
    T value;
    std::memcpy(&value, Take(sizeof(T)), sizeof(T));
    return value;
  }
  std::string Text() {
    const auto n = Raw<std::uint64_t>();
    return std::string(Take(n), n);
  }
  bool AtEnd() const { return at_ == bytes_.size(); }

 private:
  const char* Take(std::size_t n) {
    if (n > bytes_.size() - at_) throw std::runtime_error("an isolated worker sent a cut episode result");
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::string EncodeEpisodeLine(const EpisodeLine& line) {
  std::string out;
  PutText(line.row, &out);
  PutRaw(line.episode, &out);
  PutRaw(line.seed, &out);
  PutText(line.layout, &out);
  PutRaw(line.record, &out);
  PutRaw(line.humans_at_goal, &out);
  PutText(line.error, &out);
  return out;
}

EpisodeLine DecodeEpisodeLine(std::string_view bytes) {
  Reader in(bytes);
  EpisodeLine line;
  line.row = in.Text();
  line.episode = in.Raw<int>();
  line.seed = in.Raw<std::uint64_t>();
  line.layout = in.Text();
  line.record = in.Raw<EpisodeRecord>();
  line.humans_at_goal = in.Raw<int>();
  line.error = in.Text();
  if (!in.AtEnd()) throw std::runtime_error("an isolated worker sent an episode result with extra bytes");
  return line;
}

}  // namespace crowdsim
