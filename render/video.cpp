#include "render/video.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <future>
#include <vector>

#include "render/error.hpp"
#include "render/png_io.hpp"
#include "render/subprocess.hpp"

namespace render {

namespace fs = std::filesystem;

namespace {

std::string frame_name(int i) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06d.png", i);
  return buf;
}

// ffmpeg's image2 demuxer reads '%' in the path as a format directive.
std::string escape_percent(const std::string& s) {
  std::string out;
  for (char c : s) {
    out += c;
    if (c == '%') out += '%';
  }
  return out;
}

std::string tail_lines(const std::string& s, std::size_t max_chars = 1500) {
  std::string t = s.size() > max_chars ? s.substr(s.size() - max_chars) : s;
  while (!t.empty() && (t.back() == '\n' || t.back() == '\r')) t.pop_back();
  return t.empty() ? "(no output)" : t;
}

// Runs ffmpeg writing to a temporary next to `final_path`, renames on
// success, removes the temporary on any failure.
void run_to(const VideoOptions& opt, std::vector<std::string> args,
            const std::string& final_path) {
  const std::string tmp = final_path + ".part-" + std::to_string(getpid());
  args.push_back(tmp);
  // -xerror: a frame that fails to decode is an error, not a silently
  // dropped frame.
  args.insert(args.begin(),
              {opt.ffmpeg, "-nostdin", "-hide_banner", "-loglevel", "error", "-xerror", "-y"});
  const ProcessResult r = run_process(args);
  std::error_code ec;
  if (!r.ok()) {
    fs::remove(tmp, ec);
    if (!r.started) {
      throw VideoError(r.spawn_error + " (needed to write " + final_path +
                       "; install the ffmpeg package)");
    }
    throw VideoError("ffmpeg failed (" + r.status_text() + ") writing " + final_path + ":\n" +
                     tail_lines(r.output));
  }
  if (!fs::exists(tmp, ec) || fs::file_size(tmp, ec) == 0) {
    fs::remove(tmp, ec);
    throw VideoError("ffmpeg reported success but wrote nothing for " + final_path);
  }
  fs::rename(tmp, final_path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw VideoError("cannot rename " + tmp + " to " + final_path + ": " + ec.message());
  }
}

// The mp4's and the GIF's encoders (no GIF where its arguments are empty)
// side by side: the GIF's palette filters take one core, and x264 used
// about 1.3 (1.38 s of CPU in 1.03 s on 27 pages of 1280 x 667 px). Both are
// waited for; the mp4's failure is told first.
void run_side_by_side(const VideoOptions& opt, const std::vector<std::string>& mp4,
                      const std::string& mp4_path, const std::vector<std::string>& gif,
                      const std::string& gif_path) {
  std::future<void> gif_done;
  if (!gif.empty()) gif_done = std::async(std::launch::async, [&] { run_to(opt, gif, gif_path); });
  std::exception_ptr failed;
  try {
    run_to(opt, mp4, mp4_path);
  } catch (...) {
    failed = std::current_exception();
  }
  try {
    if (gif_done.valid()) gif_done.get();
  } catch (...) {
    if (!failed) failed = std::current_exception();
  }
  if (failed) std::rethrow_exception(failed);
}

}  // namespace

int count_frames(const std::string& frames_dir) {
  int n = 0;
  std::error_code ec;
  while (fs::is_regular_file(fs::path(frames_dir) / frame_name(n), ec)) ++n;
  return n;
}

namespace {

// The size every frame of dir has. ffmpeg starts its filters again where the
// frames' size changes, and a GIF's one palette for the clip then covered
// only the frames after the change: the gallery's side-by-side GIF lost the
// first half of its slide that way. So a clip of two sizes is refused.
PngSize one_frame_size(const fs::path& dir) {
  const PngSize first = png_size((dir / frame_name(0)).string());
  for (int k = 1, n = count_frames(dir.string()); k < n; ++k) {
    const PngSize s = png_size((dir / frame_name(k)).string());
    if (s.width != first.width || s.height != first.height)
      throw VideoError("frame " + (dir / frame_name(k)).string() + " is " +
                       std::to_string(s.width) + " x " + std::to_string(s.height) + " px, but " +
                       frame_name(0) + " is " + std::to_string(first.width) + " x " +
                       std::to_string(first.height) + ": every frame of a clip must have one size");
  }
  return first;
}

}  // namespace

