#include "bench/loglog_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/colour_map.hpp"

namespace bench {

namespace {

using render::Image;
using render::Rect;
using render::Rgba;

constexpr Rgba kGrid{225, 225, 225, 255};
constexpr Rgba kMinorGrid{243, 243, 243, 255};
constexpr Rgba kRing{214, 39, 40, 255};

// Anti-aliased disc: coverage falls from 1 to 0 over the last pixel of the radius.
void disc(Image& img, double cx, double cy, double r, Rgba c) {
  for (int y = int(std::floor(cy - r - 1)); y <= int(std::ceil(cy + r + 1)); ++y)
    for (int x = int(std::floor(cx - r - 1)); x <= int(std::ceil(cx + r + 1)); ++x) {
      const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      const double cover = std::clamp(r + 0.5 - d, 0.0, 1.0);
      if (cover > 0 && x >= 0 && y >= 0 && x < img.width() && y < img.height())
        img.blend(x, y, c, static_cast<std::uint8_t>(cover * 255));
    }
}

void ring(Image& img, double cx, double cy, double r, double width, Rgba c) {
  for (int y = int(std::floor(cy - r - 2)); y <= int(std::ceil(cy + r + 2)); ++y)
    for (int x = int(std::floor(cx - r - 2)); x <= int(std::ceil(cx + r + 2)); ++x) {
      const double d = std::fabs(std::hypot(x + 0.5 - cx, y + 0.5 - cy) - r);
      const double cover = std::clamp(width / 2 + 0.5 - d, 0.0, 1.0);
      if (cover > 0 && x >= 0 && y >= 0 && x < img.width() && y < img.height())
        img.blend(x, y, c, static_cast<std::uint8_t>(cover * 255));
    }
}

// A line stamped with small discs every half pixel; `dash` > 0 leaves gaps.
void line(Image& img, double x0, double y0, double x1, double y1, Rgba c, double dash = 0) {
  const double len = std::hypot(x1 - x0, y1 - y0);
  const int n = std::max(1, int(len * 2));
  for (int k = 0; k <= n; ++k) {
    const double t = double(k) / n;
    if (dash > 0 && std::fmod(t * len, 2 * dash) > dash) continue;
    disc(img, x0 + t * (x1 - x0), y0 + t * (y1 - y0), 0.7, c);
  }
}

// Diamond of half-diagonal r, filled per pixel.
void diamond(Image& img, int cx, int cy, int r, Rgba c) {
  for (int y = -r; y <= r; ++y)
    for (int x = -r; x <= r; ++x)
      if (std::abs(x) + std::abs(y) <= r && cx + x >= 0 && cy + y >= 0 && cx + x < img.width() &&
          cy + y < img.height())
        img.set(cx + x, cy + y, c);
}

void marker(Image& img, double x, double y, int shape, Rgba c) {
  const int r = 5;
  if (shape == 2) {
    diamond(img, int(x), int(y), r + 3, render::kBlack);
    diamond(img, int(x), int(y), r + 1, c);
  } else if (shape == 1) {
    img.fill_rect({int(x) - r - 1, int(y) - r - 1, 2 * r + 3, 2 * r + 3}, render::kBlack);
    img.fill_rect({int(x) - r, int(y) - r, 2 * r + 1, 2 * r + 1}, c);
  } else {
    disc(img, x, y, r + 1, render::kBlack);
    disc(img, x, y, r, c);
  }
}

// "0.01", "0.1", "1", "10" for decades near 1; 10 with a superscript power beyond.
std::string decade_label(int k) {
  if (k >= -3 && k <= 3) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%g", std::pow(10.0, k));
    return buf;
  }
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string s = "10";
  if (k < 0) s += "⁻";
  for (char d : std::to_string(std::abs(k))) s += digits[d - '0'];
  return s;
}

// Whole decades enclosing [lo, hi], at least one.
void decades(double lo, double hi, int& k0, int& k1) {
  k0 = int(std::floor(std::log10(lo)));
  k1 = int(std::ceil(std::log10(hi)));
  if (k1 <= k0) k1 = k0 + 1;
}

}  // namespace

