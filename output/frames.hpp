// Painted output of a run: the scalar fields of the points, frames captured
// (and spilled to disk) while the run goes on, the view they share, and their
// painting (PNG per field and frame, then an mp4 and a gif per field) with
// one colour range per stage.
//
// The same code paints a live sim::World (`landslide run`) and a saved VTK
// state (`landslide render`): both are captured into a Frame first, so a
// re-painted state gives the same pixels as the run did.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "render/font.hpp"
#include "render/frame_spec.hpp"
#include "render/image.hpp"
#include "render/painter.hpp"
#include "render/video.hpp"
#include "sim/physics/material.hpp"
#include "sim/scene/scenario.hpp"
#include "sim/io/vtk.hpp"
#include "sim/physics/world.hpp"

namespace app {

enum class Field {
  DisplacementX, DisplacementY, RelativeYield, StressYY, Velocity, Material, Cohesion, FrictionAngle
};

// "displacement-x", "displacement-y", "relative-yield", "stress-yy",
// "velocity", "material", "cohesion", "friction-angle". parse_field throws std::invalid_argument listing them.
const std::vector<std::string>& field_names();
Field parse_field(const std::string& name);
std::string field_name(Field f);

// How a field is labelled and coloured.
struct FieldStyle {
  Field field = Field::DisplacementX;
  std::string title;   // in the frame title, e.g. "horizontal displacement"
  std::string label;   // colour bar label
  std::string unit;    // colour bar unit ("" for none)
  bool categorical = false;
  bool fixed_range = false;  // relative yield: always [0, 2]
  double lo = 0, hi = 1;     // the fixed range
  std::vector<std::string> names;  // categorical: the name of each id
};
// The scenario names the materials on the categorical colour bar.
FieldStyle field_style(Field f, const sim::Scenario& scenario);

// Per point value of a field, in the unit field_style() names:
//   displacement-x/-y  x - ref_x, y - ref_y [m]
//   relative-yield     Eq. (32) through sim::relative_yield for Mohr-Coulomb
//                      materials (each point's own surface where a random
//                      field set it), 2 where the point yielded in the last step
//                      (paper, Figure 10), 0 for linear-elastic materials
//   stress-yy          sigma_yy [kPa], tension positive
//   velocity           |v| [m/s]
//   material           the material index (categorical)
//   cohesion           c [kPa] of Mohr-Coulomb points, NaN (grey) for others
//   friction-angle     phi [deg] of Mohr-Coulomb points, NaN (grey) for others;
//                      both point by point where a random field set them
// `materials` are the constants in force (after any material change).
std::vector<double> field_values(Field f, const sim::World& world);
// From a saved state; its displacement is the one in the file (from the
// initial position).
std::vector<double> field_values(Field f, const sim::PointState& state,
                                 const std::vector<sim::MaterialConstants>& materials);

// Half size of a point's square: sqrt(volume) / 2, its current size.
double half_size(double volume);

// Squares are painted this much larger than half_size(): a body compacted
// by its own weight loses volume while its points keep their lateral
// spacing, which would otherwise show as 1 px hairlines wherever the pixel
// rounding falls between two columns of points (about 0.4 % linear strain
// under 10 m of soil). 1 % closes gaps up to 2 % volumetric compaction.
constexpr double kSquareFill = 1.01;

// One captured frame: what painting it needs, in float32.
struct Frame {
  int number = 0;         // frame number across the run (file 000123.png)
  double time = 0;        // s since its stage began (the time stamp)
  std::string stage;      // stage name, for the title ("" if unknown)
  std::vector<float> x, y, half;
  std::vector<std::vector<float>> values;  // one array per field, in the order asked
  // Material id per point where the scene has more than one material (the
  // painter outlines all but material 0); empty otherwise.
  std::vector<std::uint8_t> material;
  std::size_t bytes() const;
};

Frame capture_frame(const sim::World& world, const std::vector<Field>& fields, int number,
                    double time, const std::string& stage);
// The same into `into`, reusing its arrays' memory.
void capture_frame_into(Frame& into, const sim::World& world, const std::vector<Field>& fields,
                        int number, double time, const std::string& stage);
Frame capture_frame(const sim::PointState& state,
                    const std::vector<sim::MaterialConstants>& materials,
                    const std::vector<Field>& fields, int number, double time,
                    const std::string& stage);

// Colour range of field k over a set of frames (one stage): relative yield
// [0, 2]; material 0 .. last material id; the continuous fields from the
// lowest 1st to the highest 99th percentile of any frame (a robust range: a
// few outlying points, such as the stress peaks at a house's corners, do not
// wash out the rest; values beyond are painted in the end colours), velocity
// from 0, displacement widened to hold 0. Non-finite values are ignored; an
// empty or zero-width range is widened to a unit one.
struct Range {
  double lo = 0, hi = 1;
};
Range field_range(const FieldStyle& style, const std::vector<Frame>& frames, std::size_t k);
// The same over the given value arrays.
Range field_range(const FieldStyle& style, const std::vector<const std::vector<float>*>& values);
// The same, one frame's values at a time, so that a stage of many frames
// never has to be in memory at once.
class RangeAccumulator {
 public:
  void add(const std::vector<float>& values);
  Range range(const FieldStyle& style) const;

