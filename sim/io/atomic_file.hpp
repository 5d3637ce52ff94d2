// Every output file is written under a temporary name in its final directory
// and renamed into place, so no reader (or a crash) ever sees half a file.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace sim {

// Calls write(stream) on a temporary file beside `path`, then renames it to
// `path`. Throws std::runtime_error naming the file on any I/O failure; the
// temporary file is removed then.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace sim
