#include "output/frame_file.hpp"

#include "output/checksum.hpp"
#include "sim/io/binary_io.hpp"
#include "sim/io/file_bytes.hpp"

namespace app {

namespace {

// "LSFRAME" and a format version (2: with the material ids, 3: a CRC-32
// after the content).
constexpr std::uint64_t kMagic = 0x4c534652414d4503ULL;
constexpr std::uint64_t kMaxFields = 64;

}  // namespace

std::string write_frame_file(const std::filesystem::path& file, const Frame& f,
                             std::string buffer) {
  sim::BinaryWriter w(std::move(buffer));
  constexpr std::size_t kHeaderBytes = 256;  // magic, number, time, counts, checksum
  w.reserve(f.bytes() + f.stage.size() + 8 * f.values.size() + kHeaderBytes);
  w.put(kMagic);
  w.put(f.number);
  w.put(f.time);
  w.put_string(f.stage);
  w.put_vector(f.x);
  w.put_vector(f.y);
  w.put_vector(f.half);
  w.put(std::uint64_t(f.values.size()));
  for (const std::vector<float>& v : f.values) w.put_vector(v);
  w.put_vector(f.material);
  append_checksum(w);
  write_bytes_atomically(file, w);
  return w.take();
}

void read_frame_file(const std::filesystem::path& file, Frame& f, std::string& bytes) {
  bytes = sim::read_file_bytes(file, file.string() + ": cannot read the captured frame",
                          std::move(bytes));
  sim::BinaryReader r(bytes, file.string());
  if (bytes.size() < 8 || r.get<std::uint64_t>() != kMagic)
    r.fail("not a frame captured by this version of landslide");
  strip_checksum(bytes, file);  // r reads `bytes` by reference: the checksum is gone for it too
  f.number = r.get<int>();
  f.time = r.get<double>();
  f.stage = r.get_string();
  r.get_vector_into(f.x);
  r.get_vector_into(f.y, f.x.size(), "a frame's y");
  r.get_vector_into(f.half, f.x.size(), "a frame's sizes");
  const auto fields = r.get<std::uint64_t>();
  if (fields > kMaxFields) r.fail("a frame with " + std::to_string(fields) + " fields");
  f.values.resize(fields);
  for (std::vector<float>& v : f.values) r.get_vector_into(v, f.x.size(), "a frame's values");
  r.get_vector_into(f.material);
  if (!f.material.empty() && f.material.size() != f.x.size())
    r.fail("a frame with " + std::to_string(f.material.size()) + " material ids for " +
           std::to_string(f.x.size()) + " points");
  if (!r.at_end()) r.fail("bytes after the end of the frame");
}

}  // namespace app
