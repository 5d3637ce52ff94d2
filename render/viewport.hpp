#pragma once
// World (metres, y up) to pixel (y down) mapping with equal scale on both
// axes, so 1 m in x is as long on screen as 1 m in y.
#include "render/image.hpp"

namespace render {

struct WorldWindow {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// Throws InvalidArgument naming the offending bound if the window is empty,
// inverted or not finite.
void validate_window(const WorldWindow& w);

class PixelMap {
 public:
  PixelMap() = default;
  // left/top: pixel position of world (x0, y1); scale: pixels per metre.
  PixelMap(const WorldWindow& window, double left, double top, double scale)
      : window_(window), left_(left), top_(top), scale_(scale) {}

  double x(double wx) const { return left_ + (wx - window_.x0) * scale_; }
  double y(double wy) const { return top_ + (window_.y1 - wy) * scale_; }
  double scale() const { return scale_; }
  const WorldWindow& window() const { return window_; }
  // The window's outline in pixels, edges rounded to the nearest pixel.
  Rect box() const;

 private:
  WorldWindow window_;
  double left_ = 0, top_ = 0, scale_ = 1;
};

// Largest equal-scale fit of window into area, centred, with the window's
// corner snapped to a whole pixel so pixel edges line up with world edges.
PixelMap fit_window(const WorldWindow& window, const Rect& area);

}  // namespace render
