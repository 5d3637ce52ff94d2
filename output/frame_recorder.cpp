// FrameRecorder (output/frames.hpp): frames spilled to disk as they are
// captured, painted together once the run's view over all of them is known.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "output/frame_file.hpp"
#include "output/frames.hpp"
#include "output/output_dir.hpp"
#include "render/annotate.hpp"
#include "render/error.hpp"
#include "render/png_io.hpp"
#include "sim/io/binary_io.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

std::string numbered(int number, const char* ext) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d%s", number, ext);
  return name;
}

}  // namespace

FrameRecorder::FrameRecorder(const sim::Scenario& scenario, fs::path out_dir)
    : scenario_(scenario),
      out_(std::move(out_dir)),
      painter_(scenario.output.image_size[0], std::max(64, scenario.output.image_size[1])) {
  for (const std::string& name : scenario.output.fields) {
    fields_.push_back(parse_field(name));
    styles_.push_back(field_style(fields_.back(), scenario));
  }
}

fs::path FrameRecorder::frames_dir(Field f) const { return out_ / "frames" / field_name(f); }

fs::path FrameRecorder::gif_dir(Field f) const { return out_ / ".gif-frames" / field_name(f); }

fs::path FrameRecorder::spill_file(int number) const {
  return spill_dir() / numbered(number, ".frame");
}

void FrameRecorder::start() {
  if (started_) return;
  for (const Field f : fields_) {
    fs::create_directories(frames_dir(f));
    remove_numbered(frames_dir(f), ".png");
  }
  fs::remove_all(spill_dir());
  fs::remove_all(out_ / ".gif-frames");
  started_ = true;
}

void FrameRecorder::resume(std::vector<PendingFrame> frames, const Extent& extent, int written) {
  for (const Field f : fields_) fs::create_directories(frames_dir(f));
  std::set<int> listed;
  for (const PendingFrame& p : frames) {
    if (!fs::is_regular_file(spill_file(p.number)))
      throw sim::StateError(spill_file(p.number).string() +
                            ": missing, but the checkpoint lists it as a captured frame");
    listed.insert(p.number);
  }
  remove_numbered(spill_dir(), ".frame", listed);
  started_ = true;
  pending_ = std::move(frames);
  extent_ = extent;
  written_ = written;
}

void FrameRecorder::capture(const sim::World& world, double stage_time, int number,
                            const std::string& stage) {
  if (pending_.empty()) fs::create_directories(spill_dir());
  capture_frame_into(scratch_, world, fields_, number, stage_time, stage);
  spill_bytes_ = write_frame_file(spill_file(number), scratch_, std::move(spill_bytes_));
  extent_.add(scratch_);
  pending_.push_back(PendingFrame{number, stage});
}

// One range per field over `frames` (one stage), reading one frame at a
// time: memory holds one frame however many the stage has.
std::vector<Range> FrameRecorder::stage_ranges(const std::vector<const PendingFrame*>& frames) {
  std::vector<RangeAccumulator> acc(fields_.size());
  for (const PendingFrame* p : frames) {
    read_frame_file(spill_file(p->number), scratch_, spill_bytes_);
    for (std::size_t k = 0; k < fields_.size(); ++k) acc[k].add(scratch_.values.at(k));
  }
  std::vector<Range> ranges;
  for (std::size_t k = 0; k < fields_.size(); ++k) ranges.push_back(acc[k].range(styles_[k]));
  return ranges;
}

// The GIF's frames are painted at its own width, so that their text keeps
// its size (render/frame_spec.hpp): scaling the full frames down to 480 px
// would leave 6 px tick labels.
FrameView gif_view(const sim::Scenario& s, const FrameView& view, render::Font& font) {
  FrameView small = view;
  small.width = std::min(view.width, render::VideoOptions{}.gif_width);
  if (s.output.image_size[1] != sim::kAutoHeight) {  // the size was fixed: keep its aspect
    small.height = std::max(64, int(std::lround(double(view.height) * small.width / view.width)));
    return small;
  }
  small.height = auto_height(s, view.window, small.width, font);
  return small;
}

