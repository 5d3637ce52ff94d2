#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "render/error.hpp"
#include "render/png_io.hpp"
#include "render/subprocess.hpp"
#include "render/video.hpp"
#include "test_support.hpp"

namespace render {
namespace {

namespace fs = std::filesystem;

void write_frames(const std::string& dir, int n, int w, int h) {
  for (int i = 0; i < n; ++i) {
    Image img(w, h, kWhite);
    img.fill_rect(Rect{i * 8, h / 4, 12, h / 2}, Rgba{200, 40, 40, 255});
    char name[32];
    std::snprintf(name, sizeof name, "/%06d.png", i);
    write_png(img, dir + name);
  }
}

bool no_partial_files(const std::string& dir) {
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().string().find(".part") != std::string::npos) return false;
  }
  return true;
}

TEST(Subprocess, RunsWithoutAShellAndReportsStatus) {
  const ProcessResult ok = run_process({"sh", "-c", "echo out; echo err >&2; exit 3"});
  ASSERT_TRUE(ok.started);
  EXPECT_EQ(ok.exit_code, 3);
  EXPECT_NE(ok.output.find("out"), std::string::npos);
  EXPECT_NE(ok.output.find("err"), std::string::npos);
  // An argument with shell syntax reaches the program verbatim.
  const ProcessResult echo = run_process({"echo", "$(rm -rf /); `x` 'q'"});
  EXPECT_EQ(echo.output, "$(rm -rf /); `x` 'q'\n");
  const ProcessResult missing = run_process({"/no/such/program"});
  EXPECT_FALSE(missing.started);
  EXPECT_NE(missing.spawn_error.find("/no/such/program"), std::string::npos);
  const ProcessResult tail = run_process({"seq", "1", "100000"}, 64);
  EXPECT_EQ(tail.output.size(), 64u);
  EXPECT_NE(tail.output.find("100000\n"), std::string::npos);
}

TEST(Video, MissingFfmpegIsReportedWithAReason) {
  std::string why;
  EXPECT_FALSE(ffmpeg_available(&why, "/no/such/ffmpeg"));
  EXPECT_NE(why.find("/no/such/ffmpeg"), std::string::npos) << why;
}

TEST(Video, EncodesMp4AndGifFromNumberedFrames) {
  std::string why;
  if (!ffmpeg_available(&why)) GTEST_SKIP() << "ffmpeg unusable: " << why;
  render_test::TempDir dir;
  const std::string frames = dir.file("frames");
  fs::create_directory(frames);
  write_frames(frames, 4, 65, 49);  // odd size: the mp4 must pad to even
  EXPECT_EQ(count_frames(frames), 4);

  VideoOptions opt;
  opt.fps = 10;
  const VideoFiles out = encode_video(frames, dir.path(), "clip", opt);
  EXPECT_EQ(out.mp4, dir.file("clip.mp4"));
  EXPECT_EQ(out.gif, dir.file("clip.gif"));
  ASSERT_TRUE(fs::exists(out.mp4));
  ASSERT_TRUE(fs::exists(out.gif));
  EXPECT_GT(fs::file_size(out.mp4), 0u);
  EXPECT_GT(fs::file_size(out.gif), 0u);
  EXPECT_TRUE(no_partial_files(dir.path()));

  std::ifstream gif(out.gif, std::ios::binary);
  char magic[6] = {0};
  gif.read(magic, 6);
  EXPECT_EQ(std::string(magic, 6), "GIF89a");

  const ProcessResult probe =
      run_process({"ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
                   "stream=codec_name,pix_fmt,width,height", "-of", "default=nw=1", out.mp4});
  if (probe.ok()) {
    EXPECT_NE(probe.output.find("codec_name=h264"), std::string::npos) << probe.output;
    EXPECT_NE(probe.output.find("pix_fmt=yuv420p"), std::string::npos) << probe.output;
    EXPECT_NE(probe.output.find("width=66"), std::string::npos) << probe.output;
    EXPECT_NE(probe.output.find("height=50"), std::string::npos) << probe.output;
  }
}

