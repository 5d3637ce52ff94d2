// `landslide new TEMPLATE OUT.json`: a documented starting scene written from
// one of the templates compiled into the binary (scenarios/templates/), and
// `landslide new --list`, one line per template.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace app {

struct NewOptions {
  std::string template_name;
  std::string out;
  bool list = false;
  bool overwrite = false;  // replace an existing OUT (without it OUT is refused)
};

// Adds the subcommand and its options to `cli`, filling `options` when parsed.
CLI::App* add_new_command(CLI::App& cli, NewOptions& options);

int new_command(const NewOptions& options);

}  // namespace app
