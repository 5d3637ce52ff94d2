// The time series of a run (output/series.hpp): OUT/series.csv and
// OUT/series.png from a short run of a tiny scene, their agreement with
// summary.json, `landslide render --series`, and how bad series files are
// refused; a series resumed within a stage goes on as if never stopped
// (tests/app/test_checkpoint.cpp also compares the series.csv of killed and
// resumed runs with a whole one's).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/estimate.hpp"
#include "output/series.hpp"
#include "output/series_plot.hpp"
#include "output/summary.hpp"
#include "block_scene.hpp"
#include "render/png_io.hpp"
#include "render/video.hpp"
#include "sim/scene/scenario.hpp"
#include "sim/run/simulation.hpp"

namespace {

namespace fs = std::filesystem;

// The checkpoint tests' block, shorter: settling under a ramped gravity
// stage that is not painted, then slumping without cohesion in a painted
// one, so the series has both kinds of rows.
std::string series_scene() {
  nlohmann::json scene = nlohmann::json::parse(kSlumpingBlock);
  scene["name"] = "series-block";
  scene["stages"][0]["duration"] = 0.2;
  scene["stages"][2]["duration"] = 0.15;
  scene["output"]["frame_interval"] = 0.05;
  scene["output"]["image_size"] = {320, 180};
  return scene.dump(1);
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class SeriesRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("landslide-series-test-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    scenario_ = root_ / "series-block.json";
    std::ofstream(scenario_) << series_scene();
    out_ = root_ / "out";
    ffmpeg_ = render::ffmpeg_available(nullptr);
    if (!ffmpeg_) return;
    app::RunOptions o;
    o.scenario = scenario_.string();
    o.out_dir = out_.string();
    o.threads = 1;
    status_ = app::run_command(o);
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  void SetUp() override {
    if (!ffmpeg_) GTEST_SKIP() << "ffmpeg (with libx264, gif, palettegen) is not available";
    ASSERT_EQ(status_, app::kExitOk);
  }

  static app::RenderOptions render_options(const fs::path& input, const fs::path& out) {
    app::RenderOptions o;
    o.input = input.string();
    o.scenario = scenario_.string();
    o.field = "displacement-x";
    o.out = out.string();
    o.series = true;
    return o;
  }

  static fs::path root_, scenario_, out_;
  static bool ffmpeg_;
  static int status_;
};

fs::path SeriesRun::root_, SeriesRun::scenario_, SeriesRun::out_;
bool SeriesRun::ffmpeg_ = false;
int SeriesRun::status_ = -1;

TEST_F(SeriesRun, CsvHasItsHeaderAndRowsInIncreasingTimeAndThePngDecodes) {
  const render::Image img = render::read_png((out_ / "series.png").string());
  EXPECT_EQ(img.width(), app::kSeriesPngWidth);
  EXPECT_EQ(img.height(), app::kSeriesPngHeight);

  const std::string text = read_text(out_ / "series.csv");
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "time_s,stage,stage_time_s,steps,kinetic_energy_J_per_m,"
            "moving_kinetic_energy_J_per_m,front_x_m,runout_m,max_soil_ux_m,max_displacement_m,"
            "external_work_J_per_m,kinetic_energy_change_J_per_m,internal_work_J_per_m,"
            "elastic_energy_change_J_per_m,plastic_dissipation_J_per_m,damping_loss_J_per_m,"
            "wall_loss_J_per_m,friction_work_J_per_m,transfer_loss_J_per_m,relative_error");
  const std::vector<app::SeriesRow> rows = app::read_series(out_ / "series.csv");
  std::vector<double> settle, slump;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (k > 0) {
      EXPECT_GE(rows[k].time, rows[k - 1].time) << "row " << k;
    }
    (rows[k].stage == "settle" ? settle : slump).push_back(rows[k].at(app::kStageTime));
    EXPECT_TRUE(rows[k].stage == "settle" || rows[k].stage == "slump") << rows[k].stage;
  }
  // Not painted: its start, the first step past each 0.05 s, its end.
  ASSERT_EQ(settle.size(), 5u);
  EXPECT_EQ(settle.front(), 0.0);
  for (std::size_t k = 1; k < 4; ++k) {
    EXPECT_GE(settle[k], 0.05 * k);
    EXPECT_LT(settle[k], 0.05 * k + 0.01);
  }
  EXPECT_DOUBLE_EQ(settle.back(), 0.2);
  // Painted: every frame time, which the time loop lands on.
  ASSERT_EQ(slump.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(slump[k], 0.05 * k, 1e-12);
  EXPECT_NEAR(rows.back().time, 0.35, 1e-12);
}

// `landslide check` counts the rows the run writes (app/estimate.hpp), and
// their time: each row measures every point.
TEST_F(SeriesRun, TheEstimateCountsTheRowsAndTheirTime) {
  const std::vector<app::SeriesRow> rows = app::read_series(out_ / "series.csv");
  const sim::Simulation sim(sim::load_scenario(scenario_.string()));
  const app::Estimate e = app::estimate_run(sim, 320, 180, fs::path(), 1);
  EXPECT_EQ(e.rows, double(rows.size()));
  const double per_row = double(e.points) * app::calibrate().row_seconds_per_point;
  EXPECT_GT(per_row, 0.0);
  EXPECT_DOUBLE_EQ(e.row_seconds, e.rows * per_row);  // one chunk: on one thread
  EXPECT_GE(e.wall_seconds, e.point_steps / e.point_steps_per_second + e.row_seconds);
}

// The last row of each stage holds, to the bit, what summary.json reports.
TEST_F(SeriesRun, TheLastRowOfAStageIsTheSummary) {
  const std::vector<app::SeriesRow> rows = app::read_series(out_ / "series.csv");
  const auto summary = nlohmann::json::parse(read_text(out_ / "summary.json"));
  int checked = 0;
  for (const auto& stage : summary.at("stages")) {
    if (stage.at("type") == "material-change") continue;
    const std::string name = stage.at("name");
    const app::SeriesRow* last = nullptr;
    for (const app::SeriesRow& r : rows)
      if (r.stage == name) last = &r;
    ASSERT_NE(last, nullptr) << name;
    EXPECT_EQ(last->at(app::kRunout), stage.at("metrics").at("runout_m").get<double>()) << name;
    EXPECT_EQ(last->at(app::kFrontX), stage.at("metrics").at("toe_x_m").get<double>()) << name;
    EXPECT_EQ(last->at(app::kKinetic), stage.at("kinetic_energy_J_per_m").get<double>());
    EXPECT_EQ(last->at(app::kMovingKinetic),
              stage.at("moving_kinetic_energy_J_per_m").get<double>());
    EXPECT_EQ(last->at(app::kSteps), stage.at("steps").get<double>());
    const auto& columns = app::series_columns();
    for (std::size_t k = app::kMaxDisplacement + 1; k < last->values.size(); ++k)
      EXPECT_EQ(last->values[k], stage.at("energy").at(columns[k + 2]).get<double>())
          << name << " " << columns[k + 2];
    ++checked;
  }
  EXPECT_EQ(checked, 2);
  EXPECT_GT(rows.back().at(app::kRunout), 0.0) << "the block slumps";
}

TEST_F(SeriesRun, RenderPutsTheSeriesBesideEachFrame) {
  const fs::path dir = root_ / "beside";
  ASSERT_EQ(app::render_command(render_options(out_, dir)), app::kExitOk);
  const render::Image first = render::read_png((dir / "000000.png").string());
  const render::Image last = render::read_png((dir / "000001.png").string());
  EXPECT_EQ(first.width(), 320 + app::series_plot_width(180));
  EXPECT_EQ(first.height(), 360);
  EXPECT_EQ(last.width(), first.width());
  // The frames (the ends of settle and slump) are marked at different times.
  const render::Image plot_a = first.crop({320, 0, first.width() - 320, 360});
  const render::Image plot_b = last.crop({320, 0, last.width() - 320, 360});
  EXPECT_NE(plot_a, plot_b);
  // One state to one file: the .vtu's run directory holds the series.
  const fs::path one = root_ / "one.png";
  ASSERT_EQ(app::render_command(render_options(out_ / "vtk" / "slump-end.vtu", one)),
            app::kExitOk);
  // Its frame takes the view of that one state (app::view_window), but the
  // plot beside it is the same, marked at the same time.
  const render::Image single = render::read_png(one.string());
  ASSERT_EQ(single.width(), last.width());
  EXPECT_EQ(single.crop({320, 0, single.width() - 320, 360}), plot_b);
}

TEST_F(SeriesRun, RenderRefusesAMissingOrMalformedSeries) {
  const fs::path copy = root_ / "copy";
  fs::create_directories(copy);
  fs::copy(out_ / "vtk", copy / "vtk");
  testing::internal::CaptureStderr();
  EXPECT_EQ(app::render_command(render_options(copy, root_ / "bad-a")), app::kExitBadInput);
  const std::string missing = testing::internal::GetCapturedStderr();
  EXPECT_NE(missing.find("series.csv: no such file"), std::string::npos) << missing;

  std::string text = read_text(out_ / "series.csv");
  text.replace(text.find("slump,"), 6, "slump,x");  // stage_time_s = x...
  std::ofstream(copy / "series.csv") << text;
  testing::internal::CaptureStderr();
  EXPECT_EQ(app::render_command(render_options(copy, root_ / "bad-b")), app::kExitBadInput);
  const std::string malformed = testing::internal::GetCapturedStderr();
  EXPECT_NE(malformed.find("series.csv: line "), std::string::npos) << malformed;
  EXPECT_NE(malformed.find("stage_time_s = 'x"), std::string::npos) << malformed;
  EXPECT_EQ(std::count(malformed.begin(), malformed.end(), '\n'), 1) << malformed;
  EXPECT_FALSE(fs::exists(root_ / "bad-a"));
  EXPECT_FALSE(fs::exists(root_ / "bad-b"));
}

// What the run's observer does with the series, stopping at `stop_at` s
// (0: never) with the state and the series' bookkeeping kept, as a
// checkpoint keeps them.
struct SeriesOnly : sim::Observer {
  struct Stop {};
  SeriesOnly(const sim::Scenario& s, const fs::path& out, double stop_at)
      : series(s, out), stop_at(stop_at) {}
  void stage_begins(const sim::Simulation& sim, const sim::StageSpec& st) override {
    series.stage_begins(sim, st);
  }
  void frame(const sim::Simulation& sim, const sim::StageSpec&, int) override {
    series.frame(sim);
  }
  void progress(const sim::Simulation& sim, const sim::StageSpec& st, long) override {
    series.progress(sim, st);
    if (stop_at <= 0 || sim.time() < stop_at) return;
    state = sim.save_state();
    bookkeeping = series.bookkeeping();
    throw Stop{};
  }
  void stage_ends(const sim::Simulation& sim, const sim::StageSpec& st,
                  const sim::StageResult& r) override {
    series.stage_ends(sim, st, r);
  }
  app::SeriesRecorder series;
  double stop_at;
  std::string state;
  nlohmann::json bookkeeping;
};

// Stopped within the gravity stage (rows every frame_interval, not painted)
// and within the painted slump, the series goes on from its bookkeeping to
// the same text as a run that never stopped.
TEST(SeriesRecorder, AResumedSeriesGoesOnExactly) {
  const fs::path root =
      fs::temp_directory_path() / ("landslide-series-resume-" + std::to_string(::getpid()));
  fs::create_directories(root);
  const sim::Scenario scenario = sim::parse_scenario(series_scene(), "series-block.json");
  SeriesOnly whole(scenario, root / "whole", 0);
  fs::create_directories(root / "whole");
  sim::Simulation(scenario).run(whole);
  for (const double stop_at : {0.11, 0.27}) {
    const fs::path dir = root / std::to_string(stop_at);
    fs::create_directories(dir);
    SeriesOnly first(scenario, dir, stop_at);
    EXPECT_THROW(sim::Simulation(scenario).run(first), SeriesOnly::Stop);
    SeriesOnly rest(scenario, dir, 0);
    rest.series.resume(nlohmann::json::parse(first.bookkeeping.dump()));
    sim::Simulation again(scenario);
    again.restore_state(first.state, "the stopped run");
    again.run(rest);
    EXPECT_EQ(rest.series.csv(), whole.series.csv()) << "stopped at " << stop_at << " s";
    EXPECT_EQ(read_text(dir / "series.csv"), whole.series.csv());
  }
  fs::remove_all(root);
}

app::SeriesRow row(double time, const std::string& stage) {
  return {time, stage, std::vector<double>(app::series_columns().size() - 2, 0.125)};
}

TEST(SeriesCsv, RoundTripsExactlyWithQuotedStageNames) {
  const std::vector<app::SeriesRow> rows = {row(0, "a, \"b\""), row(0.1 + 0.2, "line\nbreak"),
                                            row(1e300, "plain")};
  const std::vector<app::SeriesRow> back = app::parse_series(app::series_csv(rows), "test");
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(back[k].time, rows[k].time);
    EXPECT_EQ(back[k].stage, rows[k].stage);
    EXPECT_EQ(back[k].values, rows[k].values);
  }
}

TEST(SeriesCsv, RefusesMalformedText) {
  const std::string good = app::series_csv({row(0, "s"), row(1, "s")});
  auto error = [](const std::string& text) {
    try {
      app::parse_series(text, "F.csv");
    } catch (const app::SeriesError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("time,stage\n0,s\n").rfind("F.csv: line 1: expected the header time_s,", 0), 0u);
  EXPECT_EQ(error(good + "2,s,1\n"), "F.csv: line 4: 3 fields, expected 20");
  std::string back = good;
  back.replace(back.rfind("\n1,"), 3, "\n-1,");
  EXPECT_EQ(error(back), "F.csv: line 3: time_s = -1 s comes after 0 s");
  EXPECT_EQ(error(good + "\"open,s\n"), "F.csv: line 4: a quote is not closed");
  EXPECT_EQ(error(""), "F.csv: line 1: expected the header " +
                           good.substr(0, good.find('\n')));
  EXPECT_EQ(app::parse_series(app::series_csv({}), "F.csv").size(), 0u);
  EXPECT_THROW(app::read_series("/nonexistent/series.csv"), app::SeriesError);
}

}  // namespace
