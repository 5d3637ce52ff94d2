#include "sim/io/file_bytes.hpp"

#include <fstream>

#include "sim/io/binary_io.hpp"

namespace sim {

// Sized from the file and read in one call: a stream copied into a string
// stream grew its buffer by doubling and then copied it out, three copies of
// a 48 MB frame of 4 M points, each into freshly faulted pages (issue 17,
// twenty-third pass, bench/README.md).
std::string read_file_bytes(const std::filesystem::path& file, const std::string& missing,
                            std::string buffer) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) throw StateError(missing);
  const std::streamoff size = in.tellg();
  if (size < 0) throw StateError(missing);
  std::string bytes = std::move(buffer);
  bytes.resize(static_cast<std::size_t>(size));  // fills only past its old size
  in.seekg(0);
  if (!in.read(bytes.data(), size))
    throw StateError(file.string() + ": read " + std::to_string(in.gcount()) + " of " +
                     std::to_string(size) + " bytes");
  return bytes;
}

}  // namespace sim
