#include "output/checksum.hpp"

#include <zlib.h>

#include <cstdio>
#include <cstring>

#include "sim/io/atomic_file.hpp"

namespace app {

namespace {

std::uint32_t crc32_of(const char* data, std::size_t size) {
  return static_cast<std::uint32_t>(
      crc32_z(crc32_z(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(data), size));
}

std::string hex(std::uint32_t v) {
  char text[16];
  std::snprintf(text, sizeof text, "%08x", static_cast<unsigned>(v));
  return text;
}

}  // namespace

void append_checksum(sim::BinaryWriter& w) {
  w.put(crc32_of(w.bytes().data(), w.bytes().size()));
}

void strip_checksum(std::string& bytes, const std::filesystem::path& file) {
  constexpr std::size_t n = sizeof(std::uint32_t);
  if (bytes.size() < n)
    throw sim::StateError(file.string() + ": truncated (" + std::to_string(bytes.size()) +
                          " bytes, too short to hold its checksum)");
  std::uint32_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - n, n);
  const std::uint32_t computed = crc32_of(bytes.data(), bytes.size() - n);
  if (stored != computed)
    throw sim::StateError(file.string() + ": its checksum does not match its content (CRC-32 " +
                          hex(computed) + ", stored " + hex(stored) +
                          "): the file is damaged or truncated");
  bytes.resize(bytes.size() - n);
}

void write_bytes_atomically(const std::filesystem::path& file, const sim::BinaryWriter& w) {
  sim::write_file_atomically(file.string(), [&](std::ostream& o) {
    o.write(w.bytes().data(), std::streamsize(w.bytes().size()));
  });
}

}  // namespace app
