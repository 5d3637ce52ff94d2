#include "output/output_dir.hpp"

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <regex>

#include "output/checkpoint.hpp"
#include "output/frames.hpp"

namespace app {

namespace fs = std::filesystem;

void check_writable_dir(const fs::path& dir, const std::string& flag) {
  const std::string name = flag + " " + dir.string();
  std::error_code ec;
  // The nearest part of the path that exists must be a folder we may write
  // into: the run creates the rest.
  fs::path existing = dir;
  while (!existing.empty() && !fs::exists(existing, ec)) existing = existing.parent_path();
  if (existing.empty()) existing = ".";
  if (!fs::is_directory(existing, ec))
    throw PathError(name + ": " +
                    (existing == dir ? "is a file" : existing.string() + " is a file") +
                    ": expected a folder (created if missing)");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw PathError(name + ": " + (existing == dir ? "" : existing.string() + " ") +
                    "is not writable: expected a folder this user may write into");
}

std::vector<fs::path> earlier_outputs(const fs::path& out) {
  std::vector<fs::path> found;
  std::error_code ec;
  if (!fs::is_directory(out, ec)) return found;
  std::vector<fs::path> known = {"summary.json", checkpoint_path("").filename(), "series.csv",
                                 "series.png",   "vtk",  "frames", ".frames-pending",
                                 ".gif-frames"};
  for (const std::string& f : field_names()) {
    known.push_back(f + ".mp4");
    known.push_back(f + ".gif");
  }
  for (const fs::path& k : known)
    if (fs::exists(out / k, ec)) found.push_back(k);
  std::sort(found.begin(), found.end());
  return found;
}

void refuse_earlier_outputs(const fs::path& out) {
  const std::vector<fs::path> found = earlier_outputs(out);
  if (found.empty()) return;
  std::string names;
  for (const fs::path& f : found) names += (names.empty() ? "" : ", ") + f.string();
  throw PathError("--out " + out.string() + ": holds an earlier run's outputs (" + names +
                  "): expected a new or empty folder, or --overwrite to remove them first");
}

void remove_numbered(const fs::path& dir, const std::string& ext, const std::set<int>& keep) {
  if (!fs::is_directory(dir)) return;
  const std::regex numbered_file(R"((\d{6}))" + std::regex_replace(ext, std::regex(R"(\.)"), R"(\.)"));
  std::smatch m;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && std::regex_match(name, m, numbered_file) &&
        !keep.count(std::stoi(m[1].str())))
      fs::remove(e.path());
  }
}

void remove_earlier_outputs(const fs::path& out) {
  for (const fs::path& f : earlier_outputs(out)) {
    if (f != "frames") {
      fs::remove_all(out / f);
      continue;
    }
    // Frames of a field this run does not paint go too; notes beside them stay.
    for (const fs::directory_entry& e : fs::directory_iterator(out / f)) {
      if (!e.is_directory()) continue;
      remove_numbered(e.path(), ".png");
      if (fs::is_empty(e.path())) fs::remove(e.path());
    }
    if (fs::is_empty(out / f)) fs::remove(out / f);
  }
}

bool scenarios_folder_found(const std::string& dir, bool given, const std::string& command) {
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec)) return true;
  std::cerr << "error: " << dir << ": no such folder; " << command
            << (given ? " reads its scenarios from the folder --scenarios names"
                      : " reads its scenarios from ./scenarios, so run it in the repository's "
                        "top folder or give --scenarios DIR (the repository's scenarios/)")
            << '\n';
  return false;
}

}  // namespace app
