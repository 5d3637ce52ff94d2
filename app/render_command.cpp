// `landslide render`: re-paints saved VTK states (one .vtu, or every state a
// run's points.pvd lists) with the painter the run uses, without simulating.
// `landslide panel`: several PNGs with captions on one page.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "output/counted.hpp"
#include "output/frames.hpp"
#include "output/series_plot.hpp"
#include "render/error.hpp"
#include "render/font.hpp"
#include "render/png_io.hpp"
#include "render/video.hpp"
#include "sim/scene/scenario.hpp"
#include "sim/scene/seed.hpp"
#include "sim/io/vtk.hpp"

namespace app {

namespace fs = std::filesystem;

bool ends_with(std::string s, const std::string& suffix) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}


namespace {

// Bad input: exit status 2, nothing written.
class BadInput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw BadInput(p.string() + ": cannot read");
  std::stringstream b;
  b << in.rdbuf();
  return b.str();
}

// The files a .pvd collection lists, in order, relative to its folder.
std::vector<fs::path> pvd_files(const fs::path& pvd) {
  const std::string text = read_text(pvd);
  static const std::regex dataset(R"re(<DataSet\b[^>]*\bfile="([^"]*)")re");
  std::vector<fs::path> files;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset);
       it != std::sregex_iterator(); ++it)
    files.push_back(pvd.parent_path() / (*it)[1].str());
  if (files.empty()) throw BadInput(pvd.string() + ": lists no .vtu files");
  return files;
}

// What the run knew about a state and the .vtu file does not hold.
struct StateInfo {
  bool known = false;
  std::string stage;
  double stage_time = 0;
};

// vtk/states.json, written by `landslide run` beside its .vtu files. Its
// "scenario" (the run's scenario name; a file of an older run has none) must
// be the name of --scenario: another scene's states would be painted under
// its title, in its domain.
std::map<std::string, StateInfo> read_states_json(const fs::path& dir,
                                                  const sim::Scenario& scenario) {
  std::map<std::string, StateInfo> out;
  const fs::path p = dir / "states.json";
  if (!fs::is_regular_file(p)) return out;
  try {
    const nlohmann::json doc = nlohmann::json::parse(read_text(p));
    if (doc.contains("scenario") && doc.at("scenario").get<std::string>() != scenario.name)
      throw BadInput(p.string() + ": states of scenario \"" +
                     doc.at("scenario").get<std::string>() + "\", but --scenario " +
                     scenario.source_path + " is \"" + scenario.name +
                     "\": give the scenario the run was made with");
    for (const nlohmann::json& s : doc.at("states")) {
      StateInfo info;
      info.known = true;
      info.stage = s.at("stage").get<std::string>();
      info.stage_time = s.at("stage_time_s").get<double>();
      out[s.at("file").get<std::string>()] = info;
    }
  } catch (const nlohmann::json::exception& e) {
    throw BadInput(p.string() + ": " + e.what());
  }
  return out;
}

// A state must hold the points the scenario seeds (a run never adds or
// removes one), and their materials.
void check_points_fit(const fs::path& file, const sim::PointState& state,
                      const sim::Scenario& scenario, std::size_t seeded) {
  if (state.x.size() != seeded)
    throw BadInput(file.string() + ": " + counted(state.x.size(), "point") + ", but --scenario " +
                   scenario.source_path + " seeds " + counted(seeded, "point") +
                   ": give the scenario the run was made with");
  for (const int m : state.material)
    if (m < 0 || std::size_t(m) >= scenario.materials.size())
      throw BadInput(file.string() + ": material id " + std::to_string(m) + ", but " +
                     scenario.source_path + " has " +
                     counted(scenario.materials.size(), "material") +
                     ": is this the scenario of the run?");
}

// Removes earlier numbered frames (000000.png ...) so a video of the folder
// holds only this rendering.
void clear_numbered_frames(const fs::path& dir) {
  static const std::regex numbered(R"(\d{6}\.png)");
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && std::regex_match(e.path().filename().string(), numbered))
      fs::remove(e.path());
}

std::string numbered(int i) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.png", i);
  return name;
}

struct Job {
  sim::Scenario scenario;
  Field field = Field::DisplacementX;
  std::string colour_map;
  std::vector<fs::path> files;
  fs::path out;
  bool out_is_file = false;
  std::size_t points = 0;  // that the scenario seeds
  std::vector<SeriesRow> series;  // with --series
};

