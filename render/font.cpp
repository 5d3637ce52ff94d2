#include "render/font.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <sstream>

#include "render/error.hpp"

namespace render {

std::string default_font_path() {
  return "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
}

struct Font::FtState {
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
  ~FtState() {
    if (face) FT_Done_Face(face);
    if (lib) FT_Done_FreeType(lib);
  }
};

struct Font::Layout {
  struct Placed {
    const Glyph* g;
    int x;  // pen position in whole pixels
  };
  std::vector<Placed> glyphs;
  int x_min = 0, x_max = 0, ascent = 0, descent = 0;
};

std::u32string decode_utf8(const std::string& s) {
  std::u32string out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const int extra = c < 0x80 ? 0
                      : (c >> 5) == 0x6  ? 1
                      : (c >> 4) == 0xE  ? 2
                      : (c >> 3) == 0x1E ? 3
                                         : -1;
    if (extra < 0 || (extra > 0 && i + std::size_t(extra) >= s.size())) {
      throw FontError("malformed UTF-8 at byte " + std::to_string(i) + " of \"" + s + "\"");
    }
    char32_t cp = extra == 0 ? c : c & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k) {
      const unsigned char d = static_cast<unsigned char>(s[i + k]);
      if ((d >> 6) != 0x2) {
        throw FontError("malformed UTF-8 at byte " + std::to_string(i + k) + " of \"" + s + "\"");
      }
      cp = (cp << 6) | (d & 0x3F);
    }
    out.push_back(cp);
    i += std::size_t(extra) + 1;
  }
  return out;
}

Font::Font(const std::string& path) : ft_(std::make_unique<FtState>()), path_(path) {
  if (FT_Init_FreeType(&ft_->lib) != 0) throw FontError("FT_Init_FreeType failed");
  const FT_Error err = FT_New_Face(ft_->lib, path.c_str(), 0, &ft_->face);
  if (err != 0) {
    throw FontError("cannot load font '" + path + "' (FreeType error " +
                    std::to_string(err) +
                    "); on Debian/Ubuntu install the fonts-dejavu-core package");
  }
  if (!FT_IS_SCALABLE(ft_->face)) throw FontError("font '" + path + "' is not scalable");
}

Font::~Font() = default;

void Font::set_size(int pixel_size) {
  if (pixel_size < 4 || pixel_size > 512) {
    throw FontError("font pixel size " + std::to_string(pixel_size) + " is outside 4..512");
  }
  if (pixel_size == current_size_) return;
  if (FT_Set_Pixel_Sizes(ft_->face, 0, FT_UInt(pixel_size)) != 0) {
    throw FontError("cannot set size " + std::to_string(pixel_size) + " px on '" + path_ + "'");
  }
  current_size_ = pixel_size;
}

const Font::Glyph& Font::glyph(char32_t code, int pixel_size) {
  const std::uint64_t key = (std::uint64_t(pixel_size) << 32) | std::uint64_t(code);
  auto it = cache_.find(key);
  if (it != cache_.end()) return it->second;
  set_size(pixel_size);
  FT_Face face = ft_->face;
  const FT_UInt index = FT_Get_Char_Index(face, FT_ULong(code));  // 0: missing glyph box
  // Light hinting: crisp baselines without the heavy, stem-snapped strokes
  // of full hinting (an "=" at 17 px came out bold).
  if (FT_Load_Glyph(face, index, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) != 0) {
    throw FontError("cannot render glyph U+" + std::to_string(unsigned(code)) + " from '" +
                    path_ + "'");
  }
  const FT_GlyphSlot slot = face->glyph;
  Glyph g;
  g.left = slot->bitmap_left;
  g.top = slot->bitmap_top;
  g.width = int(slot->bitmap.width);
  g.height = int(slot->bitmap.rows);
  g.advance = int(slot->advance.x);
  g.index = index;
  g.bitmap.resize(std::size_t(g.width) * g.height);
  for (int y = 0; y < g.height; ++y) {
    const unsigned char* src = slot->bitmap.buffer + std::ptrdiff_t(y) * slot->bitmap.pitch;
    std::copy(src, src + g.width, g.bitmap.begin() + std::ptrdiff_t(y) * g.width);
  }
  return cache_.emplace(key, std::move(g)).first->second;
}

int Font::line_height(int pixel_size) {
  set_size(pixel_size);
  const FT_Size_Metrics& m = ft_->face->size->metrics;
  return int((m.ascender + 63) >> 6) + int((-m.descender + 63) >> 6);
}

