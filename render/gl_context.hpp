#pragma once
// An OSMesa off-screen OpenGL context and the buffer it draws into.
// One object, one context: no process-wide state, so several painters can
// live side by side (each makes itself current before drawing).
#include <cstdint>
#include <string>
#include <vector>

#include "render/image.hpp"

struct osmesa_context;  // OSMesaContext without dragging GL headers in

namespace render {

class OffscreenContext {
 public:
  // Throws GlError if OSMesa cannot create or bind the context.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

  // Binds this context to the calling thread; call before issuing GL.
  void make_current();
  // Reallocates the colour buffer (no-op when the size is unchanged) and
  // binds it.
  void resize(int width, int height);
  // Finishes pending GL work and returns the buffer flipped so row 0 is the
  // top (OSMesa stores the bottom row first).
  Image read_image();
  // Copies into an existing image of the right size (no allocation).
  void read_into(Image& out);

  // GL_RENDERER / GL_VERSION strings, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer();
  std::string version();

 private:
  osmesa_context* ctx_ = nullptr;
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> buffer_;
};

// llvmpipe allocates and frees tens of MB of bin data in every draw. With
// glibc's defaults the freed heap top goes back to the kernel after each
// frame and the next frame page-faults it all in again, which made a 67k
// point splat take ~90 ms instead of ~7 ms on our (virtualised) machines.
// This raises glibc's trim and mmap thresholds so that memory stays in the
// process. It is a process-wide allocator setting, applied once (idempotent);
// Painter calls it unless told not to. Returns false where unsupported.
bool keep_freed_heap_memory();

}  // namespace render
