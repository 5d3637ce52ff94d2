#include "app/gallery_monte_carlo.hpp"

#include <filesystem>
#include <iostream>

#include "app/sweep_command.hpp"
#include "output/exit_status.hpp"

namespace app {

namespace fs = std::filesystem;

int gallery_monte_carlo(const GalleryOptions& o) {
  const fs::path scenarios = o.scenarios.empty() ? fs::path("scenarios") : fs::path(o.scenarios);
  const fs::path out(o.out);
  const fs::path dir = out / ".sweeps" / "monte-carlo-phi20-n1661";
  sweep::SweepOptions s;
  s.file = (scenarios / "sweeps" / "monte-carlo-phi20-n1661.json").string();
  s.out_dir = dir.string();
  s.paint = {0};  // one sample's soil, painted
  std::cout << "gallery: the Monte Carlo sweep " << s.file << '\n';
  const int status = sweep_command(s);
  if (status != kExitOk) return status;
  const auto keep = [&](const fs::path& from, const std::string& name) {
    fs::copy_file(from, out / name, fs::copy_options::overwrite_existing);
    std::cout << "figure: " << (out / name).string() << '\n';
  };
  keep(dir / "sweep-exceedance.png", "monte-carlo-exceedance-phi20.png");
  keep(dir / "members/0000/frames/friction-angle/000000.png",
       "monte-carlo-friction-angle-sample0.png");
  keep(dir / "sweep.csv", "monte-carlo-phi20-n1661.csv");
  fs::remove_all(out / ".sweeps");
  return kExitOk;
}

}  // namespace app
