// The paper's slope at h = 1.127 m, four friction angles, 4 s of the slide:
// every painted frame and every summary number against the committed
// expected files. LANDSLIDE_UPDATE_REGRESSION=1 rewrites those files instead
// (scripts/update-regression.sh; README.md says when that is allowed).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <string>

#include "render/image_diff.hpp"
#include "render/png_io.hpp"
#include "tests/regression/regression.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(LANDSLIDE_SOURCE_DIR) / "tests" / "regression";

// A run is bit-identical whatever the thread count, and from one build to
// the next on one machine, so there any difference is a change. The
// tolerances only absorb another compiler or libm, whose last-bit
// differences the slide amplifies. Measured with a build that turns the
// solver's multiply-adds into FMAs (-march=native -ffp-contract=fast): every
// frame identical, numbers within 2e-10 (tests/regression/README.md).
// Numbers: relative 1e-6, 5000 times that, far below a physics change; the
// 1e-9 floor is for entries that are 0. Images: a channel may be off by two
// steps of the colour map (a value on a colour boundary) in at most 0.01 % of
// the pixels (24 of 800 x 300: a few point edges snapped the other way); a
// changed label or a moved point is more.
const regression::NumberTolerance kNumberTolerance{1e-6, 1e-9};
const render::DiffTolerance kImageTolerance{8, 1e-4};

bool updating() {
  const char* v = std::getenv("LANDSLIDE_UPDATE_REGRESSION");
  return v && *v && std::string(v) != "0";
}

bool is_review_file(const fs::path& p) {
  const std::string name = p.filename().string();
  return name.find(".actual.") != std::string::npos || name.find(".diff.") != std::string::npos;
}

// Files an earlier failure left for review would be taken for this run's.
void remove_review_files(const fs::path& dir) {
  if (!fs::is_directory(dir)) return;
  for (const auto& e : fs::directory_iterator(dir))
    if (is_review_file(e.path())) fs::remove(e.path());
}

std::set<std::string> expected_images(const fs::path& dir) {
  std::set<std::string> names;
  if (!fs::is_directory(dir)) return names;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".png" && !is_review_file(e.path()))
      names.insert(e.path().filename().string());
  return names;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  return nlohmann::json::parse(in);
}

void write_json(const nlohmann::json& j, const fs::path& file) {
  std::ofstream(file) << j.dump(2) << '\n';
}

// Rewrites expected/<scene>/ from this run and prints what changed, for the
// commit message.
void update(const std::string& scene, const regression::SceneRun& run, const fs::path& dir) {
  fs::create_directories(dir);
  const nlohmann::json before = read_json(dir / "summary.json");
  if (before.is_null()) {
    std::cout << scene << ": no expected numbers before\n";
  } else {
    for (const std::string& line : regression::compare_numbers(before, run.numbers, {0, 0}))
      std::cout << scene << ": " << line << '\n';
    for (const std::string& line : regression::new_entries(before, run.numbers))
      std::cout << scene << ": new: " << line << '\n';
  }
  for (const std::string& name : expected_images(dir)) fs::remove(dir / name);
  write_json(run.numbers, dir / "summary.json");
  for (const regression::SceneRun::Image& img : run.images)
    fs::copy_file(img.file, dir / img.name, fs::copy_options::overwrite_existing);
  std::cout << scene << ": wrote " << (dir / "summary.json").string() << " and "
            << run.images.size() << " images\n";
}

class Scene : public ::testing::TestWithParam<const char*> {};

TEST_P(Scene, MatchesExpectedNumbersAndFrames) {
  const std::string scene = GetParam();
  const fs::path work = fs::temp_directory_path() /
                        ("landslide-regression-" + std::to_string(::getpid()) + "-" + scene);
  fs::remove_all(work);
  const regression::SceneRun run = regression::run_scene(kRoot / "scenes" / (scene + ".json"), work);
  const fs::path dir = kRoot / "expected" / scene;
  remove_review_files(dir);
  if (updating()) {
    update(scene, run, dir);
    fs::remove_all(work);
    return;
  }

  const nlohmann::json want = read_json(dir / "summary.json");
  if (want.is_null()) {
    ADD_FAILURE() << (dir / "summary.json") << " is missing: scripts/update-regression.sh";
  } else {
    const std::vector<std::string> changes =
        regression::compare_numbers(want, run.numbers, kNumberTolerance);
    for (const std::string& line : changes) ADD_FAILURE() << scene << ": " << line;
    if (!changes.empty()) write_json(run.numbers, dir / "summary.actual.json");
    for (const std::string& line : regression::new_entries(want, run.numbers))
      std::cout << scene << ": not in the expected numbers yet: " << line << '\n';
  }

  std::set<std::string> unpainted = expected_images(dir);
  for (const regression::SceneRun::Image& img : run.images) {
    unpainted.erase(img.name);
    const render::CheckResult c = render::check_against_file(
        render::read_png(img.file.string()), (dir / img.name).string(), kImageTolerance);
    EXPECT_TRUE(c.passed) << scene << ": " << c.message;
  }
  for (const std::string& name : unpainted)
    ADD_FAILURE() << scene << ": " << (dir / name) << " is expected but the run painted no such frame";
  fs::remove_all(work);
}

INSTANTIATE_TEST_SUITE_P(PaperSlope, Scene, ::testing::Values("phi25", "phi20", "phi15", "phi10"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

}  // namespace
