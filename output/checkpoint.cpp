#include "output/checkpoint.hpp"

#include "output/checksum.hpp"
#include "sim/io/binary_io.hpp"
#include "sim/io/file_bytes.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// "LSCHECK" and a format version (3: a CRC-32 after the content).
constexpr std::uint64_t kMagic = 0x4c53434845434b03ULL;
constexpr std::uint64_t kMagicWithoutChecksum = 0x4c53434845434b02ULL;
// Every frame of a run can be pending (they are painted at the end): at most
// 100000 per stage, so a bound far above any real run.
constexpr std::uint64_t kMaxPending = 100000000;

void put_extent(sim::BinaryWriter& w, const Extent& e) {
  for (const double v : {e.x0, e.x1, e.y0, e.y1}) w.put(v);
}

Extent get_extent(sim::BinaryReader& r) {
  Extent e;
  for (double* v : {&e.x0, &e.x1, &e.y0, &e.y1}) *v = r.get<double>();
  return e;
}

}  // namespace

fs::path checkpoint_path(const fs::path& out_dir) { return out_dir / "checkpoint.lsck"; }

void write_checkpoint(const fs::path& file, const Checkpoint& c) {
  sim::BinaryWriter w;
  w.put(kMagic);
  w.put_string(c.scenario_text);
  w.put_string(c.scenario_file);
  w.put_string(c.run.dump());
  w.put_string(c.state);
  w.put(std::uint64_t(c.frames.size()));
  for (const PendingFrame& f : c.frames) {
    w.put(f.number);
    w.put_string(f.stage);
  }
  put_extent(w, c.extent);
  append_checksum(w);
  write_bytes_atomically(file, w);
}

Checkpoint read_checkpoint(const fs::path& file) {
  std::string bytes = sim::read_file_bytes(
      file, file.string() + ": no checkpoint here (a run writes one with --checkpoint-every, "
                            "or when stopped by Ctrl-C or SIGTERM)");
  sim::BinaryReader r(bytes, file.string());
  const std::uint64_t magic = bytes.size() < 8 ? 0 : r.get<std::uint64_t>();
  if (magic == kMagicWithoutChecksum)
    r.fail("a checkpoint of an older landslide, without a checksum; this version cannot "
           "resume it");
  if (magic != kMagic) r.fail("not a checkpoint written by this version of landslide");
  strip_checksum(bytes, file);  // r reads `bytes` by reference: the checksum is gone for it too
  Checkpoint c;
  c.scenario_text = r.get_string();
  c.scenario_file = r.get_string();
  try {
    c.run = nlohmann::json::parse(r.get_string());
  } catch (const nlohmann::json::exception& e) {
    r.fail(std::string("the run's bookkeeping is not JSON: ") + e.what());
  }
  c.state = r.get_string();
  const auto frames = r.get<std::uint64_t>();
  if (frames > kMaxPending) r.fail(std::to_string(frames) + " pending frames");
  for (std::uint64_t k = 0; k < frames; ++k) {
    PendingFrame f;
    f.number = r.get<int>();
    f.stage = r.get_string();
    c.frames.push_back(f);
  }
  c.extent = get_extent(r);
  if (!r.at_end()) r.fail("bytes after the end of the checkpoint");
  return c;
}

}  // namespace app
