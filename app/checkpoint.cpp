#include "app/checkpoint.hpp"

#include <fstream>
#include <sstream>

#include "sim/atomic_file.hpp"
#include "sim/binary_io.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// "LSCHECK" and a format version (2: frames carry their material ids).
constexpr std::uint64_t kMagic = 0x4c53434845434b02ULL;

void put_frame(sim::BinaryWriter& w, const Frame& f) {
  w.put(f.number);
  w.put(f.time);
  w.put_string(f.stage);
  w.put_vector(f.x);
  w.put_vector(f.y);
  w.put_vector(f.half);
  w.put(std::uint64_t(f.values.size()));
  for (const std::vector<float>& v : f.values) w.put_vector(v);
  w.put_vector(f.material);
}

Frame get_frame(sim::BinaryReader& r) {
  Frame f;
  f.number = r.get<int>();
  f.time = r.get<double>();
  f.stage = r.get_string();
  f.x = r.get_vector<float>();
  f.y = r.get_vector<float>(f.x.size(), "a frame's y");
  f.half = r.get_vector<float>(f.x.size(), "a frame's sizes");
  const auto fields = r.get<std::uint64_t>();
  if (fields > 64) r.fail("a frame with " + std::to_string(fields) + " fields");
  for (std::uint64_t k = 0; k < fields; ++k)
    f.values.push_back(r.get_vector<float>(f.x.size(), "a frame's values"));
  f.material = r.get_vector<std::uint8_t>();
  if (!f.material.empty() && f.material.size() != f.x.size())
    r.fail("a frame with " + std::to_string(f.material.size()) + " material ids for " +
           std::to_string(f.x.size()) + " points");
  return f;
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
  for (const Frame& f : c.frames) put_frame(w, f);
  sim::write_file_atomically(file.string(), [&](std::ostream& o) {
    o.write(w.bytes().data(), std::streamsize(w.bytes().size()));
  });
}

Checkpoint read_checkpoint(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw sim::StateError(file.string() + ": no checkpoint here (a run writes one with "
                                          "--checkpoint-every, or when stopped by Ctrl-C)");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string bytes = text.str();
  sim::BinaryReader r(bytes, file.string());
  if (bytes.size() < 8 || r.get<std::uint64_t>() != kMagic)
    r.fail("not a checkpoint written by this version of landslide");
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
  if (frames > 100000) r.fail(std::to_string(frames) + " pending frames");
  for (std::uint64_t k = 0; k < frames; ++k) c.frames.push_back(get_frame(r));
  if (!r.at_end()) r.fail("bytes after the end of the checkpoint");
  return c;
}

}  // namespace app
