#include "render/image.hpp"

#include <algorithm>
#include <string>

#include "render/error.hpp"

namespace render {

namespace {
// 16k x 16k RGBA is 1 GiB; anything larger is a bug in the caller.
constexpr int kMaxSide = 16384;
}  // namespace

Image::Image(int width, int height, Rgba fill_colour) {
  if (width < 0 || height < 0 || width > kMaxSide || height > kMaxSide) {
    throw InvalidArgument("image size " + std::to_string(width) + "x" +
                          std::to_string(height) + " is outside 0.." +
                          std::to_string(kMaxSide));
  }
  width_ = width;
  height_ = height;
  pixels_.resize(std::size_t(width) * std::size_t(height) * 4);
  fill(fill_colour);
}

Rgba Image::at(int x, int y) const {
  const std::uint8_t* p = row(y) + std::size_t(x) * 4;
  return Rgba{p[0], p[1], p[2], p[3]};
}

void Image::set(int x, int y, Rgba c) {
  std::uint8_t* p = row(y) + std::size_t(x) * 4;
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
  p[3] = c.a;
}

Rgba Image::pixel(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) {
    throw InvalidArgument("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                          ") is outside the " + std::to_string(width_) + "x" +
                          std::to_string(height_) + " image");
  }
  return at(x, y);
}

void Image::fill(Rgba c) { fill_rect(Rect{0, 0, width_, height_}, c); }

Rect clip_rect(const Rect& r, int width, int height) {
  const int x0 = std::max(r.x, 0), y0 = std::max(r.y, 0);
  const int x1 = std::min(r.right(), width), y1 = std::min(r.bottom(), height);
  if (x1 <= x0 || y1 <= y0) return Rect{0, 0, 0, 0};
  return Rect{x0, y0, x1 - x0, y1 - y0};
}

void Image::fill_rect(const Rect& r, Rgba c) {
  const Rect k = clip_rect(r, width_, height_);
  for (int y = k.y; y < k.bottom(); ++y) {
    std::uint8_t* p = row(y) + std::size_t(k.x) * 4;
    for (int x = 0; x < k.w; ++x, p += 4) {
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
      p[3] = c.a;
    }
  }
}

void Image::frame_rect(const Rect& r, Rgba c) {
  fill_rect(Rect{r.x - 1, r.y - 1, r.w + 2, 1}, c);
  fill_rect(Rect{r.x - 1, r.bottom(), r.w + 2, 1}, c);
  fill_rect(Rect{r.x - 1, r.y - 1, 1, r.h + 2}, c);
  fill_rect(Rect{r.right(), r.y - 1, 1, r.h + 2}, c);
}

void Image::blend(int x, int y, Rgba c, std::uint8_t coverage) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_ || coverage == 0) return;
  const unsigned a = (unsigned(coverage) * c.a + 127) / 255;
  if (a == 0) return;
  std::uint8_t* p = row(y) + std::size_t(x) * 4;
  const unsigned inv = 255 - a;
  p[0] = std::uint8_t((c.r * a + p[0] * inv + 127) / 255);
  p[1] = std::uint8_t((c.g * a + p[1] * inv + 127) / 255);
  p[2] = std::uint8_t((c.b * a + p[2] * inv + 127) / 255);
  p[3] = std::uint8_t(a + (p[3] * inv + 127) / 255);
}

void Image::blit(const Image& src, int x, int y) {
  const Rect k = clip_rect(Rect{x, y, src.width(), src.height()}, width_, height_);
  for (int yy = k.y; yy < k.bottom(); ++yy) {
    const std::uint8_t* s = src.row(yy - y) + std::size_t(k.x - x) * 4;
    std::copy(s, s + std::size_t(k.w) * 4, row(yy) + std::size_t(k.x) * 4);
  }
}

Image Image::crop(const Rect& r) const {
  const Rect k = clip_rect(r, width_, height_);
  Image out(k.w, k.h);
  for (int y = 0; y < k.h; ++y) {
    const std::uint8_t* s = row(k.y + y) + std::size_t(k.x) * 4;
    std::copy(s, s + std::size_t(k.w) * 4, out.row(y));
  }
  return out;
}

}  // namespace render