 private:
  double lo_ = HUGE_VAL, hi_ = -HUGE_VAL;
  std::vector<float> finite_;
};

// The unit a range is shown in: displacements under 0.5 m in mm (the
// gravity stage's settlement of a few mm reads 4, not 0.004), everything
// else in its style's unit. `scale` turns the field's values into it (the
// colour bar's labels; the values stay in SI units).
struct DisplayUnit {
  std::string unit;
  double scale = 1;
};
DisplayUnit display_unit(const FieldStyle& style, const Range& range);

// A world window [m].
struct Window {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
};
// The scenario's domain plus a margin of 3% of its larger side (at least one
// cell): the largest view a run paints unless output.view names another.
Window frame_window(const sim::Scenario& scenario);

// The region the painted squares of some frames cover (x +- kSquareFill *
// half, non-finite points left out); empty until a frame with a point is added.
struct Extent {
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  void add(const Frame& frame);
  bool empty() const { return !(x0 <= x1 && y0 <= y1); }
};

// The world window a run paints: output.view when the scenario gives one;
// otherwise `material` plus kViewMargin of its larger side (at least one
// cell) each side, clipped to frame_window(); frame_window() itself when
// nothing was captured.
constexpr double kViewMargin = 0.05;
Window view_window(const sim::Scenario& scenario, const Extent& material);

// The window and the image size every frame of a run shares: image_size's
// width, and its height, or for "auto" the height at which `window` fills
// the plot's width for the tallest title and bar label of any field and
// painted stage (render::fit_frame_height, for a colour bar of 0 .. 1).
struct FrameView {
  Window window;
  int width = 1280, height = 720;
};
FrameView frame_view(const sim::Scenario& scenario, const Window& window, render::Font& font);
// The "auto" height of a frame `width` px wide showing `window`.
int auto_height(const sim::Scenario& scenario, const Window& window, int width,
                render::Font& font);

// Title "<scenario> — <field title> (<stage>)", time stamp "t = 4.00 s".
render::FrameSpec frame_spec(const sim::Scenario& scenario, const FieldStyle& style,
                             const std::string& colour_map, const Range& range,
                             const Frame& frame, const FrameView& view);
// A frame painted outside a run (the gallery's figures, which compare scenes
// in one window): the domain's frame_window().
render::FrameSpec frame_spec(const sim::Scenario& scenario, const FieldStyle& style,
                             const std::string& colour_map, const Range& range,
                             const Frame& frame);

// Paints captured frames; owns the one render::Painter (and GL context) and
// reuses its buffers between frames. Use it on the thread that made it.
class FramePainter {
 public:
  // Throws render::Error if OSMesa or the font cannot be set up.
  FramePainter(int width, int height);
  const render::Image& paint(const render::FrameSpec& spec, const Frame& frame, std::size_t k);
  render::Font& font() { return painter_->font(); }
  const render::FrameLayout& last_layout() const { return painter_->last_layout(); }

