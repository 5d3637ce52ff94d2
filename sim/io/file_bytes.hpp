// A whole file read into memory in one call, for every reader of this
// program's own files: saved states, checkpoints, spilled frames (output/)
// and VTK point states (vtk.cpp).
#pragma once

#include <filesystem>
#include <string>

namespace sim {

// The whole of `file`, in `buffer`'s memory where it is large enough; throws
// StateError (sim/io/binary_io.hpp) with `missing` if it cannot be opened,
// and naming the bytes it got if the read falls short.
std::string read_file_bytes(const std::filesystem::path& file, const std::string& missing,
                            std::string buffer = {});

}  // namespace sim
