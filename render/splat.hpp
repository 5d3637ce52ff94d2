#pragma once
// Draws every point as a filled axis-aligned square (its GIMP domain), in
// OpenGL draw calls of kSplatBatch points.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/colour_map.hpp"
#include "render/gl_context.hpp"
#include "render/viewport.hpp"

namespace render {

// Read-only view of the point cloud; the caller owns the arrays, which must
// each hold `count` entries. World units (metres), half widths > 0.
struct PointsView {
  std::size_t count = 0;
  const double* x = nullptr;
  const double* y = nullptr;
  const double* half_width = nullptr;
  const double* half_height = nullptr;
  const double* value = nullptr;  // scalar field to colour by
  // Optional material id per point; where given, the painter outlines the
  // materials other than 0 (outline.hpp).
  const std::uint8_t* material = nullptr;
};

// Throws InvalidArgument if count > 0 and any array is null.
void validate_points(const PointsView& points);

struct SplatStyle {
  Rgba background = kWhite;
};

// Square edges snapped to whole pixels; each square at least 1 px wide and
// tall so sub-pixel points never vanish and neighbours never leave
// hairline gaps. Every edge lands within 1 px of its exact position.
struct PixelSquare {
  int x0, y0, x1, y1;  // [x0, x1) x [y0, y1), image rows (y down)
};
PixelSquare snap_square(const PixelMap& map, double x, double y, double hw, double hh);

// Points per draw call: the vertex buffers hold this many at most.
constexpr std::size_t kSplatBatch = 65536;

class Splatter {
 public:
  // Clears ctx to style.background, then paints points clipped to `clip`
  // (normally the world window's pixel box). Leaves the result in ctx;
  // read it with ctx.read_image(). Vertex buffers are kept between calls.
  void draw(OffscreenContext& ctx, const PixelMap& map, const Rect& clip,
            const PointsView& points, const ColourMap& cmap, double lo, double hi,
            const SplatStyle& style = {});

  // Quads sent to GL by the last draw, after culling points outside the
  // clip and merging same-colour runs within each batch.
  std::size_t last_drawn() const { return drawn_; }

 private:
  std::size_t batch_quads(const PixelMap& map, const Rect& clip, const PointsView& points,
                          std::size_t first, std::size_t end, const ColourMap& cmap, double lo,
                          double hi);
  std::vector<float> xy_;
  std::vector<std::uint8_t> rgba_;
  std::size_t drawn_ = 0;
};

}  // namespace render
