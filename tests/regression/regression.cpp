#include "tests/regression/regression.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "output/frames.hpp"
#include "output/summary.hpp"
#include "sim/run/simulation.hpp"

namespace regression {

namespace fs = std::filesystem;

namespace {

// Captures and paints frames the way `landslide run` does (FrameRecorder,
// painted when each stage ends), without VTK, videos or progress output:
// those are not what the regression guards and videos would need ffmpeg.
class PaintingObserver : public sim::Observer {
 public:
  explicit PaintingObserver(app::FrameRecorder* recorder) : recorder_(recorder) {}
  void frame(const sim::Simulation& sim, const sim::StageSpec& stage, int frame) override {
    if (recorder_) recorder_->capture(sim.world(), sim.stage_time(), frame, stage.name);
  }
  void stage_ends(const sim::Simulation&, const sim::StageSpec&,
                  const sim::StageResult&) override {
    if (recorder_ && recorder_->pending() > 0) recorder_->paint_pending();
  }

 private:
  app::FrameRecorder* recorder_;  // null: the scene paints nothing
};

using Flat = std::map<std::string, nlohmann::json>;

// Leaves of the summary by path; a stage is named by its index and name so
// that a message says which stage a number belongs to.
void flatten(const nlohmann::json& j, const std::string& path, Flat& out) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items())
      flatten(value, path.empty() ? key : path + "." + key, out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      std::string p = path + "[" + std::to_string(i) + "]";
      if (j[i].is_object() && j[i].contains("name") && j[i]["name"].is_string())
        p += " (" + j[i]["name"].get<std::string>() + ")";
      else if (j[i].is_object() && j[i].contains("material") && j[i]["material"].is_string())
        p += " (" + j[i]["material"].get<std::string>() + ")";
      flatten(j[i], p, out);
    }
  } else {
    out[path] = j;
  }
}

std::string show(const nlohmann::json& v) {
  if (!v.is_number_float()) return v.dump();
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v.get<double>());
  return buf;
}

}  // namespace

SceneRun run_scene(const fs::path& scene, const fs::path& work) {
  const sim::Scenario scenario = sim::load_scenario(scene.string());
  fs::create_directories(work);
  std::unique_ptr<app::FrameRecorder> recorder;
  if (app::paints_frames(scenario)) {
    recorder = std::make_unique<app::FrameRecorder>(scenario, work);
    recorder->start();
  }
  sim::Simulation simulation(scenario);
  PaintingObserver observer(recorder.get());
  simulation.run(observer);

  SceneRun run;
  run.numbers = stable_numbers(app::make_summary(simulation, 0, 0, "finished"));
  if (recorder) {
    for (const app::Field f : recorder->fields()) {
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(recorder->frames_dir(f)))
        if (e.path().extension() == ".png") files.push_back(e.path());
      std::sort(files.begin(), files.end());
      for (const fs::path& file : files)
        run.images.push_back({app::field_name(f) + "-" + file.filename().string(), file});
    }
  }
  return run;
}

nlohmann::json stable_numbers(nlohmann::json summary) {
  for (const char* key : {"wall_time_s", "threads", "version", "scenario_file"})
    summary.erase(key);
  if (summary.contains("stages"))
    for (nlohmann::json& stage : summary["stages"]) stage.erase("wall_time_s");
  return summary;
}

std::vector<std::string> compare_numbers(const nlohmann::json& expected,
                                         const nlohmann::json& actual,
                                         const NumberTolerance& tol) {
  Flat want, got;
  flatten(expected, "", want);
  flatten(actual, "", got);
  std::vector<std::string> out;
  for (const auto& [path, e] : want) {
    const auto it = got.find(path);
    if (it == got.end()) {
      out.push_back(path + ": expected " + show(e) + ", missing");
      continue;
    }
    const nlohmann::json& a = it->second;
    if (e.is_number() && a.is_number()) {
      const double x = e.get<double>(), y = a.get<double>();
      const double change = std::abs(y - x);
      if (change <= tol.relative * std::abs(x) || change <= tol.absolute) continue;
      char rel[64];
      std::snprintf(rel, sizeof rel, "%.2e", x != 0 ? change / std::abs(x) : HUGE_VAL);
      char limit[64];
      std::snprintf(limit, sizeof limit, "%.0e", tol.relative);
      out.push_back(path + ": expected " + show(e) + ", got " + show(a) + " (relative change " +
                    rel + ", tolerance " + limit + ")");
    } else if (e != a) {
      out.push_back(path + ": expected " + show(e) + ", got " + show(a));
    }
  }
  return out;
}

std::vector<std::string> new_entries(const nlohmann::json& expected, const nlohmann::json& actual) {
  Flat want, got;
  flatten(expected, "", want);
  flatten(actual, "", got);
  std::vector<std::string> out;
  for (const auto& [path, a] : got)
    if (!want.count(path)) out.push_back(path + ": " + show(a));
  return out;
}

}  // namespace regression
