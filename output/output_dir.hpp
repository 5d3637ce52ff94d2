// The folders a run writes into: --out and --state-cache must be folders (or
// not exist yet, under a writable folder), and a fresh run never mixes its
// outputs with an earlier run's: it refuses a folder that holds them unless
// --overwrite, which removes them first (README.md, "Output folders").
#pragma once

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace app {

// A one-line refusal of a path given on the command line.
class PathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws PathError ("FLAG PATH: ...") if `dir` is a file, lies under a file,
// or cannot be written (nor created).
void check_writable_dir(const std::filesystem::path& dir, const std::string& flag);

// What an earlier run left in `out` that this program writes: summary.json,
// checkpoint.lsck, series.csv, series.png, vtk/, frames/, FIELD.mp4,
// FIELD.gif, .frames-pending/, .gif-frames/ (those present, sorted).
std::vector<std::filesystem::path> earlier_outputs(const std::filesystem::path& out);

// Throws PathError naming what it found if `out` holds an earlier run's outputs.
void refuse_earlier_outputs(const std::filesystem::path& out);

// Removes the files called NNNNNN<ext> in `dir` (an earlier run's frames),
// but those numbered in `keep`.
void remove_numbered(const std::filesystem::path& dir, const std::string& ext,
                     const std::set<int>& keep = {});

// Removes them: the files and folders above, but only the numbered PNGs in
// frames/FIELD/ (frames/ and its folders go once empty; other files stay).
void remove_earlier_outputs(const std::filesystem::path& out);

// Whether `dir` (of validate or gallery: --scenarios if `given`, else
// ./scenarios) is a folder; if not, says so on stderr with a hint at
// --scenarios.
bool scenarios_folder_found(const std::string& dir, bool given, const std::string& command);

}  // namespace app