void draw_loglog(Image& img, const Rect& area, const LogLogPlot& plot, render::Font& font) {
  img.fill_rect(area, render::kWhite);
  double xlo = HUGE_VAL, xhi = 0, ylo = HUGE_VAL, yhi = 0;
  for (const PlotPoint& p : plot.points) {
    if (!(p.x > 0 && p.y > 0)) continue;
    xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
    ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
  }
  if (plot.threshold > 0) ylo = std::min(ylo, plot.threshold), yhi = std::max(yhi, plot.threshold);
  if (xhi == 0) xlo = 0.1, xhi = 1;
  if (yhi == 0) ylo = 0.1, yhi = 1;
  int kx0, kx1, ky0, ky1;
  decades(xlo, xhi, kx0, kx1);
  decades(ylo, yhi, ky0, ky1);
  const int legend_w = 190, label = 16, small = 14;
  const Rect box{area.x + 86, area.y + 44, area.w - 86 - legend_w - 16, area.h - 44 - 64};
  auto px = [&](double x) { return box.x + (std::log10(x) - kx0) / (kx1 - kx0) * box.w; };
  auto py = [&](double y) { return box.bottom() - (std::log10(y) - ky0) / (ky1 - ky0) * box.h; };

  // Minor grid at 2..9 x 10^k, decade grid and labels.
  for (int k = kx0; k <= kx1; ++k)
    for (int m = 1; m <= (k < kx1 ? 9 : 1); ++m) {
      const int x = int(px(m * std::pow(10.0, k)));
      img.fill_rect({x, box.y, 1, box.h}, m == 1 ? kGrid : kMinorGrid);
      if (m == 1)
        font.draw(img, decade_label(k), small, x, box.bottom() + 6, render::HAlign::Centre,
                  render::VAlign::Top);
    }
  for (int k = ky0; k <= ky1; ++k)
    for (int m = 1; m <= (k < ky1 ? 9 : 1); ++m) {
      const int y = int(py(m * std::pow(10.0, k)));
      img.fill_rect({box.x, y, box.w, 1}, m == 1 ? kGrid : kMinorGrid);
      if (m == 1)
        font.draw(img, decade_label(k), small, box.x - 6, y, render::HAlign::Right,
                  render::VAlign::Middle);
    }
  for (const Rect& edge : {Rect{box.x, box.y, box.w, 1}, Rect{box.x, box.bottom(), box.w + 1, 1},
                           Rect{box.x, box.y, 1, box.h}, Rect{box.right(), box.y, 1, box.h}})
    img.fill_rect(edge, render::kBlack);
  font.draw(img, plot.title, 18, box.x + box.w / 2, area.y + 12, render::HAlign::Centre,
            render::VAlign::Top);
  font.draw(img, plot.x_label, label, box.x + box.w / 2, box.bottom() + 32,
            render::HAlign::Centre, render::VAlign::Top);
  render::draw_mask(img, render::rotate_ccw(font.render(plot.y_label, label)), area.x + 8,
                    box.y + box.h / 2, render::HAlign::Left, render::VAlign::Middle,
                    render::kBlack);

  if (plot.threshold > 0) {
    const double y = py(plot.threshold);
    line(img, box.x, y, box.right(), y, Rgba{90, 90, 90, 255}, 6);
    font.draw(img, plot.threshold_label, small, box.right() - 4, int(y) - 3,
              render::HAlign::Right, render::VAlign::Bottom, Rgba{90, 90, 90, 255});
  }

  const render::ColourMap tab10 = render::ColourMap::categorical();
  auto drawable = [](const PlotPoint& p) { return p.x > 0 && p.y > 0; };
  for (std::size_t a = 0; a < plot.points.size(); ++a) {  // join each point to the next of its kind
    const PlotPoint& p = plot.points[a];
    if (!drawable(p)) continue;
    for (std::size_t b = a + 1; b < plot.points.size(); ++b) {
      const PlotPoint& q = plot.points[b];
      if (q.series != p.series || q.group != p.group || !drawable(q)) continue;
      line(img, px(p.x), py(p.y), px(q.x), py(q.y), tab10.map(p.series, 0, 1));
      break;
    }
  }
  for (const PlotPoint& p : plot.points) {
    if (!drawable(p)) continue;
    marker(img, px(p.x), py(p.y), p.shape, tab10.map(p.series, 0, 1));
    if (!p.label.empty())
      font.draw(img, p.label, 11, int(px(p.x)) + 8, int(py(p.y)) - 7, render::HAlign::Left,
                render::VAlign::Bottom, Rgba{110, 110, 110, 255});
  }
  if (plot.highlight >= 0 && drawable(plot.points[plot.highlight])) {
    const PlotPoint& p = plot.points[plot.highlight];
    ring(img, px(p.x), py(p.y), 11, 2.5, kRing);
    const bool right_half = px(p.x) > box.x + box.w / 2;  // keep the label inside the box
    font.draw(img, plot.highlight_label, small, int(px(p.x)) + (right_half ? -14 : 14),
              int(py(p.y)) + 14, right_half ? render::HAlign::Right : render::HAlign::Left,
              render::VAlign::Top, kRing);
  }

  // Legend: colours, then shapes.
  int y = box.y + 10;
  const int lx = box.right() + 24;
  for (std::size_t s = 0; s < plot.series.size(); ++s, y += 24) {
    marker(img, lx, y, 0, tab10.map(int(s), 0, 1));
    font.draw(img, plot.series[s], small, lx + 14, y, render::HAlign::Left, render::VAlign::Middle);
  }
  y += 8;
  for (std::size_t s = 0; s < plot.shape_names.size(); ++s, y += 24) {
    marker(img, lx, y, int(s), Rgba{200, 200, 200, 255});
    font.draw(img, plot.shape_names[s], small, lx + 14, y, render::HAlign::Left,
              render::VAlign::Middle);
  }
}

}  // namespace bench
