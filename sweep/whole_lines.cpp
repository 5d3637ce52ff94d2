#include "sweep/whole_lines.hpp"

#include <unistd.h>

#include <cerrno>
#include <streambuf>
#include <utility>

namespace sweep {

// Collects characters and hands each finished line to the sink. sync() (a
// flush) sends nothing: std::cerr's flush after every << would otherwise
// write the pieces one by one again.
class WholeLines::Buffer : public std::streambuf {
 public:
  explicit Buffer(Sink sink) : sink_(std::move(sink)) {}
  void send_rest() {
    if (line_.empty()) return;
    sink_(line_);
    line_.clear();
  }

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    line_.push_back(traits_type::to_char_type(c));
    if (traits_type::to_char_type(c) == '\n') send_rest();
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i) overflow(traits_type::to_int_type(s[i]));
    return n;
  }
  int sync() override { return 0; }

 private:
  Sink sink_;
  std::string line_;
};

namespace {

// All of `text` to fd, through short writes and interrupted calls. A failing
// stderr has nowhere to report to, so a write error drops the line.
void write_all(int fd, const std::string& text) {
  const char* at = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, at, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    at += n;
    left -= static_cast<std::size_t>(n);
  }
}

}  // namespace

WholeLines::WholeLines(std::ostream& stream, int fd)
    : WholeLines(stream, [fd](const std::string& line) { write_all(fd, line); }) {}

WholeLines::WholeLines(std::ostream& stream, Sink sink)
    : stream_(stream), buffer_(std::make_unique<Buffer>(std::move(sink))) {
  stream_.flush();  // what the stream held before goes out first, in order
  own_ = stream_.rdbuf(buffer_.get());
}

WholeLines::~WholeLines() {
  buffer_->send_rest();
  stream_.rdbuf(own_);
}

}  // namespace sweep
