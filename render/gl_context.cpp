#include "render/gl_context.hpp"

#include <GL/osmesa.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cstdio>
#include <cstring>

#include "render/error.hpp"

static_assert(sizeof(OSMesaContext) == sizeof(osmesa_context*),
              "OSMesaContext is expected to be a pointer to osmesa_context");

namespace render {

namespace {
void check_size(int width, int height) {
  // GL_MAX_VIEWPORT_DIMS of llvmpipe is 16384.
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    throw InvalidArgument("off-screen buffer size " + std::to_string(width) + "x" +
                          std::to_string(height) + " is outside 1..16384");
  }
}
}  // namespace

OffscreenContext::OffscreenContext(int width, int height) {
  check_size(width, height);
  // No depth buffer: points are painted in order, later ones on top.
  ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (!ctx_) {
    throw GlError("OSMesaCreateContextExt(OSMESA_RGBA) failed: is libOSMesa "
                  "(package libosmesa6) installed and working?");
  }
  try {
    resize(width, height);
  } catch (...) {
    OSMesaDestroyContext(ctx_);
    throw;
  }
}

OffscreenContext::~OffscreenContext() {
  if (!ctx_) return;
  // Unbind first so the thread is never left with a dangling current context.
  if (OSMesaGetCurrentContext() == ctx_) {
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }
  OSMesaDestroyContext(ctx_);
}

void OffscreenContext::make_current() {
  if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
    throw GlError("OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
                  std::to_string(height_) + " buffer");
  }
}

void OffscreenContext::resize(int width, int height) {
  check_size(width, height);
  if (width != width_ || height != height_ || buffer_.empty()) {
    buffer_.assign(std::size_t(width) * std::size_t(height) * 4, 0);
    width_ = width;
    height_ = height;
  }
  make_current();
}

void OffscreenContext::read_into(Image& out) {
  if (out.width() != width_ || out.height() != height_) out = Image(width_, height_);
  make_current();
  // OSMesa (gallium) copies its render target into our buffer on finish.
  glFinish();
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR) {
    char msg[64];
    std::snprintf(msg, sizeof msg, "OpenGL error 0x%04x while drawing", unsigned(err));
    throw GlError(msg);
  }
  const std::size_t stride = std::size_t(width_) * 4;
  for (int y = 0; y < height_; ++y) {
    const std::uint8_t* src = buffer_.data() + std::size_t(height_ - 1 - y) * stride;
    std::memcpy(out.row(y), src, stride);
  }
}

Image OffscreenContext::read_image() {
  Image out(width_, height_);
  read_into(out);
  return out;
}

std::string OffscreenContext::renderer() {
  make_current();
  const GLubyte* s = glGetString(GL_RENDERER);
  return s ? reinterpret_cast<const char*>(s) : "unknown";
}

std::string OffscreenContext::version() {
  make_current();
  const GLubyte* s = glGetString(GL_VERSION);
  return s ? reinterpret_cast<const char*>(s) : "unknown";
}

bool keep_freed_heap_memory() {
#if defined(__GLIBC__)
  // Setting any threshold turns glibc's adaptive thresholds off, so set
  // both: keep up to 256 MiB of free heap, and serve blocks below 32 MiB
  // (whole frames included) from the heap rather than fresh mmaps.
  const bool trim = mallopt(M_TRIM_THRESHOLD, 256 << 20) == 1;
  const bool mmap = mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1;
  return trim && mmap;
#else
  return false;
#endif
}

}  // namespace render
