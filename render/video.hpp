#pragma once
// Numbered PNG frames (000000.png, 000001.png, ...) -> <name>.mp4 (H.264,
// yuv420p, even size, faststart: plays in browsers) and a small looping
// <name>.gif, through the ffmpeg program.
#include <string>

namespace render {

struct VideoOptions {
  int fps = 25;           // frames per second of the mp4
  int crf = 20;           // x264 quality, lower is better (0..51)
  bool gif = true;        // also write the GIF
  int gif_width = 480;    // GIF width in px (never upscaled); aspect kept
  int gif_fps = 12;       // GIF frame rate (frames are dropped to reach it)
  std::string ffmpeg = "ffmpeg";  // program name or path
};

struct VideoFiles {
  std::string mp4;
  std::string gif;  // empty when options.gif is false
};

// Checks that ffmpeg runs and has the libx264 and gif encoders and the
// palettegen filter. On false, *why (if given) says what is missing, so the
// app can refuse to start before simulating for hours.
bool ffmpeg_available(std::string* why, const std::string& ffmpeg = "ffmpeg");

// Encodes frames_dir/%06d.png (from 000000.png on) into out_dir/<name>.mp4
// and out_dir/<name>.gif. Each is written under a temporary name and
// renamed when ffmpeg succeeded. Throws VideoError (with the tail of
// ffmpeg's messages) on failure; InvalidArgument for a bad name or option.
VideoFiles encode_video(const std::string& frames_dir, const std::string& out_dir,
                        const std::string& name, const VideoOptions& options = {});

// Number of consecutive frames 000000.png, 000001.png, ... in dir.
int count_frames(const std::string& frames_dir);

}  // namespace render
