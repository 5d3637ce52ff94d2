// The solver's stable region, measured: a matrix of stressed scenes, one row
// each, saying whether the run finished, ended at rest, or was stopped
// cleanly (and why), its energy balance error, the largest point speed, and
// whether any point was lost or any value went non-finite. Prints figures;
// never fails on timing. bench/README.md records the latest table.
//
// Usage: stability [--quick]   (--quick: a few rows, for a smoke check)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "sim/run/simulation.hpp"
#include "sim/run/watchdog.hpp"

namespace {

const std::string kSlope = LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20-n1661.json";

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The trigger of the paper slopes sets the friction angle; the dilation angle
// may not exceed it at any moment, so it changes first.
void set_friction(sim::Scenario& s, double degrees) {
  for (sim::StageSpec& st : s.stages)
    for (sim::MaterialChange& c : st.changes)
      if (c.property == "friction_angle") {
        c.value = degrees * M_PI / 180;
        sim::MaterialChange psi = c;
        psi.property = "dilation_angle";
        psi.value = std::min(10.0, degrees) * M_PI / 180;
        st.changes.insert(st.changes.begin(), psi);  // lowered before the friction angle
        return;
      }
}

sim::MaterialSpec& soil(sim::Scenario& s) {
  for (sim::MaterialSpec& m : s.materials)
    if (m.name == "soil") return m;
  return s.materials.front();
}

// An elastic block of 4 m x 2 m dropped from 5 m onto the fixed base.
sim::Scenario dropped_block(bool plastic) {
  sim::Scenario s = sim::load_scenario(kSlope);
  s.name = plastic ? "dropped Mohr-Coulomb block" : "dropped elastic block";
  s.domain_min = {0, 0};
  s.domain_max = {20, 12};
  s.cell_size = 0.25;
  s.bodies.resize(1);
  s.bodies[0].polygon = {{8, 5}, {12, 5}, {12, 7}, {8, 7}};
  s.bodies[0].material = int(&soil(s) - &s.materials[0]);
  soil(s).cohesion = plastic ? 0 : 1e9;  // 1 GPa: never yields
  soil(s).friction_angle = 30 * M_PI / 180;
  sim::StageSpec fall;
  fall.name = "slide";
  fall.type = sim::StageType::Dynamic;
  fall.duration = 4;
  s.stages = {fall};
  return s;
}

struct Row {
  std::string label;
  std::function<sim::Scenario()> make;  // throws ScenarioError to be "refused"
};

// Samples the largest point speed every few steps.
class Watch : public sim::Observer {
 public:
  double max_speed = 0;
  void progress(const sim::Simulation& s, const sim::StageSpec&, long steps) override {
    if (steps % 10 != 0) return;
    const sim::Particles& p = s.world().points;
    for (std::size_t i = 0; i < p.size(); ++i)
      max_speed = std::max(max_speed, std::hypot(p.vx[i], p.vy[i]));
  }
};

// Points outside the domain's walls at the end (above a free top, say). No
// point is ever removed: one about to leave the grid stops the run instead.
int points_outside(const sim::Simulation& s) {
  const sim::Scenario& sc = s.scenario();
  const sim::Particles& p = s.world().points;
  int lost = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    lost += !(p.x[i] >= sc.domain_min[0] && p.x[i] <= sc.domain_max[0] &&
              p.y[i] >= sc.domain_min[1] && p.y[i] <= sc.domain_max[1]);
  return lost;
}

void run_row(const Row& row) {
  const auto start = std::chrono::steady_clock::now();
  sim::Scenario s;
  try {
    s = row.make();
  } catch (const sim::ScenarioError& e) {
    std::printf("%-34s refused by the loader: %s\n", row.label.c_str(), e.what());
    return;
  }
  s.output.frame_interval = 0;
  sim::Simulation simulation(s);
  Watch watch;
  std::string status;
  try {
    simulation.run(watch);
    const sim::StageResult& last = simulation.results().back();
    status = last.ended_at_rest ? "at rest" : "finished";
  } catch (const sim::WatchdogError& e) {
    status = std::string("STOPPED: ") + e.what();
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The energy error of the last stage, if the run finished it.
  const bool finished = simulation.stage_index() == s.stages.size();
  const double error = finished ? simulation.results().back().energy.relative_error : NAN;
  long steps = 0;  // of the finished stages
  for (const sim::StageResult& r : simulation.results()) steps += r.steps;
  const std::string bad = sim::find_bad_point(simulation.world());
  const bool non_finite = bad.find("non-finite") != std::string::npos;
  std::printf("%-34s %7zu %8ld %8.1f %10.3f %9.2f %5d %4s %7.1f  %s\n", row.label.c_str(),
              simulation.world().points.size(), steps, simulation.time(), error, watch.max_speed,
              points_outside(simulation), non_finite ? "yes" : "no", wall, status.c_str());
  std::fflush(stdout);
}

std::vector<Row> rows(bool quick) {
  const auto slope = [] { return sim::load_scenario(kSlope); };
  std::vector<Row> r;
  for (double c : {0.1, 0.25, 0.5})
    r.push_back({"Courant " + std::to_string(c).substr(0, 4), [=] {
                   sim::Scenario s = slope();
                   s.time_step.courant = c;
                   return s;
                 }});
  r.push_back({"Courant 0.6 (beyond the bound)", [] {
                 std::string t = read_text(kSlope);
                 const std::string from = "\"courant\": 0.5";
                 t.replace(t.find(from), from.size(), "\"courant\": 0.6");
                 return sim::parse_scenario(t, kSlope);
               }});
  r.push_back({"fixed dt 1.2x the bound", [=] {
                 sim::Scenario s = slope();
                 // At rest, the fastest P wave (the house's).
                 const double signal = sim::max_signal_speed(sim::Simulation(s).world());
                 s.time_step.mode = sim::TimeStepSpec::Mode::Fixed;
                 s.time_step.fixed_dt = 1.2 * 0.5 * s.cell_size / signal;
                 return s;
               }});
  if (quick) return r;
  for (double phi : {45.0, 30.0, 20.0, 10.0, 5.0, 2.0})
    r.push_back({"friction " + std::to_string(int(phi)) + " deg", [=] {
                   sim::Scenario s = slope();
                   set_friction(s, phi);
                   return s;
                 }});
  for (double nu : {0.0, 0.3, 0.45, 0.49})
    r.push_back({"Poisson " + std::to_string(nu).substr(0, 4), [=] {
                   sim::Scenario s = slope();
                   for (sim::MaterialSpec& m : s.materials) m.poisson_ratio = nu;
                   return s;
                 }});
  for (double e : {2e5, 2e6, 2e7, 2e8, 2e9}) {
    char label[64];
    std::snprintf(label, sizeof label, "Young %.0e Pa, 5 s slide", e);
    r.push_back({label, [=] {
                   sim::Scenario s = slope();
                   for (sim::MaterialSpec& m : s.materials) m.youngs_modulus = e;
                   s.stages.back().duration = 5;
                   return s;
                 }});
  }
  r.push_back({"100 s of slide, no rest test", [=] {
                 sim::Scenario s = slope();
                 s.stages.back().duration = 100;
                 s.stages.back().rest.enabled = false;
                 return s;
               }});
  r.push_back({"dropped elastic block", [] { return dropped_block(false); }});
  r.push_back({"dropped Mohr-Coulomb block", [] { return dropped_block(true); }});
  for (double top : {20.0, 40.0})
    r.push_back({"phi 10 into a wall at 70 m, top " + std::to_string(int(top)), [=] {
                   sim::Scenario s = slope();
                   set_friction(s, 10);
                   s.domain_max = {70, top};
                   return s;
                 }});
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::printf("stability matrix: the paper slope at 1661 points (h = 1.127 m) unless named, "
              "%d threads\n",
              omp_get_max_threads());
  std::printf("%-34s %7s %8s %8s %10s %9s %5s %4s %7s  %s\n", "case", "points", "steps",
              "t [s]", "energy err", "max |v|", "out", "NaN", "wall s", "outcome");
  const auto start = std::chrono::steady_clock::now();
  for (const Row& row : rows(quick)) run_row(row);
  std::printf("total %.0f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return 0;
}