 private:
  std::unique_ptr<render::Painter> painter_;
  render::Image image_;
  std::vector<double> x_, y_, half_, value_;
};

// Frames per second of the videos: shown at twice the simulated speed, 2..30,
// and played at kPlayFps or more (each frame repeated; render/video.hpp).
constexpr int kPlayFps = 25;
render::VideoOptions video_options(double frame_interval);

// True when the scenario asks for frames: frame_interval > 0 and at least
// one timed stage named in frame_stages.
bool paints_frames(const sim::Scenario& scenario);

// A frame captured and spilled to disk, not painted yet.
struct PendingFrame {
  int number = 0;
  std::string stage;
};

// Collects a run's frames and paints them once the view over all of them is
// known:
//   DIR/.frames-pending/000123.frame  one file per captured frame, while the
//                                     run goes on (output/frame_file.hpp)
//   DIR/frames/<field>/000123.png     (numbers continue across stages)
//   DIR/<field>.mp4, DIR/<field>.gif  (every frame of the run)
// Memory holds one captured frame at a time; painting reads the files back
// (and, for the colour range of a stage, one field of that stage's frames).
class FrameRecorder {
 public:
  // Sets up the painter (throws render::Error). Check ffmpeg before.
  FrameRecorder(const sim::Scenario& scenario, std::filesystem::path out_dir);

  // Creates DIR/frames/<field>/ and removes numbered PNGs an earlier run
  // left there (they would join this run's videos), and an earlier run's
  // spilled frames. Call once the output directory exists; paint_pending()
  // calls it if nobody did.
  void start();
  // Lays out a frame of every field, full size and the GIF's, in the view
  // known before the run (output.view, or the domain's window), so that an
  // image_size too small for the annotations is refused before simulating;
  // throws render::InvalidArgument. Returns that full-size view.
  FrameView check_layouts();
  void capture(const sim::World& world, double stage_time, int number, const std::string& stage);
  std::size_t pending() const { return pending_.size(); }
  // Bytes held in memory for captured frames: the last one spilled and its
  // bytes as written, kept for the next capture or read; none once painted.
  std::size_t bytes_in_memory() const { return scratch_.bytes() + spill_bytes_.size(); }
  // Paints every pending frame in the view over all of them, with one colour
  // range per stage, writes the PNGs, and removes the spilled files and
  // their folder. Returns the number of PNG files written.
  int paint_pending();
  // mp4 + gif of each field from every frame this run wrote (none if it
  // painted fewer than two frames).
  std::vector<render::VideoFiles> encode_videos();
  std::filesystem::path frames_dir(Field f) const;
  // OUT/.gif-frames/<field>/: the frames painted at the GIF's width, until
  // encode_videos() has made the GIF.
  std::filesystem::path gif_dir(Field f) const;
  std::filesystem::path spill_dir() const { return out_ / ".frames-pending"; }
  const std::vector<Field>& fields() const { return fields_; }

  // For checkpoints: the frames spilled and not yet painted, the extent of
  // every frame captured, and the PNGs written so far. resume() takes them
  // back in a resumed run: it keeps the listed files (throws sim::StateError
  // naming one that is missing), removes files captured after the
  // checkpoint (the resumed run captures them again), and keeps the PNGs of
  // the stopped run, which start() would remove.
  const std::vector<PendingFrame>& pending_frames() const { return pending_; }
  const Extent& extent() const { return extent_; }
  int written() const { return written_; }
  void resume(std::vector<PendingFrame> frames, const Extent& extent, int written);

 private:
  std::filesystem::path spill_file(int number) const;
  std::vector<Range> stage_ranges(const std::vector<const PendingFrame*>& frames);

  const sim::Scenario& scenario_;
  std::filesystem::path out_;
  std::vector<Field> fields_;
  std::vector<FieldStyle> styles_;
  FramePainter painter_;
  std::vector<PendingFrame> pending_;
  Extent extent_;
  Frame scratch_;  // the frame being captured, or read back to be painted
  std::string spill_bytes_;  // its bytes on their way to or from the spill file
  bool started_ = false;
  int written_ = 0;
};

// Materials in force during `stage` (its name; "" for after every change):
// the scenario's materials with the changes of every material-change stage
// before it applied.
std::vector<sim::MaterialConstants> materials_at_stage(const sim::Scenario& scenario,
                                                       const std::string& stage);

}  // namespace app
