#pragma once
// Lossless RGBA8 PNG files through libpng.
#include <string>

#include "render/image.hpp"

namespace render {

struct PngOptions {
  // zlib level 0..9. 3 keeps frames small while staying fast; frames are
  // mostly flat colour so higher levels buy little.
  int compression = 3;
};

// Writes to a temporary file in the same directory, then renames it over
// `path`, so no reader ever sees a half-written file under the final name.
// Throws FileError naming the path (the temporary is removed on failure).
void write_png(const Image& img, const std::string& path, const PngOptions& opt = {});

// Reads any PNG (grey, palette, 16-bit, interlaced ...) as RGBA8.
// Throws FileError naming the path if it is missing, not a PNG or corrupt.
Image read_png(const std::string& path);

// Width and height from the PNG's header alone (the IHDR chunk, which the
// format puts first). Throws FileError as read_png does.
struct PngSize {
  int width = 0, height = 0;
};
PngSize png_size(const std::string& path);

}  // namespace render
