#include "value_rl/zip_crc_check.h"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace crowdsim::value_rl {
namespace fs = std::filesystem;

namespace {

// Signatures and sizes of the zip records (PKWARE's APPNOTE), all little-endian.
constexpr uint32_t kLocalHeader = 0x04034b50;
constexpr uint32_t kCentralHeader = 0x02014b50;
constexpr uint32_t kEndRecord = 0x06054b50;
constexpr uint32_t kZip64EndRecord = 0x06064b50;
constexpr uint32_t kZip64Locator = 0x07064b50;
constexpr uint16_t kZip64ExtraId = 0x0001;
constexpr uint64_t kLocalHeaderSize = 30;
constexpr uint64_t kCentralHeaderSize = 46;
constexpr uint64_t kEndRecordSize = 22;
constexpr uint64_t kZip64LocatorSize = 20;
constexpr uint64_t kZip64EndRecordSize = 56;
constexpr uint32_t kSaturated32 = 0xFFFFFFFF;

// The archive's bytes with bounds-checked little-endian reads.
class Bytes {
 public:
  explicit Bytes(std::string data) : data_(std::move(data)) {}
  uint64_t size() const { return data_.size(); }
  bool Has(uint64_t at, uint64_t n) const { return at <= size() && n <= size() - at; }
  uint64_t Le(uint64_t at, int n) const {  // callers check Has(at, n) first
    uint64_t v = 0;
    for (int k = n - 1; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(data_[at + k]);
    return v;
  }
  const unsigned char* At(uint64_t at) const {
    return reinterpret_cast<const unsigned char*>(data_.data()) + at;
  }
  std::string Text(uint64_t at, uint64_t n) const { return data_.substr(at, n); }

 private:
  std::string data_;
};

std::string Hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", v);
  return buf;
}

Bytes ReadAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open '" + file.string() + "': " + std::strerror(errno));
  std::string data;
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  if (!ec) data.resize(size);
  if (!in.read(data.data(), static_cast<std::streamsize>(data.size()))) {
    throw std::runtime_error("cannot read '" + file.string() + "': " + std::strerror(errno));
  }
  return Bytes(std::move(data));
}

// Where the central directory is and how many entries it lists.
struct Directory {
  uint64_t offset = 0;
  uint64_t size = 0;
  uint64_t entries = 0;
};

// The end record: the last one whose comment ends exactly at the end of the file.
std::optional<uint64_t> FindEndRecord(const Bytes& b) {
  if (b.size() < kEndRecordSize) return std::nullopt;
  const uint64_t lowest =
      b.size() > kEndRecordSize + 0xFFFF ? b.size() - kEndRecordSize - 0xFFFF : 0;
  for (uint64_t at = b.size() - kEndRecordSize;; --at) {
    if (b.Le(at, 4) == kEndRecord && at + kEndRecordSize + b.Le(at + 20, 2) == b.size()) return at;
    if (at == lowest) return std::nullopt;
  }
}

// The central directory from the end record, or from the zip64 end record when the archive has
// one (libtorch writes it always; other writers when a count or an offset does not fit).
std::optional<Directory> ReadDirectory(const Bytes& b, uint64_t end) {
  if (end >= kZip64LocatorSize && b.Le(end - kZip64LocatorSize, 4) == kZip64Locator) {
    const uint64_t at = b.Le(end - kZip64LocatorSize + 8, 8);
    if (!b.Has(at, kZip64EndRecordSize) || b.Le(at, 4) != kZip64EndRecord) return std::nullopt;
    return Directory{b.Le(at + 48, 8), b.Le(at + 40, 8), b.Le(at + 32, 8)};
  }
  return Directory{b.Le(end + 16, 4), b.Le(end + 12, 4), b.Le(end + 10, 2)};
}

// One central directory record.
struct Entry {
  std::string name;
  uint16_t method = 0;
  uint32_t crc = 0;
  uint64_t compressed = 0;
  uint64_t uncompressed = 0;
  uint64_t local = 0;  ///< offset of its local header
};

// Replaces the saturated 32-bit fields by those of the zip64 extra field, in APPNOTE's order.
bool ApplyZip64Extra(const Bytes& b, uint64_t at, uint64_t length, Entry* e) {
  const uint64_t end = at + length;
  while (at + 4 <= end) {
    const uint64_t id = b.Le(at, 2), size = b.Le(at + 2, 2);
    if (at + 4 + size > end) return false;
    if (id == kZip64ExtraId) {
      uint64_t field = at + 4;
      for (uint64_t* v : {&e->uncompressed, &e->compressed, &e->local}) {
        if (*v != kSaturated32) continue;
        if (field + 8 > at + 4 + size) return false;
        *v = b.Le(field, 8);
        field += 8;
      }
      return true;
    }
    at += 4 + size;
  }
  return e->uncompressed != kSaturated32 && e->compressed != kSaturated32 &&
         e->local != kSaturated32;
}

