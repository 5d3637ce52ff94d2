// glibc picks exp, log, sin and the rest by processor: variants with FMA
// and AVX2, or without, which may round some arguments differently in the
// last bit. The step no longer calls one whose result reaches the points
// (the density update's exp is sim/physics/exp_lanes.hpp; the materials'
// sin and cos, taken once, are libm's and agree here), so the same binary
// gives the same bits whichever variant glibc takes. GLIBC_TUNABLES
// makes a child take the variants of a processor without FMA and AVX2; with
// std::exp in the step, e0407aa's binary gave the 1661-point slope a runout
// of 16.137817597509645 m that way and 16.137817597509247 m without.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "run_binary.hpp"

namespace {

namespace fs = std::filesystem;

// series.csv of the slope's run into `dir`/out (its numbers at every frame
// time), with GLIBC_TUNABLES set to `tunables` for the child.
std::string series_of_run(const fs::path& dir, const std::string& tunables) {
  fs::create_directories(dir);
  if (tunables.empty())
    ::unsetenv("GLIBC_TUNABLES");
  else
    ::setenv("GLIBC_TUNABLES", tunables.c_str(), 1);
  const apptest::Result r = apptest::landslide(
      "run '" LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20-n1661.json' --out out --threads 1",
      dir);
  ::unsetenv("GLIBC_TUNABLES");
  EXPECT_EQ(r.status, 0) << r.output;
  return apptest::read_text(dir / "out" / "series.csv");
}

TEST(LibmVariants, TheSlopeGivesTheSameBitsWithOrWithoutFmaVariants) {
  const fs::path root = fs::temp_directory_path() / ("landslide-libm-" + std::to_string(::getpid()));
  fs::remove_all(root);
  const std::string usual = series_of_run(root / "usual", "");
  const std::string without = series_of_run(root / "without", "glibc.cpu.hwcaps=-FMA,-AVX2");
  ASSERT_GT(usual.size(), 1000u);
  EXPECT_EQ(usual, without) << "the run's numbers depend on the libm variant glibc picks";
  fs::remove_all(root);
}

}  // namespace