bool ffmpeg_available(std::string* why, const std::string& ffmpeg) {
  auto fail = [why](const std::string& msg) {
    if (why) *why = msg;
    return false;
  };
  const ProcessResult enc = run_process({ffmpeg, "-hide_banner", "-encoders"}, 1 << 20);
  if (!enc.started) return fail(enc.spawn_error + " (install the ffmpeg package)");
  if (!enc.ok()) {
    return fail("'" + ffmpeg + " -encoders' failed (" + enc.status_text() + "): " +
                tail_lines(enc.output, 300));
  }
  if (enc.output.find(" libx264 ") == std::string::npos) {
    return fail("'" + ffmpeg + "' has no libx264 encoder (needed for browser-playable mp4)");
  }
  if (enc.output.find(" gif ") == std::string::npos) {
    return fail("'" + ffmpeg + "' has no gif encoder");
  }
  const ProcessResult fil = run_process({ffmpeg, "-hide_banner", "-filters"}, 1 << 20);
  if (!fil.ok() || fil.output.find(" palettegen ") == std::string::npos) {
    return fail("'" + ffmpeg + "' has no palettegen filter (needed for the gif)");
  }
  if (why) why->clear();
  return true;
}

VideoFiles encode_video(const std::string& frames_dir, const std::string& out_dir,
                        const std::string& name, const VideoOptions& opt) {
  if (name.empty() || name.find('/') != std::string::npos || name[0] == '.') {
    throw InvalidArgument("video name '" + name +
                          "' must be a plain file name (no '/', not starting with '.')");
  }
  if (opt.fps < 1 || opt.fps > 240 || opt.play_fps < opt.fps || opt.play_fps > 240 ||
      opt.gif_width < 16 || opt.crf < 0 || opt.crf > 51) {
    throw InvalidArgument("video options out of range (fps 1..240, play_fps fps..240, "
                          "gif_width >= 16, crf 0..51)");
  }
  // Absolute paths: a directory named "-x" can never pass for an option.
  const fs::path dir = fs::absolute(frames_dir);
  const fs::path first = dir / frame_name(0);
  std::error_code ec;
  if (!fs::is_regular_file(first, ec)) {
    throw VideoError("no frames to encode: " + first.string() + " does not exist");
  }
  const fs::path out = fs::absolute(out_dir);
  if (!fs::is_directory(out, ec)) {
    throw VideoError("output directory " + out.string() + " does not exist");
  }
  const PngSize size = one_frame_size(dir);  // fails early on a clip of two sizes
  auto input_of = [&](const fs::path& d) {
    return std::vector<std::string>{"-framerate", std::to_string(opt.fps), "-start_number", "0",
                                    "-i", escape_percent(d.string()) + "/%06d.png"};
  };
  const std::vector<std::string> input = input_of(dir);
  const std::string repeat = "fps=" + std::to_string(opt.play_fps);

  VideoFiles files;
  files.mp4 = (out / (name + ".mp4")).string();
  std::vector<std::string> mp4 = input;
  // x264 with yuv420p needs even sizes: pad (not scale) to keep pixels sharp.
  // Each painted frame is converted to yuv420p once, before the repeats: the
  // repeats converted it play_fps / fps times over. The same mp4 byte for
  // byte, in 0.74 of the time (render/README.md).
  mp4.insert(mp4.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white,format=yuv420p," + repeat,
                         "-c:v", "libx264", "-preset", "veryfast", "-crf",
                         std::to_string(opt.crf), "-pix_fmt", "yuv420p", "-movflags",
                         "+faststart", "-f", "mp4"});
  std::vector<std::string> gif;
  if (opt.gif) {
    files.gif = (out / (name + ".gif")).string();
    const bool own = !opt.gif_frames_dir.empty();
    if (own) one_frame_size(fs::absolute(opt.gif_frames_dir));
    const int width = std::min(opt.gif_width, size.width);
    const std::string fit = own ? "null" : "scale=" + std::to_string(width) + ":-1:flags=lanczos";
    // One palette for the whole clip (palettegen), then dithered mapping; at
    // the story's pace, without the mp4's repeats (VideoOptions).
    const std::string graph = fit + ",split[a][b];[a]palettegen[p];[b][p]paletteuse";
    gif = own ? input_of(fs::absolute(opt.gif_frames_dir)) : input;
    gif.insert(gif.end(), {"-vf", graph, "-loop", "0", "-f", "gif"});
  }
  run_side_by_side(opt, mp4, files.mp4, gif, files.gif);
  return files;
}

}  // namespace render
