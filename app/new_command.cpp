#include "app/new_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "landslide_templates.hpp"
#include "output/exit_status.hpp"
#include "sim/io/atomic_file.hpp"

namespace app {

namespace {

namespace fs = std::filesystem;

// The first sentence of a template's description: its line in --list.
std::string summary(const char* text) {
  const std::string description = nlohmann::json::parse(text).at("description");
  const std::size_t end = description.find(". ");
  return end == std::string::npos ? description : description.substr(0, end + 1);
}

std::string template_names() {
  std::string names;
  for (const EmbeddedTemplate& t : kTemplates) names += (names.empty() ? "" : ", ") + std::string(t.name);
  return names;
}

const EmbeddedTemplate* find_template(const std::string& name) {
  for (const EmbeddedTemplate& t : kTemplates)
    if (name == t.name) return &t;
  return nullptr;
}

}  // namespace

CLI::App* add_new_command(CLI::App& cli, NewOptions& o) {
  CLI::App* cmd = cli.add_subcommand(
      "new", "Write a documented starting scene from a template (--list names them)");
  cmd->add_option("template", o.template_name, "Template name (see --list)");
  cmd->add_option("out", o.out, "Scenario JSON file to write");
  cmd->add_flag("--list", o.list, "List the templates, one line each, and exit");
  cmd->add_flag("--overwrite", o.overwrite, "Replace OUT if it exists (without it OUT is refused)");
  return cmd;
}

int new_command(const NewOptions& o) {
  if (o.list) {
    if (!o.template_name.empty()) {
      std::cerr << "error: new --list takes no TEMPLATE or OUT (got \"" << o.template_name
                << "\")\n";
      return kExitBadInput;
    }
    std::size_t width = 0;
    for (const EmbeddedTemplate& t : kTemplates) width = std::max(width, std::string(t.name).size());
    for (const EmbeddedTemplate& t : kTemplates)
      std::cout << t.name << std::string(width + 2 - std::string(t.name).size(), ' ')
                << summary(t.text) << "\n";
    return kExitOk;
  }
  if (o.template_name.empty() || o.out.empty()) {
    std::cerr << "error: new needs TEMPLATE and OUT.json, e.g. `landslide new slope my-slope.json` "
                 "(templates: " << template_names() << "; `landslide new --list` says what each is)\n";
    return kExitBadInput;
  }
  const EmbeddedTemplate* t = find_template(o.template_name);
  if (!t) {
    std::cerr << "error: new: template = \"" << o.template_name << "\": expected one of "
              << template_names() << " (`landslide new --list` says what each is)\n";
    return kExitBadInput;
  }
  std::error_code ec;
  const fs::file_status status = fs::status(o.out, ec);
  if (fs::is_directory(status)) {
    std::cerr << "error: " << o.out << ": is a directory (expected the scenario file to write)\n";
    return kExitBadInput;
  }
  if (fs::exists(status) && !o.overwrite) {
    std::cerr << "error: " << o.out << ": already exists; choose another name, or add --overwrite "
                 "to replace it\n";
    return kExitBadInput;
  }
  try {
    sim::write_file_atomically(o.out, [&](std::ostream& out) { out << t->text; });
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitBadInput;
  }
  std::cout << "wrote " << o.out << " from template " << t->name << "; next: landslide check "
            << o.out << ", then landslide run " << o.out << " --out DIR\n";
  return kExitOk;
}

}  // namespace app
