#include "render/splat.hpp"

#include <GL/osmesa.h>

#include <algorithm>
#include <cmath>

#include "render/error.hpp"

namespace render {

void validate_points(const PointsView& p) {
  if (p.count == 0) return;
  const char* missing = !p.x             ? "x"
                        : !p.y           ? "y"
                        : !p.half_width  ? "half_width"
                        : !p.half_height ? "half_height"
                        : !p.value       ? "value"
                                         : nullptr;
  if (missing) {
    throw InvalidArgument(std::string("PointsView with ") + std::to_string(p.count) +
                          " points has a null '" + missing + "' array");
  }
}

namespace {
// std::lround of a clamped value without the call into libm (four a point;
// 3 % of the samples of a 4 M-point run painting three fields, issue 17):
// the nearest integer, halves away from zero. a - trunc(a) is exact, so the
// comparisons with 0.5 decide as lround does.
int round_half_away(double a) {
  const double whole = std::trunc(a), part = a - whole;
  return int(whole) + (part >= 0.5 ? 1 : part <= -0.5 ? -1 : 0);
}

// Snap both edges to the nearest pixel boundary and keep at least one pixel:
// a half-open [a, a + 1) span always holds exactly one pixel centre.
void snap_span(double a, double b, int& lo, int& hi) {
  // Clamp far-off values before the int conversion.
  a = std::clamp(a, -1e7, 1e7);
  b = std::clamp(b, -1e7, 1e7);
  lo = round_half_away(a);
  hi = round_half_away(b);
  if (hi <= lo) {
    lo = int(std::floor((a + b) / 2));
    hi = lo + 1;
  }
}
}  // namespace

PixelSquare snap_square(const PixelMap& map, double x, double y, double hw, double hh) {
  PixelSquare s{};
  snap_span(map.x(x - hw), map.x(x + hw), s.x0, s.x1);
  snap_span(map.y(y + hh), map.y(y - hh), s.y0, s.y1);
  return s;
}

// The quads of points [first, end) into xy_ and rgba_, from quad 0: returns
// how many. Consecutive squares on the same pixel rows, same colour,
// touching or overlapping, become one wider quad that paints exactly the
// same pixels in the same order: it cuts the primitive count several-fold
// for smooth fields, and llvmpipe's per-primitive setup is the cost that
// matters.
std::size_t Splatter::batch_quads(const PixelMap& map, const Rect& clip, const PointsView& points,
                                  std::size_t first, std::size_t end, const ColourMap& cmap,
                                  double lo, double hi) {
  std::size_t n = 0;
  PixelSquare last{};
  Rgba last_colour{};
  for (std::size_t i = first; i < end; ++i) {
    const double x = points.x[i], y = points.y[i];
    const double hw = std::abs(points.half_width[i]), hh = std::abs(points.half_height[i]);
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(hw) || !std::isfinite(hh)) {
      continue;
    }
    const PixelSquare s = snap_square(map, x, y, hw, hh);
    if (s.x1 <= clip.x || s.x0 >= clip.right() || s.y1 <= clip.y || s.y0 >= clip.bottom()) {
      continue;
    }
    const Rgba c = cmap.map(points.value[i], lo, hi);
    if (n > 0 && s.y0 == last.y0 && s.y1 == last.y1 && c == last_colour &&
        s.x0 <= last.x1 && s.x1 >= last.x0) {
      last.x0 = std::min(last.x0, s.x0);
      last.x1 = std::max(last.x1, s.x1);
      float* v = &xy_[(n - 1) * 8];
      v[0] = v[6] = float(last.x0);
      v[2] = v[4] = float(last.x1);
      continue;
    }
    // Image rows grow downward; the projection in draw() flips them for GL.
    float* v = &xy_[n * 8];
    v[0] = float(s.x0), v[1] = float(s.y0);
    v[2] = float(s.x1), v[3] = float(s.y0);
    v[4] = float(s.x1), v[5] = float(s.y1);
    v[6] = float(s.x0), v[7] = float(s.y1);
    std::uint8_t* q = &rgba_[n * 16];
    for (int k = 0; k < 4; ++k) {
      q[4 * k + 0] = c.r, q[4 * k + 1] = c.g, q[4 * k + 2] = c.b, q[4 * k + 3] = c.a;
    }
    last = s;
    last_colour = c;
    ++n;
  }
  return n;
}

void Splatter::draw(OffscreenContext& ctx, const PixelMap& map, const Rect& clip_in,
                    const PointsView& points, const ColourMap& cmap, double lo,
                    double hi, const SplatStyle& style) {
  validate_points(points);
  if (!cmap.is_categorical()) validate_range(lo, hi);
  const int W = ctx.width(), H = ctx.height();
  const Rect clip = clip_rect(clip_in, W, H);

  ctx.make_current();
  glViewport(0, 0, W, H);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_DITHER);
  glClearColor(style.background.r / 255.f, style.background.g / 255.f,
               style.background.b / 255.f, style.background.a / 255.f);
  glClear(GL_COLOR_BUFFER_BIT);
  drawn_ = 0;
  if (points.count == 0 || clip.w == 0) return;

  // Scissor rows count from the bottom in GL.
  glEnable(GL_SCISSOR_TEST);
  glScissor(clip.x, H - clip.bottom(), clip.w, clip.h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, H, 0, -1, 1);  // image coordinates, y down
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_FLAT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  // The points go in batches of kSplatBatch, each its own draw call, in
  // their order: without blending the last quad drawn on a pixel sets it
  // either way, so the image is the same as from one call, and the vertex
  // buffers hold one batch (3 MB) instead of 48 B for every point, 190 MB
  // for a frame of 4 M points.
  const std::size_t batch = std::min(points.count, kSplatBatch);
  xy_.resize(batch * 8);
  rgba_.resize(batch * 16);
  glVertexPointer(2, GL_FLOAT, 0, xy_.data());
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, rgba_.data());
  for (std::size_t first = 0; first < points.count; first += batch) {
    const std::size_t end = std::min(points.count, first + batch);
    const std::size_t n = batch_quads(map, clip, points, first, end, cmap, lo, hi);
    if (n > 0) glDrawArrays(GL_QUADS, 0, GLsizei(n * 4));
    // glDrawArrays copies the client arrays before it returns, so the next
    // batch may overwrite them.
    drawn_ += n;
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace render
