// Painted output of a run: the scalar fields of the points, frames captured
// in memory while a stage runs, and their painting (PNG per field and frame,
// then an mp4 and a gif per field) with one colour range per stage.
//
// The same code paints a live sim::World (`landslide run`) and a saved VTK
// state (`landslide render`): both are captured into a Frame first, so a
// re-painted state gives the same pixels as the run did.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "render/frame_spec.hpp"
#include "render/image.hpp"
#include "render/painter.hpp"
#include "render/video.hpp"
#include "sim/material.hpp"
#include "sim/scenario.hpp"
#include "sim/vtk.hpp"
#include "sim/world.hpp"

namespace app {

enum class Field { DisplacementX, DisplacementY, RelativeYield, StressYY, Velocity, Material };

// "displacement-x", "displacement-y", "relative-yield", "stress-yy",
// "velocity", "material". parse_field throws std::invalid_argument listing them.
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
//                      materials, 2 where the point yielded in the last step
//                      (paper, Figure 10), 0 for linear-elastic materials
//   stress-yy          sigma_yy [kPa], tension positive
//   velocity           |v| [m/s]
//   material           the material index (categorical)
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

// The unit a range is shown in: displacements under 0.5 m in mm (the
// gravity stage's settlement of a few mm reads 4, not 0.004), everything
// else in its style's unit. `scale` turns the field's values into it (the
// colour bar's labels; the values stay in SI units).
struct DisplayUnit {
  std::string unit;
  double scale = 1;
};
DisplayUnit display_unit(const FieldStyle& style, const Range& range);

// The world window of every frame of a run: the scenario's domain plus a
// margin of 3% of its larger side (at least one cell).
struct Window {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
};
Window frame_window(const sim::Scenario& scenario);

// Title "<scenario> — <field title> (<stage>)", time stamp "t = 4.00 s".
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

// Collects a run's frames while a stage runs and paints them when it ends:
//   DIR/frames/<field>/000123.png  (numbers continue across stages)
//   DIR/<field>.mp4, DIR/<field>.gif  (every frame of the run, after the last painted stage)
class FrameRecorder {
 public:
  // Sets up the painter (throws render::Error). Check ffmpeg before.
  FrameRecorder(const sim::Scenario& scenario, std::filesystem::path out_dir);

  // Creates DIR/frames/<field>/ and removes numbered PNGs an earlier run
  // left there (they would join this run's videos). Call once the output
  // directory exists; paint_pending() calls it if nobody did.
  void start();
  void capture(const sim::World& world, double stage_time, int number, const std::string& stage);
  std::size_t pending() const { return frames_.size(); }
  // Paints the captured frames with their own ranges, writes the PNGs and
  // frees the frames. Returns the number of PNG files written.
  int paint_pending();
  // mp4 + gif of each field from every frame this run wrote (none if it
  // painted fewer than two frames).
  std::vector<render::VideoFiles> encode_videos();
  std::filesystem::path frames_dir(Field f) const;
  const std::vector<Field>& fields() const { return fields_; }

  // For checkpoints: the captured frames not yet painted and the PNGs
  // written so far; resume() takes them back in a resumed run (and keeps the
  // PNGs of the stopped run, which start() would remove).
  const std::vector<Frame>& pending_frames() const { return frames_; }
  int written() const { return written_; }
  void resume(std::vector<Frame> frames, int written);

 private:
  const sim::Scenario& scenario_;
  std::filesystem::path out_;
  std::vector<Field> fields_;
  std::vector<FieldStyle> styles_;
  FramePainter painter_;
  std::vector<Frame> frames_;
  bool started_ = false;
  int written_ = 0;
};

// Materials in force during `stage` (its name; "" for after every change):
// the scenario's materials with the changes of every material-change stage
// before it applied.
std::vector<sim::MaterialConstants> materials_at_stage(const sim::Scenario& scenario,
                                                       const std::string& stage);

}  // namespace app