FrameView FrameRecorder::check_layouts() {
  const FrameView view = frame_view(scenario_, view_window(scenario_, Extent{}), painter_.font());
  const FrameView small = gif_view(scenario_, view, painter_.font());
  Frame probe;
  probe.stage = scenario_.stages.front().name;
  for (std::size_t k = 0; k < fields_.size(); ++k) {
    const Range range = styles_[k].fixed_range ? Range{styles_[k].lo, styles_[k].hi} : Range{};
    for (const FrameView* v : {&view, &small}) {
      const render::FrameSpec spec =
          frame_spec(scenario_, styles_[k], scenario_.output.colour_map, range, probe, *v);
      try {
        render::layout_frame(painter_.font(), spec);
      } catch (const render::InvalidArgument& e) {
        throw render::InvalidArgument((v == &small ? "its GIF copy " + std::to_string(v->width) +
                                                         " px wide: "
                                                   : std::string()) +
                                      e.what());
      }
    }
  }
  return view;
}

int FrameRecorder::paint_pending() {
  start();
  const FrameView view = frame_view(scenario_, view_window(scenario_, extent_), painter_.font());
  const FrameView small = gif_view(scenario_, view, painter_.font());
  int written = 0;
  std::size_t first = 0;
  while (first < pending_.size()) {  // one stage (a run of frames of one stage) at a time
    std::size_t end = first;
    std::vector<const PendingFrame*> stage;
    while (end < pending_.size() && pending_[end].stage == pending_[first].stage)
      stage.push_back(&pending_[end++]);
    const std::vector<Range> ranges = stage_ranges(stage);
    for (const PendingFrame* p : stage) {
      read_frame_file(spill_file(p->number), scratch_, spill_bytes_);
      const Frame& fr = scratch_;
      for (std::size_t k = 0; k < fields_.size(); ++k) {
        const render::FrameSpec spec =
            frame_spec(scenario_, styles_[k], scenario_.output.colour_map, ranges[k], fr, view);
        render::write_png(painter_.paint(spec, fr, k),
                          (frames_dir(fields_[k]) / numbered(fr.number, ".png")).string());
        const render::FrameSpec gif =
            frame_spec(scenario_, styles_[k], scenario_.output.colour_map, ranges[k], fr, small);
        fs::create_directories(gif_dir(fields_[k]));
        render::write_png(painter_.paint(gif, fr, k),
                          (gif_dir(fields_[k]) / numbered(fr.number, ".png")).string());
        ++written;
      }
    }
    first = end;
  }
  pending_.clear();
  // The frames are read back through the capture's frame and bytes, which
  // then go: a run between its stages holds no frame.
  scratch_ = Frame{};
  std::string().swap(spill_bytes_);  // a move from an empty string keeps the memory
  fs::remove_all(spill_dir());
  written_ += written;
  return written;
}

std::vector<render::VideoFiles> FrameRecorder::encode_videos() {
  std::vector<render::VideoFiles> files;
  if (written_ == 0) return files;
  for (const Field f : fields_) {
    const fs::path dir = frames_dir(f);
    const int frames = render::count_frames(dir.string());
    if (frames < 2) continue;  // no video of a single frame
    render::VideoOptions options = video_options(scenario_.output.frame_interval);
    // A run stopped between painting and encoding may lack some GIF frames:
    // then the GIF scales the full ones down.
    if (render::count_frames(gif_dir(f).string()) == frames)
      options.gif_frames_dir = gif_dir(f).string();
    files.push_back(render::encode_video(dir.string(), out_.string(), field_name(f), options));
  }
  fs::remove_all(out_ / ".gif-frames");
  return files;
}

}  // namespace app
