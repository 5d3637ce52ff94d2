// A stream's output held until each line is whole, then written at once.
//
// Under mpirun every rank's stderr goes to one terminal. std::cerr is
// unbuffered and flushes after every <<, so a message of several pieces was
// several writes, and another rank's line could land inside it (a fresh
// clone's Sweep.OneAndTwoRanksWriteTheSameCsv once read "sweep: member
// 1estimate: ..."). While a WholeLines lives, its stream's text goes to the
// sink a line at a time, each line (with its '\n') in one call; flushes
// before the line's end keep it. A multi-rank sweep holds one on std::cerr
// and one on std::cout (sweep.cpp).
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace sweep {

class WholeLines {
 public:
  using Sink = std::function<void(const std::string& line)>;
  // Each line in one write(2) to file descriptor fd.
  WholeLines(std::ostream& stream, int fd);
  WholeLines(std::ostream& stream, Sink sink);
  // Writes what is left of a last line without its '\n', and gives the
  // stream its own buffer back.
  ~WholeLines();
  WholeLines(const WholeLines&) = delete;
  WholeLines& operator=(const WholeLines&) = delete;

 private:
  class Buffer;
  std::ostream& stream_;
  std::unique_ptr<Buffer> buffer_;
  std::streambuf* own_;
};

}  // namespace sweep
