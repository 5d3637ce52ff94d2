// `landslide gallery`, declared apart from the command line (app/) so that
// app/ only parses the options.
#pragma once

#include <string>

namespace app {

// `landslide gallery`: the paper's figures 5, 6, 9, 10, 11, 12 (PNG), an
// animation of the phi = 20 slide and one of the four friction angles side by
// side, regenerated from the committed phi = 20 scene and, for Figures 11
// and 12, the members of scenarios/sweeps/fig11-resolutions.json and
// fig12-friction-angles.json.
struct GalleryOptions {
  std::string out;        // directory
  std::string scenarios;  // "" : ./scenarios
  bool quick = false;     // every run at h = 1.127 m (1661 points)
};
int gallery_command(const GalleryOptions& options);

}  // namespace app
