// Pieces of the scenario reader that live in their own file.
#pragma once

#include <string>
#include <vector>

#include "sim/scene/memory_budget.hpp"
#include "sim/scene/scenario.hpp"
#include "sim/scene/scenario_json.hpp"

namespace sim {

// `s` holds everything read before the stages (grid, materials).
std::vector<StageSpec> parse_stages(const scenario_json::Node& node, const Scenario& s);
// A random field in place of material m's `property` (scenario_fields.cpp).
RandomFieldSpec parse_random_field(const scenario_json::Node& value, const std::string& property,
                                   const MaterialSpec& m, const Scenario& s);
// The index of the material `name` names; fails listing the defined ones.
int material_index(const scenario_json::Node& name, const std::vector<MaterialSpec>& materials);
OutputSpec parse_output(const scenario_json::Node& node, const std::vector<StageSpec>& stages);

// Limits checked before anything is allocated: a scene asks for at most
// kMaxPoints points and kMaxGridNodes grid nodes (memory_budget.hpp).
constexpr double kMaxFrames = 100000;  // per stage
void check_memory_budget_of_grid(const scenario_json::Node& root, const Scenario& s);
void check_memory_budget_of_points(const scenario_json::Node& root, const Scenario& s);

}  // namespace sim
