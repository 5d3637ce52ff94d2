// The VTK state files (sim/io/vtk.hpp): formatted in pieces on the OpenMP
// threads, they hold the same bytes at any thread count, and read back to
// the points' values bit for bit (17 significant digits round-trip); a
// damaged file is refused with the array named.
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sim/io/vtk.hpp"
#include "sim/scene/seed.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// About 53,000 points (four pieces of 16,384) with values that use all 17
// digits, negative ones and zeros among them.
sim::World busy_world() {
  sim::World w = sim::make_world(
      simtest::block_scenario({0.0, 0.0}, {0.3, 0.1}, 0.0015, 2, {0, 0}, {1, 0.2}));
  sim::Particles& p = w.points;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double t = 0.37 * double(i);
    p.x[i] += 1e-3 * std::sin(t);
    p.vx[i] = std::sin(1.3 * t) / 3;
    p.vy[i] = i % 5 == 0 ? 0.0 : -std::cos(0.7 * t) * 1e-9;
    p.sxx[i] = -1e3 * (1 + std::sin(t)) / 7;
    p.sxy[i] = i % 7 == 0 ? -0.0 : 300 * std::sin(2.1 * t);
    p.yielded[i] = i % 3 == 0;
  }
  return w;
}

TEST(Vtk, SameBytesAtAnyThreadCountAndReadBackBitForBit) {
  const fs::path dir =
      fs::temp_directory_path() / ("landslide-vtk-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const sim::World w = busy_world();
  ASSERT_GT(w.points.size(), 2u * 16384u);
  omp_set_num_threads(1);
  sim::write_vtu((dir / "one.vtu").string(), w, 0.1);
  omp_set_num_threads(3);
  sim::write_vtu((dir / "three.vtu").string(), w, 0.1);
  omp_set_num_threads(1);
  EXPECT_EQ(read_text(dir / "one.vtu"), read_text(dir / "three.vtu"));

  const sim::PointState s = sim::read_vtu((dir / "three.vtu").string());
  const sim::Particles& p = w.points;
  ASSERT_EQ(s.x.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(s.x[i], p.x[i]) << i;
    ASSERT_EQ(s.vx[i], p.vx[i]) << i;
    ASSERT_EQ(s.vy[i], p.vy[i]) << i;
    ASSERT_EQ(s.sxx[i], p.sxx[i]) << i;
    ASSERT_EQ(std::signbit(s.sxy[i]), std::signbit(p.sxy[i])) << i;
    ASSERT_EQ(s.sxy[i], p.sxy[i]) << i;
    ASSERT_EQ(s.yielded[i], p.yielded[i]) << i;
  }

  // A word that is not a number, deep in a many-piece array, and a missing
  // value: read_vtu names the array.
  std::string text = read_text(dir / "one.vtu");
  const std::size_t stress = text.find("Name=\"stress\"");
  const std::size_t deep = text.find('\n', stress + 2 * (std::size_t(1) << 20)) + 1;
  ASSERT_LT(deep, text.find("</DataArray>", stress)) << "the array spans several pieces";
  std::string bad = text;
  bad[deep] = 'x';
  std::ofstream(dir / "bad.vtu", std::ios::binary) << bad;
  EXPECT_THROW(
      {
        try {
          sim::read_vtu((dir / "bad.vtu").string());
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("DataArray 'stress' holds a non-number"),
                    std::string::npos) << e.what();
          throw;
        }
      },
      std::runtime_error);
  bad = text;
  bad.erase(deep, bad.find('\n', deep) - deep + 1);  // one point's line of four
  std::ofstream(dir / "short.vtu", std::ios::binary) << bad;
  try {
    sim::read_vtu((dir / "short.vtu").string());
    ADD_FAILURE() << "a missing line was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("DataArray 'stress' has"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
