#pragma once
// RGBA8 raster, row 0 at the top. Plain value type: copyable, no GL inside.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace render {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba& p, const Rgba& q) {
    return p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a;
  }
  friend bool operator!=(const Rgba& p, const Rgba& q) { return !(p == q); }
};

inline constexpr Rgba kWhite{255, 255, 255, 255};
inline constexpr Rgba kBlack{0, 0, 0, 255};

// Integer pixel rectangle; [x, x + w) x [y, y + h).
struct Rect {
  int x = 0, y = 0, w = 0, h = 0;
  int right() const { return x + w; }
  int bottom() const { return y + h; }
  bool contains(int px, int py) const {
    return px >= x && px < x + w && py >= y && py < y + h;
  }
  friend bool operator==(const Rect& a, const Rect& b) {
    return a.x == b.x && a.y == b.y && a.w == b.w && a.h == b.h;
  }
};

class Image {
 public:
  Image() = default;
  // Throws InvalidArgument for negative or absurd sizes.
  Image(int width, int height, Rgba fill = kWhite);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return width_ == 0 || height_ == 0; }

  // Tightly packed RGBA, width*4 bytes a row, top row first.
  std::uint8_t* data() { return pixels_.data(); }
  const std::uint8_t* data() const { return pixels_.data(); }
  std::uint8_t* row(int y) { return pixels_.data() + std::size_t(y) * stride(); }
  const std::uint8_t* row(int y) const {
    return pixels_.data() + std::size_t(y) * stride();
  }
  std::size_t stride() const { return std::size_t(width_) * 4; }
  std::size_t byte_size() const { return pixels_.size(); }

  // Unchecked access; callers keep (x, y) inside the image.
  Rgba at(int x, int y) const;
  void set(int x, int y, Rgba c);
  // Checked: throws InvalidArgument naming the coordinates.
  Rgba pixel(int x, int y) const;

  void fill(Rgba c);
  // Clipped to the image; a rectangle partly outside is drawn where it lands.
  void fill_rect(const Rect& r, Rgba c);
  // A 1 px line just outside r (an axes box, a colour bar).
  void frame_rect(const Rect& r, Rgba c);
  // Source-over blend of colour c with coverage alpha (0..255) at (x, y),
  // ignoring points outside the image.
  void blend(int x, int y, Rgba c, std::uint8_t coverage);
  // Copies src with its top-left corner at (x, y), clipped.
  void blit(const Image& src, int x, int y);
  // Copy of the region r (clipped to the image).
  Image crop(const Rect& r) const;

  friend bool operator==(const Image& a, const Image& b) {
    return a.width_ == b.width_ && a.height_ == b.height_ && a.pixels_ == b.pixels_;
  }
  friend bool operator!=(const Image& a, const Image& b) { return !(a == b); }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> pixels_;
};

// Clip r to the image bounds (may return an empty rect).
Rect clip_rect(const Rect& r, int width, int height);

}  // namespace render
