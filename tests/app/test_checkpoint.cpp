// Checkpoints lose nothing: a run killed (SIGKILL), stopped by Ctrl-C
// (SIGINT) or by SIGTERM and continued with `landslide resume` writes byte for byte the
// frames, states and videos of a run that never stopped, with the frames
// captured before the stop waiting in DIR/.frames-pending/. The real binary
// runs in a child process, so the kill is a real one.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "block_scene.hpp"
#include "render/video.hpp"

namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Starts `landslide run` in a child, sends it `signal` once it has written
// its second checkpoint, and returns the child's wait status.
int run_and_stop(const fs::path& scene, const fs::path& out, int signal) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::execl(LANDSLIDE_BINARY, LANDSLIDE_BINARY, "run", scene.c_str(), "--out", out.c_str(),
            "--threads", "1", "--checkpoint-every", "0.3", "--state-cache",
            (out.parent_path() / "cache").c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  // Waits for the second checkpoint (t >= 0.6 s, in the slump, with frames
  // captured and not yet painted), or for the child to end on its own.
  const fs::path checkpoint = out / "checkpoint.lsck";
  std::string first;
  while (::waitpid(child, &status, WNOHANG) == 0) {
    if (fs::exists(checkpoint)) {
      const std::string now = read_bytes(checkpoint);
      if (first.empty()) {
        first = now;
      } else if (now != first) {
        ::kill(child, signal);
        ::waitpid(child, &status, 0);
        return status;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return status;
}

// Every output file of `a` is in `b` with the same bytes (summary.json aside:
// it holds wall times), series.csv among them: a resumed run neither loses
// nor repeats a row.
void expect_same_outputs(const fs::path& a, const fs::path& b) {
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(a)) {
    if (!e.is_regular_file() || e.path().filename() == "summary.json") continue;
    const fs::path rel = fs::relative(e.path(), a);
    ++files;
    ASSERT_TRUE(fs::exists(b / rel)) << rel;
    EXPECT_TRUE(read_bytes(e.path()) == read_bytes(b / rel)) << rel << " differs";
  }
  EXPECT_TRUE(fs::exists(a / "series.csv") && fs::exists(a / "series.png"));
  EXPECT_GE(files, 12);  // 11 frames, 2 states, .pvd, states.json, mp4, gif, series
  EXPECT_FALSE(fs::exists(b / "checkpoint.lsck")) << "a finished run keeps no checkpoint";
  EXPECT_FALSE(fs::exists(b / ".frames-pending")) << "a finished run keeps no spilled frames";
}

class Checkpoints : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "ffmpeg is not available";
    root_ = fs::temp_directory_path() / ("landslide-checkpoint-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    scene_ = root_ / "block.json";
    std::ofstream(scene_) << kSlumpingBlock;
    app::RunOptions o;
    o.scenario = scene_.string();
    o.out_dir = (root_ / "whole").string();
    o.threads = 1;
    ASSERT_EQ(app::run_command(o), app::kExitOk);
  }
  void TearDown() override { fs::remove_all(root_); }

  int resume(const fs::path& dir) {
    app::ResumeOptions r;
    r.dir = dir.string();
    r.threads = 1;
    return app::resume_command(r);
  }

  // A run of the scene into root_/first sharing the cache root_/cache.
  app::RunOptions cached_run() const {
    app::RunOptions o;
    o.scenario = scene_.string();
    o.threads = 1;
    o.state_cache = (root_ / "cache").string();
    o.out_dir = (root_ / "first").string();
    return o;
  }

  // Stops a run with `signal`, expects `exit_status`, a checkpoint and an
  // "interrupted" summary, then resumes it and compares every output with
  // the run that never stopped. Returns the stopped run's summary status.
  std::string stop_and_resume(const fs::path& cut, int signal, int exit_status) {
    const int status = run_and_stop(scene_, cut, signal);
    EXPECT_TRUE(WIFEXITED(status)) << "the run did not exit by itself after the signal";
    EXPECT_EQ(WEXITSTATUS(status), exit_status);
    EXPECT_TRUE(fs::exists(cut / "checkpoint.lsck"));
    const auto summary = nlohmann::json::parse(read_bytes(cut / "summary.json"));
    const std::string text = summary.at("status").get<std::string>();
    EXPECT_EQ(text.rfind("interrupted", 0), 0u) << text;
    EXPECT_EQ(resume(cut), app::kExitOk);
    expect_same_outputs(root_ / "whole", cut);
    return text;
  }

  fs::path root_, scene_;
};

TEST_F(Checkpoints, ResumeAfterKillIsByteIdentical) {
  const fs::path cut = root_ / "killed";
  const int status = run_and_stop(scene_, cut, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before its second checkpoint";
  ASSERT_TRUE(fs::exists(cut / "checkpoint.lsck"));
  EXPECT_EQ(resume(cut), app::kExitOk);
  expect_same_outputs(root_ / "whole", cut);
}

TEST_F(Checkpoints, CtrlCWritesACheckpointAndExits130) {
  const fs::path cut = root_ / "interrupted";
  stop_and_resume(cut, SIGINT, app::kExitInterrupted);
  // The run saved its gravity stage, and that stage's series, for the next
  // scene that shares it.
  std::vector<std::string> cached;
  for (const auto& e : fs::directory_iterator(root_ / "cache"))
    cached.push_back(e.path().filename().string());
  std::sort(cached.begin(), cached.end());
  ASSERT_EQ(cached.size(), 2u);
  EXPECT_EQ(cached[0].substr(cached[0].size() - 11), ".series.csv");
  EXPECT_EQ(cached[0].substr(0, cached[0].size() - 11) + ".state", cached[1]);
}

// What `timeout` and batch schedulers send: handled as Ctrl-C is, with its
// own exit status.
TEST_F(Checkpoints, SigtermWritesACheckpointAndExits143) {
  const fs::path cut = root_ / "terminated";
  const std::string status = stop_and_resume(cut, SIGTERM, app::kExitTerminated);
  EXPECT_NE(status.find("SIGTERM"), std::string::npos) << status;
}

TEST_F(Checkpoints, AReusedGravityStageGivesTheSameOutputs) {
  app::RunOptions o = cached_run();
  ASSERT_EQ(app::run_command(o), app::kExitOk);  // computes and saves the gravity stage
  o.out_dir = (root_ / "second").string();
  ASSERT_EQ(app::run_command(o), app::kExitOk);  // starts from it
  const auto summary = nlohmann::json::parse(read_bytes(root_ / "second" / "summary.json"));
  EXPECT_EQ(summary.at("stages").size(), 3u);
  expect_same_outputs(root_ / "whole", root_ / "first");
  expect_same_outputs(root_ / "whole", root_ / "second");
}

// VTK states at an interval continue where the stopped run left them.
TEST_F(Checkpoints, StatesAtAnIntervalResumeByteIdentical) {
  std::string scene = kSlumpingBlock;
  const std::string vtk = R"("vtk": "stage-end")";
  scene.replace(scene.find(vtk), vtk.size(), R"("vtk": "interval", "vtk_interval": 0.05)");
  const fs::path file = root_ / "interval.json";
  std::ofstream(file) << scene;
  app::RunOptions o;
  o.scenario = file.string();
  o.out_dir = (root_ / "interval-whole").string();
  o.threads = 1;
  ASSERT_EQ(app::run_command(o), app::kExitOk);
  const fs::path cut = root_ / "interval-killed";
  ASSERT_TRUE(WIFSIGNALED(run_and_stop(file, cut, SIGKILL)));
  EXPECT_EQ(resume(cut), app::kExitOk);
  expect_same_outputs(root_ / "interval-whole", cut);
  // settle 0 .. 0.5 s and slump 0 .. 1 s, every 0.05 s.
  // (A kill in the middle of a write may leave its temporary file beside them.)
  const std::regex state(R"(state-\d{6}\.vtu)");
  int states = 0;
  for (const auto& e : fs::directory_iterator(cut / "vtk"))
    states += std::regex_match(e.path().filename().string(), state);
  EXPECT_EQ(states, 11 + 21);
}

// One byte flipped anywhere, or the file cut short: the CRC-32 after the
// content no longer matches, and resume says so, naming the file, before it
// writes anything. The undamaged file then resumes as ever.
TEST_F(Checkpoints, ResumeRefusesACheckpointWhoseChecksumDoesNotMatch) {
  const fs::path cut = root_ / "damaged";
  ASSERT_TRUE(WIFSIGNALED(run_and_stop(scene_, cut, SIGKILL)));
  const fs::path file = cut / "checkpoint.lsck";
  const std::string good = read_bytes(file);
  ASSERT_GT(good.size(), 1000u);
  auto refused = [&](const std::string& bytes, const std::string& what) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    const auto before = fs::last_write_time(cut / "summary.json");
    testing::internal::CaptureStderr();
    EXPECT_EQ(resume(cut), app::kExitBadInput) << what;
    const std::string text = testing::internal::GetCapturedStderr();
    EXPECT_NE(text.find(file.string() + ": its checksum does not match its content"),
              std::string::npos)
        << what << ": " << text;
    EXPECT_EQ(fs::last_write_time(cut / "summary.json"), before) << what;
  };
  for (const std::size_t at : {good.size() / 2, good.size() - 1, std::size_t(8)}) {
    std::string bytes = good;
    bytes[at] = static_cast<char>(bytes[at] ^ 0x10);
    refused(bytes, "byte " + std::to_string(at) + " flipped");
  }
  refused(good.substr(0, good.size() - 1), "last byte cut");
  refused(good.substr(0, good.size() / 2), "cut in half");
  std::ofstream(file, std::ios::binary | std::ios::trunc) << good;
  EXPECT_EQ(resume(cut), app::kExitOk);
  expect_same_outputs(root_ / "whole", cut);
}

// A damaged cached gravity state is not used (nor is the run stopped): the
// stages are computed again, giving the same outputs, and the file replaced.
TEST_F(Checkpoints, ADamagedCachedStateIsComputedAgainAndReplaced) {
  app::RunOptions o = cached_run();
  ASSERT_EQ(app::run_command(o), app::kExitOk);
  fs::path state;
  for (const auto& e : fs::directory_iterator(root_ / "cache"))
    if (e.path().extension() == ".state") state = e.path();
  ASSERT_FALSE(state.empty());
  std::string bad = read_bytes(state);
  bad[bad.size() / 2] = static_cast<char>(bad[bad.size() / 2] ^ 0x01);
  std::ofstream(state, std::ios::binary | std::ios::trunc) << bad;
  o.out_dir = (root_ / "second").string();
  testing::internal::CaptureStderr();
  EXPECT_EQ(app::run_command(o), app::kExitOk);
  const std::string text = testing::internal::GetCapturedStderr();
  EXPECT_NE(text.find(state.string() + ": its checksum does not match its content"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("starting after stage"), std::string::npos) << text;
  expect_same_outputs(root_ / "whole", root_ / "second");
  // The replacement (it holds wall times, so other bytes) is whole: the
  // next run starts from it.
  o.out_dir = (root_ / "third").string();
  testing::internal::CaptureStderr();
  EXPECT_EQ(app::run_command(o), app::kExitOk);
  const std::string third = testing::internal::GetCapturedStderr();
  EXPECT_NE(third.find("starting after stage 'settle' from " + state.string()), std::string::npos)
      << third;
  expect_same_outputs(root_ / "whole", root_ / "third");
}

TEST_F(Checkpoints, ResumeRefusesAMissingOrDamagedCheckpoint) {
  EXPECT_EQ(resume(root_ / "whole"), app::kExitBadInput);  // finished: no checkpoint
  fs::create_directories(root_ / "bad");
  std::ofstream(root_ / "bad" / "checkpoint.lsck") << "not a checkpoint";
  EXPECT_EQ(resume(root_ / "bad"), app::kExitBadInput);
}

}  // namespace
