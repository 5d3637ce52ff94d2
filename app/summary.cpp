#include "app/summary.hpp"

namespace app {

namespace {

const char* stage_type_name(sim::StageType t) {
  switch (t) {
    case sim::StageType::Gravity: return "gravity";
    case sim::StageType::MaterialChange: return "material-change";
    case sim::StageType::Dynamic: return "dynamic";
  }
  return "?";
}

}  // namespace

nlohmann::json make_summary(const sim::Simulation& simulation, int threads, double wall_time,
                            const std::string& status) {
  const sim::Scenario& s = simulation.scenario();
  nlohmann::json stages = nlohmann::json::array();
  for (const sim::StageResult& r : simulation.results()) {
    stages.push_back({{"name", r.name},
                      {"type", stage_type_name(r.type)},
                      {"simulated_time_s", r.simulated_time},
                      {"wall_time_s", r.wall_time},
                      {"steps", r.steps},
                      {"ended_at_rest", r.ended_at_rest},
                      {"kinetic_energy_J_per_m", r.kinetic_energy},
                      {"moving_kinetic_energy_J_per_m", r.moving_kinetic_energy},
                      {"gravity_work_J_per_m", r.gravity_work}});
  }
  return {{"scenario", s.name},
          {"scenario_file", s.source_path},
          {"version", LANDSLIDE_VERSION},
          {"status", status},
          {"points", simulation.world().points.size()},
          {"cell_size_m", s.cell_size},
          {"threads", threads},
          {"simulated_time_s", simulation.time()},
          {"wall_time_s", wall_time},
          {"stages", stages}};
}

}  // namespace app
