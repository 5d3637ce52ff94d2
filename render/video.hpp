#pragma once
// Numbered PNG frames (000000.png, 000001.png, ...) -> <name>.mp4 (H.264,
// yuv420p, even size, faststart: plays in browsers) and a small looping
// <name>.gif, through the ffmpeg program.
#include <string>

namespace render {

// Frames are shown at `fps` (the pace of the story: a few frames per second
// of a slide painted every 0.5 s). The mp4 plays at `play_fps`: each frame is
// repeated until the next is due, so players that stutter below 24 fps
// play a smooth clip of the same length. (Interpolating between frames would
// show states the simulation never had.) The GIF needs no repeats, since each
// of its frames carries its own delay: it holds each frame for 1/fps.
struct VideoOptions {
  int fps = 25;           // frames shown per second
  int play_fps = 25;      // frames per second of the mp4 (at least fps)
  // x264 quality, lower is better (0..51). 17 with the veryfast preset
  // matches 20 with medium (SSIM 0.9986 on 4-panel 1920 x 1000 pages) in
  // 0.6 of the time, for files 10 % larger (render/README.md).
  int crf = 17;
  bool gif = true;        // also write the GIF
  int gif_width = 480;    // GIF width in px (never upscaled); aspect kept
  // Frames painted at the GIF's own size, so their text stays legible
  // (DIR/%06d.png, as many as the video's). "": the video's frames, scaled.
  std::string gif_frames_dir;
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
