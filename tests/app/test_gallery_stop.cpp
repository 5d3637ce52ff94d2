// `landslide gallery` stopped by Ctrl-C or SIGTERM while its first run is
// under way: it stops at the run's next step, exits 130 or 143 as `run`
// does, and leaves neither its work folder (OUT/.work, the frames of the
// animations) nor a half-written file. Before, the signal ended the process
// where it stood and OUT/.work stayed. The real binary runs in a child
// process, so the signal is a real one.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "output/exit_status.hpp"
#include "render/video.hpp"

namespace {

namespace fs = std::filesystem;

// Starts `landslide gallery --quick --out OUT` in a child, sends it `signal`
// once OUT/.work exists, and returns the child's wait status.
int gallery_stopped_by(int signal, const fs::path& out) {
  const std::string scenarios = LANDSLIDE_SOURCE_DIR "/scenarios";
  const pid_t child = ::fork();
  if (child == 0) {
    const int quiet = ::open("/dev/null", O_WRONLY);
    ::dup2(quiet, 1);
    ::dup2(quiet, 2);
    ::execl(LANDSLIDE_BINARY, LANDSLIDE_BINARY, "gallery", "--quick", "--out", out.c_str(),
            "--scenarios", scenarios.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(child, &status, WNOHANG) == 0) {
    if (fs::exists(out / ".work")) {
      ::kill(child, signal);
      ::waitpid(child, &status, 0);
      return status;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return status;  // ended before its work folder was made: a failure below
}

TEST(GalleryStop, CtrlCAndSigtermLeaveNoWorkFolderAndNoPartFile) {
  if (!render::ffmpeg_available(nullptr)) GTEST_SKIP() << "ffmpeg is not available";
  const fs::path root = fs::temp_directory_path() / ("landslide-gallery-stop-" + std::to_string(::getpid()));
  for (const auto& [signal, exit] :
       {std::pair{SIGINT, app::kExitInterrupted}, std::pair{SIGTERM, app::kExitTerminated}}) {
    fs::remove_all(root);
    const fs::path out = root / "gallery";
    const int status = gallery_stopped_by(signal, out);
    ASSERT_TRUE(WIFEXITED(status)) << "signal " << signal << ": the process did not exit itself";
    EXPECT_EQ(WEXITSTATUS(status), exit) << "signal " << signal;
    EXPECT_FALSE(fs::exists(out / ".work")) << "signal " << signal;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      const std::string name = e.path().filename().string();
      EXPECT_EQ(name.find(".tmp-"), std::string::npos) << e.path();
      EXPECT_EQ(name.find(".part-"), std::string::npos) << e.path();
    }
  }
  fs::remove_all(root);
}

}  // namespace