// Issue 14: 4 frames shown at 4 per second play at 25 fps for the same 1 s,
// each frame repeated; the GIF comes from its own frames when given, and
// holds each for 25 cs instead of repeating it.
TEST(Video, PlaysAtTwentyFiveFpsAndTakesTheGifFramesGiven) {
  std::string why;
  if (!ffmpeg_available(&why)) GTEST_SKIP() << "ffmpeg unusable: " << why;
  render_test::TempDir dir;
  const std::string frames = dir.file("frames"), small = dir.file("small");
  fs::create_directory(frames);
  fs::create_directory(small);
  write_frames(frames, 4, 64, 48);
  write_frames(small, 4, 32, 24);
  VideoOptions opt;
  opt.fps = 4;
  opt.gif_frames_dir = small;
  const VideoFiles out = encode_video(frames, dir.path(), "clip", opt);
  const ProcessResult mp4 =
      run_process({"ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                   "-show_entries", "stream=r_frame_rate,nb_read_frames", "-of",
                   "default=nw=1", out.mp4});
  ASSERT_TRUE(mp4.ok()) << mp4.output;
  EXPECT_NE(mp4.output.find("r_frame_rate=25/1"), std::string::npos) << mp4.output;
  EXPECT_NE(mp4.output.find("nb_read_frames=25"), std::string::npos) << mp4.output;
  const ProcessResult gif =
      run_process({"ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                   "-show_entries", "stream=width,nb_read_frames:format=duration", "-of",
                   "default=nw=1", out.gif});
  ASSERT_TRUE(gif.ok()) << gif.output;
  EXPECT_NE(gif.output.find("width=32"), std::string::npos) << gif.output;
  EXPECT_NE(gif.output.find("nb_read_frames=4"), std::string::npos) << gif.output;
  EXPECT_NE(gif.output.find("duration=1.000000"), std::string::npos) << gif.output;
}

TEST(Video, FailuresThrowAndLeaveNoOutput) {
  render_test::TempDir dir;
  try {
    encode_video(dir.path(), dir.path(), "clip");
    FAIL() << "expected VideoError";
  } catch (const VideoError& e) {
    EXPECT_NE(std::string(e.what()).find("000000.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(encode_video(dir.path(), dir.path(), "../escape"), InvalidArgument);

  write_frames(dir.path(), 2, 32, 32);
  VideoOptions bogus;
  bogus.ffmpeg = "/no/such/ffmpeg";
  EXPECT_THROW(encode_video(dir.path(), dir.path(), "clip", bogus), VideoError);

  std::string why;
  if (!ffmpeg_available(&why)) GTEST_SKIP() << "ffmpeg unusable: " << why;
  // A second frame corrupt after its header makes ffmpeg itself fail: its
  // message comes back.
  {
    std::ifstream first(dir.file("000000.png"), std::ios::binary);
    char header[33];  // the signature and the whole IHDR chunk
    first.read(header, sizeof header);
    std::ofstream second(dir.file("000001.png"), std::ios::binary);
    second.write(header, sizeof header);
    second << "not a png";
  }
  try {
    encode_video(dir.path(), dir.path(), "clip");
    FAIL() << "expected VideoError";
  } catch (const VideoError& e) {
    EXPECT_NE(std::string(e.what()).find("ffmpeg failed"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.file("clip.mp4")));
  EXPECT_FALSE(fs::exists(dir.file("clip.gif")));
  EXPECT_TRUE(no_partial_files(dir.path()));
}

// ffmpeg starts its filters again where the frames' size changes, and the
// GIF's one palette then covered only the frames after it (the gallery's
// side-by-side GIF lost the first half of its slide): refused before ffmpeg.
TEST(Video, RefusesAClipOfTwoFrameSizes) {
  render_test::TempDir dir;
  write_frames(dir.path(), 3, 32, 32);
  write_png(Image(32, 40, kWhite), dir.file("000002.png"));
  try {
    encode_video(dir.path(), dir.path(), "clip");
    FAIL() << "expected VideoError";
  } catch (const VideoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("000002.png is 32 x 40 px, but 000000.png is 32 x 32"), std::string::npos)
        << what;
  }
  EXPECT_FALSE(fs::exists(dir.file("clip.mp4")));
  EXPECT_EQ(png_size(dir.file("000002.png")).height, 40);
  std::ofstream(dir.file("000003.png")) << "not a png";
  EXPECT_THROW(png_size(dir.file("000003.png")), FileError);
}

}  // namespace
}  // namespace render
