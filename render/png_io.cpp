#include "render/png_io.hpp"

#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include "render/error.hpp"

namespace render {

namespace {

// libpng reports errors by longjmp; the message is parked here and turned
// into an exception once we are back in ordinary C++ frames.
struct PngErr {
  char message[256] = {0};
};

void on_error(png_structp png, png_const_charp msg) {
  auto* e = static_cast<PngErr*>(png_get_error_ptr(png));
  std::snprintf(e->message, sizeof e->message, "%s", msg ? msg : "libpng error");
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

// Only trivially destructible locals live across setjmp here; row pointers
// are built by the caller before the call.
bool write_stream(FILE* fp, const Image& img, png_bytep* rows, int level, PngErr* err) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, err, on_error, on_warning);
  if (!png) {
    std::snprintf(err->message, sizeof err->message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, fp);
  png_set_compression_level(png, level);
  // One fixed filter: offering libpng several makes it try each on every
  // row, which doubled the write time of a 1280x720 frame for ~1% smaller
  // files. UP suits frames of vertical-ish structure and flat colour.
  png_set_filter(png, 0, PNG_FILTER_UP);
  png_set_IHDR(png, info, png_uint_32(img.width()), png_uint_32(img.height()), 8,
               PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

// pixels and rows belong to the caller: objects modified after setjmp must
// not be locals of this frame, or their state is indeterminate after a jump.
bool read_stream(FILE* fp, std::vector<std::uint8_t>* pixels, std::vector<png_bytep>* rows,
                 int* w, int* h, PngErr* err) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, err, on_error, on_warning);
  if (!png) {
    std::snprintf(err->message, sizeof err->message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, fp);
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  if (width == 0 || height == 0 || width > 16384 || height > 16384) {
    png_error(png, "image size outside 1..16384");
  }
  // Normalise everything to 8-bit RGBA.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xFF, PNG_FILLER_AFTER);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != std::size_t(width) * 4) {
    png_error(png, "unexpected row size after conversion to RGBA8");
  }
  pixels->resize(std::size_t(width) * height * 4);
  rows->resize(height);
  for (png_uint_32 y = 0; y < height; ++y) {
    (*rows)[y] = pixels->data() + std::size_t(y) * width * 4;
  }
  png_read_image(png, rows->data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  *w = int(width);
  *h = int(height);
  return true;
}

std::string errno_text() { return std::strerror(errno); }

}  // namespace

void write_png(const Image& img, const std::string& path, const PngOptions& opt) {
  if (img.empty()) throw FileError(path, "refusing to write an empty image");
  if (opt.compression < 0 || opt.compression > 9) {
    throw InvalidArgument("PNG compression level " + std::to_string(opt.compression) +
                          " is outside 0..9");
  }
  std::vector<png_bytep> rows(std::size_t(img.height()));
  for (int y = 0; y < img.height(); ++y) rows[y] = const_cast<png_bytep>(img.row(y));

  // mkstemp gives a unique name, so concurrent writers never share a temp.
  std::string tmp = path + ".tmp-XXXXXX";
  std::vector<char> tmpl(tmp.begin(), tmp.end());
  tmpl.push_back('\0');
  const int fd = mkstemp(tmpl.data());
  if (fd < 0) throw FileError(path, "cannot create temporary file: " + errno_text());
  tmp = tmpl.data();
  fchmod(fd, 0644);  // mkstemp creates 0600; frames are meant to be shared
  FILE* fp = fdopen(fd, "wb");
  if (!fp) {
    const std::string why = errno_text();
    close(fd);
    unlink(tmp.c_str());
    throw FileError(path, "fdopen failed: " + why);
  }
  PngErr err;
  const bool ok = write_stream(fp, img, rows.data(), opt.compression, &err);
  const bool flushed = std::fflush(fp) == 0;
  const std::string flush_why = flushed ? "" : errno_text();
  const bool closed = std::fclose(fp) == 0;
  if (!ok || !flushed || !closed) {
    unlink(tmp.c_str());
    throw FileError(path, !ok ? std::string("libpng: ") + err.message
                              : "write failed: " + (flushed ? errno_text() : flush_why));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = errno_text();
    unlink(tmp.c_str());
    throw FileError(path, "cannot rename temporary file into place: " + why);
  }
}

namespace {

// The file open at its start, once its first 8 bytes are PNG's signature;
// the caller closes it. Throws FileError naming the path otherwise.
FILE* open_png(const std::string& path) {
  FILE* fp = std::fopen(path.c_str(), "rb");
  if (!fp) throw FileError(path, "cannot open PNG: " + errno_text());
  unsigned char sig[8] = {0};
  const std::size_t got = std::fread(sig, 1, 8, fp);
  if (got != 8 || png_sig_cmp(sig, 0, 8) != 0) {
    std::fclose(fp);
    throw FileError(path, "not a PNG file (bad signature)");
  }
  std::rewind(fp);
  return fp;
}

}  // namespace

Image read_png(const std::string& path) {
  FILE* fp = open_png(path);
  std::vector<std::uint8_t> pixels;
  std::vector<png_bytep> rows;
  int w = 0, h = 0;
  PngErr err;
  const bool ok = read_stream(fp, &pixels, &rows, &w, &h, &err);
  std::fclose(fp);
  if (!ok) throw FileError(path, std::string("corrupt PNG: ") + err.message);
  Image img(w, h);
  std::memcpy(img.data(), pixels.data(), pixels.size());
  return img;
}

PngSize png_size(const std::string& path) {
  FILE* fp = open_png(path);
  unsigned char head[24] = {0};  // signature, IHDR length and type, width, height
  const std::size_t got = std::fread(head, 1, sizeof head, fp);
  std::fclose(fp);
  if (got != sizeof head || std::memcmp(head + 12, "IHDR", 4) != 0)
    throw FileError(path, "corrupt PNG: no IHDR chunk first");
  auto big_endian = [&](int at) {
    return int(png_uint_32(head[at]) << 24 | png_uint_32(head[at + 1]) << 16 |
               png_uint_32(head[at + 2]) << 8 | png_uint_32(head[at + 3]));
  };
  return {big_endian(16), big_endian(20)};
}

}  // namespace render