Font::Layout Font::layout(const std::string& utf8, int pixel_size) {
  const std::u32string text = decode_utf8(utf8);
  set_size(pixel_size);
  FT_Face face = ft_->face;
  Layout L;
  L.ascent = int((face->size->metrics.ascender + 63) >> 6);
  L.descent = int((-face->size->metrics.descender + 63) >> 6);
  long pen = 0;  // 26.6
  unsigned prev = 0;
  for (char32_t c : text) {
    const Glyph& g = glyph(c, pixel_size);
    if (prev && g.index && FT_HAS_KERNING(face)) {
      FT_Vector k{};
      if (FT_Get_Kerning(face, prev, g.index, FT_KERNING_DEFAULT, &k) == 0) pen += k.x;
    }
    const int x = int((pen + 32) >> 6);
    L.glyphs.push_back({&g, x});
    if (g.width > 0) {
      L.x_min = std::min(L.x_min, x + g.left);
      L.x_max = std::max(L.x_max, x + g.left + g.width);
      L.ascent = std::max(L.ascent, g.top);
      L.descent = std::max(L.descent, g.height - g.top);
    }
    pen += g.advance;
    prev = g.index;
  }
  L.x_max = std::max(L.x_max, int((pen + 32) >> 6));
  return L;
}

int Font::text_width(const std::string& utf8, int pixel_size) {
  const Layout L = layout(utf8, pixel_size);
  return L.x_max - L.x_min;
}

TextMask Font::render(const std::string& utf8, int pixel_size) {
  const Layout L = layout(utf8, pixel_size);
  TextMask m;
  m.width = L.x_max - L.x_min;
  m.height = L.ascent + L.descent;
  m.baseline = L.ascent;
  m.alpha.assign(std::size_t(m.width) * m.height, 0);
  for (const auto& p : L.glyphs) {
    const Glyph& g = *p.g;
    const int ox = p.x + g.left - L.x_min, oy = m.baseline - g.top;
    for (int y = 0; y < g.height; ++y) {
      for (int x = 0; x < g.width; ++x) {
        std::uint8_t& dst = m.alpha[std::size_t(oy + y) * m.width + (ox + x)];
        dst = std::max(dst, g.bitmap[std::size_t(y) * g.width + x]);
      }
    }
  }
  return m;
}

int ink_height(const TextMask& m) {
  int rows = 0;
  for (int y = 0; y < m.height; ++y) {
    bool ink = false;
    for (int x = 0; x < m.width && !ink; ++x) ink = m.at(x, y) >= 128;
    rows += ink;
  }
  return rows;
}

TextMask rotate_ccw(const TextMask& m) {
  TextMask r;
  r.width = m.height;
  r.height = m.width;
  r.baseline = m.width / 2;  // no baseline once upright text is turned
  r.alpha.assign(m.alpha.size(), 0);
  // Source (x, y) goes to (y, width - 1 - x).
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      r.alpha[std::size_t(m.width - 1 - x) * r.width + y] = m.at(x, y);
    }
  }
  return r;
}

Rect draw_mask(Image& img, const TextMask& m, int x, int y, HAlign h, VAlign v,
               Rgba colour) {
  const int left = h == HAlign::Left ? x : h == HAlign::Centre ? x - m.width / 2 : x - m.width;
  const int top = v == VAlign::Top        ? y
                  : v == VAlign::Middle   ? y - m.height / 2
                  : v == VAlign::Baseline ? y - m.baseline
                                          : y - m.height;
  for (int yy = 0; yy < m.height; ++yy) {
    for (int xx = 0; xx < m.width; ++xx) {
      img.blend(left + xx, top + yy, colour, m.at(xx, yy));
    }
  }
  return Rect{left, top, m.width, m.height};
}

Rect Font::draw(Image& img, const std::string& utf8, int pixel_size, int x, int y,
                HAlign h, VAlign v, Rgba colour) {
  return draw_mask(img, render(utf8, pixel_size), x, y, h, v, colour);
}

std::vector<std::string> wrap_text(Font& font, const std::string& text, int px, int width) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string word, line;
  while (words >> word) {
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && font.text_width(longer, px) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

int widest_word(Font& font, const std::string& text, int px) {
  std::istringstream words(text);
  std::string word;
  int widest = 0;
  while (words >> word) widest = std::max(widest, font.text_width(word, px));
  return widest;
}

}  // namespace render
