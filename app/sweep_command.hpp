// `landslide sweep SWEEP.json --out DIR`: the command line of sweep/sweep.hpp,
// whose members run as `landslide run` runs a scene.
#pragma once

#include "sweep/sweep.hpp"

namespace CLI {
class App;
}

namespace app {

// Adds the subcommand and its options to `cli`, filling `options` when parsed.
CLI::App* add_sweep_command(CLI::App& cli, sweep::SweepOptions& options);

int sweep_command(const sweep::SweepOptions& options);

}  // namespace app
