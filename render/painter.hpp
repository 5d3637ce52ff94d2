#pragma once
// The one-call API for the app: points + FrameSpec -> annotated Image.
// A Painter owns the OSMesa context and the font and is reused for every
// frame; keep one per thread (OpenGL contexts are bound per thread).
#include <string>

#include "render/annotate.hpp"
#include "render/font.hpp"
#include "render/frame_spec.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"
#include "render/splat.hpp"

namespace render {

// Wall-clock milliseconds of the last paint(), for benchmarks.
struct PaintTimings {
  double layout_ms = 0, splat_ms = 0, readback_ms = 0, annotate_ms = 0;
  double total_ms() const { return layout_ms + splat_ms + readback_ms + annotate_ms; }
};

struct PainterOptions {
  std::string font_path = default_font_path();
  // Calls keep_freed_heap_memory() (process-wide glibc malloc setting; see
  // gl_context.hpp). Without it frames can be several times slower.
  bool keep_heap = true;
};

class Painter {
 public:
  // Throws GlError / FontError if OSMesa or the font cannot be set up.
  Painter(int width, int height, const PainterOptions& options = {});

  // Paints one frame. A spec whose width/height differ from the current
  // buffer resizes it. Throws InvalidArgument for a bad spec or view.
  Image paint(const FrameSpec& spec, const PointsView& points);
  // Same, into an existing image (reuses its memory between frames).
  void paint_into(Image& out, const FrameSpec& spec, const PointsView& points);

  // Where the last frame put the world window, ticks and colour bar.
  const FrameLayout& last_layout() const { return layout_; }
  const PaintTimings& last_timings() const { return timings_; }
  // Quads the last frame sent to GL (points after culling and run merging).
  std::size_t last_quads() const { return splatter_.last_drawn(); }
  std::string gl_renderer() { return ctx_.renderer(); }
  Font& font() { return font_; }

 private:
  OffscreenContext ctx_;
  Font font_;
  Splatter splatter_;
  FrameLayout layout_;
  PaintTimings timings_;
};

}  // namespace render
