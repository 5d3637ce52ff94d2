#pragma once
// Text through FreeType: a Font owns its FT_Library and FT_Face (no global
// state) and caches rendered glyphs per pixel size.
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "render/image.hpp"

namespace render {

// /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf (Debian fonts-dejavu-core).
std::string default_font_path();

// 8-bit coverage mask of a line of text. The mask's box encloses every
// glyph's ink and the font's ascender..descender, so nothing draws outside.
struct TextMask {
  int width = 0, height = 0;
  int baseline = 0;  // rows from the top of the mask to the baseline
  std::vector<std::uint8_t> alpha;
  std::uint8_t at(int x, int y) const { return alpha[std::size_t(y) * width + x]; }
};

// Rows of the mask with at least half coverage somewhere: the ink's height
// (what a reader sees as the text's size).
int ink_height(const TextMask& m);

// Quarter turn counter-clockwise: text then reads bottom to top (y labels).
TextMask rotate_ccw(const TextMask& m);

enum class HAlign { Left, Centre, Right };
enum class VAlign { Top, Middle, Baseline, Bottom };

// Blends colour through the mask with its anchor point at (x, y); returns
// the mask's rectangle in the image (possibly partly outside it).
Rect draw_mask(Image& img, const TextMask& m, int x, int y, HAlign h, VAlign v,
               Rgba colour);

class Font {
 public:
  // Throws FontError naming the path if the file is missing or unreadable
  // (hint: install fonts-dejavu-core).
  explicit Font(const std::string& path = default_font_path());
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  const std::string& path() const { return path_; }

  // UTF-8 text at a pixel size (em height) of 4..512. Throws FontError on
  // bad UTF-8 or sizes.
  TextMask render(const std::string& utf8, int pixel_size);
  // Width/height of render(...) without building the mask.
  int text_width(const std::string& utf8, int pixel_size);
  int line_height(int pixel_size);

  // render + draw_mask.
  Rect draw(Image& img, const std::string& utf8, int pixel_size, int x, int y,
            HAlign h, VAlign v, Rgba colour = kBlack);

 private:
  struct Glyph {
    int left = 0, top = 0, width = 0, height = 0;
    int advance = 0;  // 26.6 fixed point
    unsigned index = 0;
    std::vector<std::uint8_t> bitmap;
  };
  struct Layout;
  const Glyph& glyph(char32_t code, int pixel_size);
  void set_size(int pixel_size);
  Layout layout(const std::string& utf8, int pixel_size);

  struct FtState;
  std::unique_ptr<FtState> ft_;
  std::string path_;
  int current_size_ = 0;
  std::unordered_map<std::uint64_t, Glyph> cache_;
};

// Words of `text` in lines no wider than `width` px at `px` (a word wider
// than the line gets a line of its own).
std::vector<std::string> wrap_text(Font& font, const std::string& text, int px, int width);
// Width of the widest word of `text` at `px`: the narrowest line wrap_text
// can keep every word inside.
int widest_word(Font& font, const std::string& text, int px);

// Decodes UTF-8; throws FontError on malformed input.
std::u32string decode_utf8(const std::string& s);

}  // namespace render
