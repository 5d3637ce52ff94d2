// A CRC-32 after the bytes of every file a run reads back (checkpoint,
// cached gravity state, spilled frame), so a file damaged on disk or cut
// short is refused by name instead of being read as some other state.
//
// zlib's crc32_z (Debian's zlib1g, which libpng already pulls in): a
// maintained, fast implementation, and CRC-32 finds every single flipped
// byte and every burst up to 32 bits, which a hand-written hash would have
// to be shown to do.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "sim/io/binary_io.hpp"

namespace app {

// Appends the CRC-32 of w's bytes so far.
void append_checksum(sim::BinaryWriter& w);

// Checks that the last 4 bytes of `bytes` are the CRC-32 of those before
// them, then removes them. Throws sim::StateError naming `file` if not.
void strip_checksum(std::string& bytes, const std::filesystem::path& file);

// Writes w's bytes to `file` under a temporary name, then renames it.
void write_bytes_atomically(const std::filesystem::path& file, const sim::BinaryWriter& w);

}  // namespace app
