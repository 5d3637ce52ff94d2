#include "landslide_version.hpp"
#include "output/summary.hpp"

#include <cmath>

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

nlohmann::json energy_json(const sim::EnergyBalance& e) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, value] : energy_terms(e)) out[name] = value;
  return out;
}

nlohmann::json metrics_json(const sim::StageMetrics& m) {
  nlohmann::json materials = nlohmann::json::array();
  for (const sim::MaterialMotion& mm : m.materials)
    materials.push_back({{"material", mm.material},
                         {"mean_ux_m", mm.mean_ux},
                         {"mean_uy_m", mm.mean_uy},
                         {"max_displacement_m", mm.max_displacement}});
  nlohmann::json slope = nullptr;  // JSON has no NaN
  if (std::isfinite(m.deposit_slope_deg)) slope = m.deposit_slope_deg;
  return {{"max_soil_horizontal_displacement_m", m.max_soil_ux},
          {"initial_toe_x_m", m.initial_toe},
          {"toe_x_m", m.toe},
          {"runout_m", m.runout},
          {"main_body_fraction", m.main_body_fraction},
          {"packed_fraction", m.packed_fraction},
          {"disconnected_fraction", m.disconnected_fraction},
          {"yielding_fraction", m.yielding_fraction},
          {"deposit_slope_deg", slope},
          {"materials", materials}};
}

}  // namespace

std::vector<std::pair<std::string, double>> energy_terms(const sim::EnergyBalance& e) {
  return {{"external_work_J_per_m", e.external_work},
          {"kinetic_energy_change_J_per_m", e.kinetic_change},
          {"internal_work_J_per_m", e.internal_work},
          {"elastic_energy_change_J_per_m", e.elastic_energy_change},
          {"plastic_dissipation_J_per_m", e.plastic_dissipation},
          {"damping_loss_J_per_m", e.damping_loss},
          {"wall_loss_J_per_m", e.wall_loss},
          {"friction_work_J_per_m", e.friction_work},
          {"transfer_loss_J_per_m", e.transfer_loss},
          {"relative_error", e.relative_error}};
}

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
    if (r.type != sim::StageType::MaterialChange) {
      stages.back()["energy"] = energy_json(r.energy);
      stages.back()["metrics"] = metrics_json(r.metrics);
    }
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
