// One captured frame on disk: what FrameRecorder spills while a run goes on,
// so that memory holds one frame however many are captured. Raw float32 as
// in memory, with a header that refuses a file of another build or kind.
#pragma once

#include <filesystem>

#include "output/frames.hpp"

namespace app {

// Written under a temporary name and renamed: a kill leaves the whole file
// or none. Throws std::runtime_error naming the file on an I/O failure. The
// bytes are put together in `buffer`'s memory, handed back for the next
// frame.
std::string write_frame_file(const std::filesystem::path& file, const Frame& frame,
                             std::string buffer);
// Into `into`, through `buffer`: both keep their memory from one frame to
// the next. Throws sim::StateError naming the file if it is missing,
// truncated or not a frame file.
void read_frame_file(const std::filesystem::path& file, Frame& into, std::string& buffer);

}  // namespace app
