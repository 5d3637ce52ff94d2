// sweep::WholeLines: a message written in pieces, with flushes between them
// as std::cerr makes after every <<, reaches the sink as one line, so that
// ranks sharing a terminal cannot cut into each other's lines.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "sweep/whole_lines.hpp"

namespace {

TEST(WholeLines, PiecesAndFlushesOfALineReachTheSinkAsOneLine) {
  std::ostringstream stream;
  stream.setf(std::ios::unitbuf);  // as std::cerr: a flush after every <<
  std::vector<std::string> lines;
  {
    sweep::WholeLines whole(stream, [&](const std::string& line) { lines.push_back(line); });
    stream << "sweep: member " << 1 << " of " << 3 << " on rank " << 1 << '\n';
    stream << "a" << std::flush << 'b' << "c\nd" << std::endl;
    stream << "no end";
    EXPECT_EQ(lines, (std::vector<std::string>{"sweep: member 1 of 3 on rank 1\n", "abc\n", "d\n"}));
  }
  // The last line without its '\n' goes out when the WholeLines ends, and
  // the stream writes to its own buffer again.
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines.back(), "no end");
  stream << "after";
  EXPECT_EQ(stream.str(), "after");
}

TEST(WholeLines, TheStreamKeepsWhatItHeldBefore) {
  std::ostringstream stream;
  stream << "before ";
  std::vector<std::string> lines;
  {
    sweep::WholeLines whole(stream, [&](const std::string& line) { lines.push_back(line); });
    stream << "during\n";
  }
  EXPECT_EQ(stream.str(), "before ");
  EXPECT_EQ(lines, std::vector<std::string>{"during\n"});
}

}  // namespace
