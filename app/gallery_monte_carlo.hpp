// The gallery's Monte Carlo figures (issue 16), made after the paper's figures
// by `landslide gallery` (not with --quick): the shipped sweep
// scenarios/sweeps/monte-carlo-phi20-n1661.json runs as `landslide sweep`
// would into OUT/.sweeps/monte-carlo-phi20-n1661 (a killed gallery resumes
// it), and three of its outputs are kept in OUT:
//   monte-carlo-exceedance-phi20.png       P(runout > L) with its 95 % band
//   monte-carlo-friction-angle-sample0.png sample 0's friction angle, point by
//                                          point, at the start of the slide
//   monte-carlo-phi20-n1661.csv            the sweep's sweep.csv
#pragma once

#include "gallery/src/gallery.hpp"

namespace app {

// The exit status of the sweep (output/exit_status.hpp).
int gallery_monte_carlo(const GalleryOptions& options);

}  // namespace app