// --series: RUN/series.csv, RUN being the run directory given or the one
// whose vtk/ holds the .vtu file.
std::vector<SeriesRow> run_series(const fs::path& in) {
  std::error_code ec;
  fs::path run = fs::is_directory(in, ec) ? in : in.parent_path();
  if (run.filename() == "vtk") run = run.parent_path();
  const fs::path file = run / "series.csv";
  if (!fs::is_regular_file(file, ec))
    throw BadInput("--series: " + file.string() + ": no such file (landslide run writes it)");
  try {
    return read_series(file);
  } catch (const SeriesError& e) {
    throw BadInput(std::string("--series: ") + e.what());
  }
}

// What job.out is: one .png, or a directory. An --out that names another
// kind of picture or a video would otherwise become a directory of that name.
void check_out(Job& job, const RenderOptions& o) {
  static const char* const kOther[] = {".jpg", ".jpeg", ".gif", ".bmp", ".tif", ".tiff",
                                       ".webp", ".ppm", ".pgm", ".svg", ".pdf", ".eps",
                                       ".avif", ".mp4", ".webm", ".mov", ".avi", ".mkv"};
  for (const char* ext : kOther)
    if (ends_with(job.out.string(), ext))
      throw BadInput("--out " + job.out.string() + ": landslide render writes PNG only: a "
                     ".png file (one state) or a directory (--video adds FIELD.mp4 and "
                     "FIELD.gif in it)");
  job.out_is_file = ends_with(job.out.string(), ".png");
  if (job.out_is_file && job.files.size() != 1)
    throw BadInput("--out " + job.out.string() + ": one PNG file, but there are " +
                   std::to_string(job.files.size()) + " states; give a directory");
  if (job.out_is_file && o.video) throw BadInput("--video needs a directory for --out");
  std::error_code ec;
  if (!job.out_is_file && fs::exists(job.out, ec) && !fs::is_directory(job.out, ec))
    throw BadInput("--out " + job.out.string() + ": exists and is not a directory");
}

Job prepare(const RenderOptions& o) {
  Job job;
  try {
    job.scenario = sim::load_scenario(o.scenario);
    job.points = sim::make_world(job.scenario).points.size();
  } catch (const sim::ScenarioError& e) {
    throw BadInput(e.what());
  }
  try {
    job.field = parse_field(o.field);
  } catch (const std::invalid_argument& e) {
    throw BadInput(std::string("--field: ") + e.what());
  }
  job.colour_map = o.colour_map.empty() ? job.scenario.output.colour_map : o.colour_map;
  if (job.colour_map != "jet" && job.colour_map != "viridis")
    throw BadInput("--colour-map " + job.colour_map + ": expected jet or viridis");
  if (o.range) {
    const auto [lo, hi] = *o.range;
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
      throw BadInput("--range " + std::to_string(lo) + " " + std::to_string(hi) +
                     ": expected two finite numbers LO < HI");
  }

  const fs::path in(o.input);
  std::error_code ec;
  if (fs::is_directory(in, ec)) {
    fs::path pvd;
    for (const fs::path& c : {in / "vtk" / "points.pvd", in / "points.pvd"})
      if (fs::is_regular_file(c, ec)) {
        pvd = c;
        break;
      }
    if (pvd.empty())
      throw BadInput(in.string() + ": a directory without vtk/points.pvd (was the run's "
                     "output.vtk \"none\"?)");
    job.files = pvd_files(pvd);
    const fs::path vtk_dir = pvd.parent_path();
    const fs::path base = vtk_dir.filename() == "vtk" ? vtk_dir.parent_path() : vtk_dir;
    job.out = o.out.empty() ? base / "render" / field_name(job.field) : fs::path(o.out);
  } else if (fs::is_regular_file(in, ec)) {
    if (!ends_with(in.string(), ".vtu"))
      throw BadInput(in.string() + ": expected a .vtu file or a run directory");
    job.files = {in};
    job.out = o.out.empty()
                  ? in.parent_path() / (in.stem().string() + "-" + field_name(job.field) + ".png")
                  : fs::path(o.out);
  } else {
    throw BadInput(in.string() + ": no such file or directory");
  }
  for (const fs::path& f : job.files)
    if (!fs::is_regular_file(f, ec)) throw BadInput(f.string() + ": listed but missing");

  check_out(job, o);
  if (o.video) {
    std::string why;
    if (!render::ffmpeg_available(&why)) throw BadInput("--video: " + why);
  }
  if (o.series) job.series = run_series(in);
  return job;
}

