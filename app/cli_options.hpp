// Options that several subcommands take, declared once.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace app {

// --threads: the OpenMP threads of a run, 1 to 1024; `help` says whose.
inline CLI::Option* add_threads_option(CLI::App& cmd, int& threads, const std::string& help) {
  return cmd.add_option("--threads", threads, help)->check(CLI::Range(1, 1024));
}

}  // namespace app
