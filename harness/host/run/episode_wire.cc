#include "run/episode_wire.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace crowdsim {
namespace {

// Numbers travel as their bytes (parent and worker are one program), strings with their length.
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
    if (n > bytes_.size() - at_)
      throw std::runtime_error("an isolated worker sent a cut episode result");
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace

// Both follow kEpisodeColumns, so every value episodes.csv stores travels, unrounded.

std::string EncodeEpisodeLine(const EpisodeLine& line) {
  std::string out;
  for (const EpisodeColumn& c : kEpisodeColumns) {
    std::visit(
        [&](auto member) {
          const auto& v = ColumnValue(line, member);
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) {
            PutText(v, &out);
          } else {
            PutRaw(v, &out);
          }
        },
        c.field);
  }
  return out;
}

EpisodeLine DecodeEpisodeLine(std::string_view bytes) {
  Reader in(bytes);
  EpisodeLine line;
  for (const EpisodeColumn& c : kEpisodeColumns) {
    std::visit(
        [&](auto member) {
          auto& v = ColumnValue(line, member);
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, std::string>) {
            v = in.Text();
          } else {
            v = in.Raw<T>();
          }
        },
        c.field);
  }
  if (!in.AtEnd())
    throw std::runtime_error("an isolated worker sent an episode result with extra bytes");
  return line;
}

}  // namespace crowdsim