// Reads every state into a frame of the one field (float32, as the run keeps it).
std::vector<Frame> load_frames(const Job& job) {
  const std::vector<Field> fields{job.field};
  std::map<fs::path, std::map<std::string, StateInfo>> infos;  // per folder
  std::map<std::string, std::vector<sim::MaterialConstants>> materials;  // per stage
  std::vector<Frame> frames;
  bool unknown_stage = false;

  for (std::size_t i = 0; i < job.files.size(); ++i) {
    const fs::path& file = job.files[i];
    const fs::path dir = file.parent_path();
    if (!infos.count(dir)) infos[dir] = read_states_json(dir, job.scenario);
    const auto it = infos[dir].find(file.filename().string());
    const StateInfo info = it == infos[dir].end() ? StateInfo{} : it->second;
    unknown_stage |= !info.known;
    // Unknown stage: the materials after every change (what a slide sees).
    if (!materials.count(info.stage))
      materials[info.stage] = materials_at_stage(job.scenario, info.stage);

    sim::PointState state;
    try {
      state = sim::read_vtu(file.string());
    } catch (const std::exception& e) {
      throw BadInput(e.what());
    }
    check_points_fit(file, state, job.scenario, job.points);
    frames.push_back(capture_frame(state, materials[info.stage], fields, int(i),
                                   info.known ? info.stage_time : state.time, info.stage));
  }
  if (unknown_stage)
    std::cerr << "note: no vtk/states.json entry for some states: their time stamps are times "
                 "since the start of the run and their materials those after every "
                 "material change\n";
  if ((job.field == Field::DisplacementX || job.field == Field::DisplacementY) &&
      job.scenario.output.displacement_reference == "stage-start")
    std::cerr << "note: displacements are measured from the initial positions (the .vtu "
                 "files hold no stage-start reference)\n";
  return frames;
}

}  // namespace

namespace {

// The run's colours: one range per stage (frames of one stage together),
// or the one --range gives.
std::map<std::string, Range> stage_ranges(const RenderOptions& o, const FieldStyle& style,
                                          const std::vector<Frame>& frames) {
  std::map<std::string, Range> ranges;
  if (o.range) {
    for (const Frame& f : frames) ranges[f.stage] = Range{o.range->first, o.range->second};
    return ranges;
  }
  std::map<std::string, std::vector<const std::vector<float>*>> by_stage;
  for (const Frame& f : frames) by_stage[f.stage].push_back(&f.values[0]);
  for (const auto& [stage, list] : by_stage) ranges[stage] = field_range(style, list);
  return ranges;
}

// Paints every state into job.out (one PNG, or numbered ones and a video).
void paint_states(const Job& job, const RenderOptions& o, const std::vector<Frame>& frames,
                  FramePainter& painter, render::Font* font, const FrameView& view) {
  const FieldStyle style = field_style(job.field, job.scenario);
  std::map<std::string, Range> ranges = stage_ranges(o, style, frames);
  if (!job.out_is_file) {
    fs::create_directories(job.out);
    clear_numbered_frames(job.out);
  } else if (job.out.has_parent_path()) {
    fs::create_directories(job.out.parent_path());
  }
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& fr = frames[i];
    const render::FrameSpec spec =
        frame_spec(job.scenario, style, job.colour_map, ranges[fr.stage], fr, view);
    const fs::path path = job.out_is_file ? job.out : job.out / numbered(int(i));
    const render::Image& image = painter.paint(spec, fr, 0);
    if (job.series.empty())
      render::write_png(image, path.string());
    else
      render::write_png(
          beside_series(*font, image, job.series, run_time_of(job.series, fr.stage, fr.time)),
          path.string());
  }
  if (job.out_is_file) {
    std::cout << job.out.string() << '\n';
    return;
  }
  std::cout << job.out.string() << "/: " << counted(frames.size(), "frame") << '\n';
  if (o.video) {
    const render::VideoFiles v =
        render::encode_video(job.out.string(), job.out.string(), field_name(job.field),
                             video_options(job.scenario.output.frame_interval));
    std::cout << v.mp4 << '\n' << v.gif << '\n';
  }
}

}  // namespace

int render_command(const RenderOptions& o) {
  Job job;
  std::vector<Frame> frames;
  try {
    job = prepare(o);
    frames = load_frames(job);
  } catch (const BadInput& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  }
  std::unique_ptr<FramePainter> painter;
  std::unique_ptr<render::Font> font;
  FrameView view;
  try {
    painter = std::make_unique<FramePainter>(job.scenario.output.image_size[0],
                                             std::max(64, job.scenario.output.image_size[1]));
    if (!job.series.empty()) font = std::make_unique<render::Font>();
  } catch (const std::exception& e) {
    std::cerr << "error: cannot set up the off-screen painter: " << e.what() << '\n';
    return kExitBadInput;
  }
  // The run's view: the material's extent over the states painted here
  // (the run's own frames, when its output.vtk was "frames").
  Extent extent;
  for (const Frame& f : frames) extent.add(f);
  try {
    view = frame_view(job.scenario, view_window(job.scenario, extent), painter->font());
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  }
  try {
    paint_states(job, o, frames, *painter, font.get(), view);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitFailed;
  }
  return kExitOk;
}

}  // namespace app
