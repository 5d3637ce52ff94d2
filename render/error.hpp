#pragma once
// Every failure in the renderer is one of these exceptions; nothing logs and
// carries on. Messages name the file or the value that was wrong.
#include <stdexcept>
#include <string>

namespace render {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A caller handed us a value we cannot draw (bad size, empty range, ...).
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

// Reading or writing a file failed; path() is the file concerned.
class FileError : public Error {
 public:
  FileError(const std::string& path, const std::string& what)
      : Error(path + ": " + what), path_(path) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// OSMesa / OpenGL could not create a context or draw.
class GlError : public Error {
 public:
  using Error::Error;
};

// FreeType could not load the font or a glyph.
class FontError : public Error {
 public:
  using Error::Error;
};

// ffmpeg is missing or exited with an error.
class VideoError : public Error {
 public:
  using Error::Error;
};

}  // namespace render