// Reads the record at `*at` and moves past it; nullopt when it is not a readable record.
std::optional<Entry> ReadEntry(const Bytes& b, const Directory& dir, uint64_t* at) {
  const uint64_t p = *at;
  if (!b.Has(p, kCentralHeaderSize) || p + kCentralHeaderSize > dir.offset + dir.size ||
      b.Le(p, 4) != kCentralHeader) {
    return std::nullopt;
  }
  const uint64_t name_length = b.Le(p + 28, 2), extra_length = b.Le(p + 30, 2),
                 comment_length = b.Le(p + 32, 2);
  const uint64_t record = kCentralHeaderSize + name_length + extra_length + comment_length;
  if (!b.Has(p, record)) return std::nullopt;
  Entry e;
  e.name = b.Text(p + kCentralHeaderSize, name_length);
  e.method = static_cast<uint16_t>(b.Le(p + 10, 2));
  e.crc = static_cast<uint32_t>(b.Le(p + 16, 4));
  e.compressed = b.Le(p + 20, 4);
  e.uncompressed = b.Le(p + 24, 4);
  e.local = b.Le(p + 42, 4);
  if (!ApplyZip64Extra(b, p + kCentralHeaderSize + name_length, extra_length, &e))
    return std::nullopt;
  *at = p + record;
  return e;
}

// CRC-32 and size of a deflated run, or the reason it cannot be inflated.
struct Inflated {
  uint32_t crc = 0;
  uint64_t size = 0;
  std::string error;
};

Inflated Inflate(const unsigned char* data, uint64_t length) {
  Inflated out;
  out.crc = static_cast<uint32_t>(crc32_z(0, Z_NULL, 0));
  z_stream s{};
  if (inflateInit2(&s, -MAX_WBITS) != Z_OK) {
    out.error = "zlib cannot start inflating";
    return out;
  }
  unsigned char buffer[1 << 16];
  uint64_t fed = 0;
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    if (s.avail_in == 0 && fed < length) {
      const uint64_t chunk = std::min<uint64_t>(length - fed, 1u << 30);
      s.next_in = const_cast<unsigned char*>(data + fed);
      s.avail_in = static_cast<uInt>(chunk);
      fed += chunk;
    }
    s.next_out = buffer;
    s.avail_out = sizeof buffer;
    rc = inflate(&s, Z_NO_FLUSH);
    const uint64_t produced = sizeof buffer - s.avail_out;
    out.crc = static_cast<uint32_t>(crc32_z(out.crc, buffer, produced));
    out.size += produced;
    if (rc == Z_BUF_ERROR && s.avail_in == 0 && fed == length) {
      out.error = "its deflated data end early";
      break;
    }
    if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) {
      out.error =
          std::string("its deflated data are corrupt (zlib: ") + (s.msg ? s.msg : "error") + ")";
      break;
    }
  }
  inflateEnd(&s);
  return out;
}

// What is wrong with one entry's bytes, or "" when they match its record.
std::string CheckEntry(const Bytes& b, const Entry& e) {
  if (!b.Has(e.local, kLocalHeaderSize) || b.Le(e.local, 4) != kLocalHeader) {
    return "its local header at byte " + std::to_string(e.local) + " is missing";
  }
  const uint64_t data = e.local + kLocalHeaderSize + b.Le(e.local + 26, 2) + b.Le(e.local + 28, 2);
  if (!b.Has(data, e.compressed)) return "its data run past the end of the file (truncated?)";
  uint32_t crc = 0;
  uint64_t size = 0;
  if (e.method == 0) {
    crc = static_cast<uint32_t>(crc32_z(crc32_z(0, Z_NULL, 0), b.At(data), e.compressed));
    size = e.compressed;
  } else if (e.method == 8) {
    const Inflated inflated = Inflate(b.At(data), e.compressed);
    if (!inflated.error.empty()) return inflated.error;
    crc = inflated.crc;
    size = inflated.size;
  } else {
    return "it uses compression method " + std::to_string(e.method) +
           ", which libtorch archives do not use";
  }
  if (size != e.uncompressed) {
    return "it holds " + std::to_string(size) + " bytes, the archive records " +
           std::to_string(e.uncompressed);
  }
  if (crc != e.crc) return "its CRC-32 is " + Hex(crc) + ", the archive records " + Hex(e.crc);
  return "";
}

}  // namespace

std::optional<ZipDamage> FindZipDamage(const fs::path& file) {
  const Bytes b = ReadAll(file);
  const bool starts_as_zip = b.Has(0, 4) && b.Le(0, 4) == kLocalHeader;
  const std::optional<uint64_t> end = FindEndRecord(b);
  if (!end) {
    if (!starts_as_zip) return std::nullopt;
    return ZipDamage{"", "the archive's end record is missing (the file is truncated or damaged)"};
  }
  const std::optional<Directory> dir = ReadDirectory(b, *end);
  if (!dir || !b.Has(dir->offset, dir->size)) {
    return ZipDamage{"", "the archive's central directory lies outside the file"};
  }
  uint64_t at = dir->offset;
  for (uint64_t k = 0; k < dir->entries; ++k) {
    const std::optional<Entry> e = ReadEntry(b, *dir, &at);
    if (!e) {
      return ZipDamage{"", "record " + std::to_string(k + 1) + " of " +
                               std::to_string(dir->entries) +
                               " of the archive's central directory is damaged"};
    }
    if (std::string problem = CheckEntry(b, *e); !problem.empty())
      return ZipDamage{e->name, problem};
  }
  return std::nullopt;
}

}  // namespace crowdsim::value_rl
