#include "output/series.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "output/series_plot.hpp"
#include "output/summary.hpp"
#include "render/png_io.hpp"
#include "sim/io/atomic_file.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

constexpr double kEventSlack = 1e-9;  // as the time loop's: a row due "now" is not missed

std::string number(double v) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  return std::string(buf, end);
}

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// The records of a CSV text, each a list of fields, with their first lines.
struct Record {
  int line = 0;
  std::vector<std::string> fields;
};

std::vector<Record> split_csv(const std::string& text, const std::string& label) {
  std::vector<Record> records;
  Record r{1, {std::string()}};
  int line = 1;
  bool in_quotes = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        r.fields.back() += text[++i];
      } else if (c == '"') {
        in_quotes = false;
      } else {
        r.fields.back() += c;
        line += c == '\n';
      }
    } else if (c == '"' && r.fields.back().empty()) {
      in_quotes = true;
    } else if (c == ',') {
      r.fields.emplace_back();
    } else if (c == '\n') {
      records.push_back(std::move(r));
      r = Record{++line, {std::string()}};
    } else if (c != '\r') {
      r.fields.back() += c;
    }
  }
  if (in_quotes) throw SeriesError(label + ": line " + std::to_string(r.line) + ": a quote is not closed");
  if (r.fields.size() > 1 || !r.fields[0].empty()) records.push_back(std::move(r));
  return records;
}

double parse_number(const Record& r, std::size_t k, const std::string& label) {
  const std::string& f = r.fields[k];
  double v = 0;
  const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || end != f.data() + f.size() || f.empty())
    throw SeriesError(label + ": line " + std::to_string(r.line) + ", " + series_columns()[k] +
                      " = '" + f + "': expected a number");
  return v;
}

std::string header() {
  std::string h;
  for (const std::string& c : series_columns()) h += (h.empty() ? "" : ",") + c;
  return h;
}

}  // namespace

const std::vector<std::string>& series_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> c = {"time_s",        "stage",
                                  "stage_time_s",  "steps",
                                  "kinetic_energy_J_per_m", "moving_kinetic_energy_J_per_m",
                                  "front_x_m",     "runout_m",
                                  "max_soil_ux_m", "max_displacement_m"};
    for (const auto& term : energy_terms(sim::EnergyBalance{})) c.push_back(term.first);
    return c;
  }();
  return columns;
}

double series_interval(const sim::Scenario& scenario, const sim::StageSpec& stage) {
  const double every = scenario.output.frame_interval;
  return every > 0 ? every : stage.duration / 100;
}

SeriesRow series_row(const sim::Simulation& sim, const sim::StageResult& r,
                     const sim::StageMotion& m) {
  double max_u = 0;
  for (const sim::MaterialMotion& mm : m.materials) max_u = std::max(max_u, mm.max_displacement);
  SeriesRow row{sim.time(), r.name,
                {r.simulated_time, double(r.steps), r.kinetic_energy, r.moving_kinetic_energy,
                 m.toe, m.runout, m.max_soil_ux, max_u}};
  for (const auto& term : energy_terms(r.energy)) row.values.push_back(term.second);
  return row;
}

std::string series_csv(const std::vector<SeriesRow>& rows) {
  std::string out = header() + '\n';
  for (const SeriesRow& row : rows) {
    out += number(row.time) + ',' + quoted(row.stage);
    for (const double v : row.values) out += ',' + number(v);
    out += '\n';
  }
  return out;
}

std::vector<SeriesRow> parse_series(const std::string& text, const std::string& label) {
  const std::vector<Record> records = split_csv(text, label);
  if (records.empty() || records[0].fields != series_columns())
    throw SeriesError(label + ": line 1: expected the header " + header());
  const std::size_t n = series_columns().size();
  std::vector<SeriesRow> rows;
  for (std::size_t i = 1; i < records.size(); ++i) {
    const Record& r = records[i];
    if (r.fields.size() != n)
      throw SeriesError(label + ": line " + std::to_string(r.line) + ": " +
                        std::to_string(r.fields.size()) + " fields, expected " +
                        std::to_string(n));
    SeriesRow row{parse_number(r, 0, label), r.fields[1], {}};
    for (std::size_t k = 2; k < n; ++k) row.values.push_back(parse_number(r, k, label));
    if (!rows.empty() && !(row.time >= rows.back().time))
      throw SeriesError(label + ": line " + std::to_string(r.line) + ": time_s = " +
                        r.fields[0] + " s comes after " + number(rows.back().time) + " s");
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<SeriesRow> read_series(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SeriesError(file.string() + ": cannot read (written by landslide run)");
  std::ostringstream text;
  text << in.rdbuf();
  std::vector<SeriesRow> rows = parse_series(text.str(), file.string());
  if (rows.empty()) throw SeriesError(file.string() + ": holds no rows");
  return rows;
}

SeriesRecorder::SeriesRecorder(const sim::Scenario& scenario, fs::path out_dir)
    : scenario_(scenario), out_(std::move(out_dir)), font_(std::make_unique<render::Font>()) {}

void SeriesRecorder::add(SeriesRow row) {
  // The end of a stage at a frame time: the same state, written once.
  if (!rows_.empty() && rows_.back().stage == row.stage && rows_.back().time == row.time)
    rows_.back() = std::move(row);
  else
    rows_.push_back(std::move(row));
}

// A stage started afresh (not resumed within it, where next_row_ > 0).
void SeriesRecorder::stage_begins(const sim::Simulation& sim, const sim::StageSpec& stage) {
  if (stage.type == sim::StageType::MaterialChange || sim::stage_is_painted(scenario_, stage) ||
      next_row_ > 0)
    return;
  add(series_row(sim, sim.stage_so_far(), sim::measure_motion(sim.world())));
  next_row_ = 1;
}

void SeriesRecorder::frame(const sim::Simulation& sim) {
  add(series_row(sim, sim.stage_so_far(), sim::measure_motion(sim.world())));
}

void SeriesRecorder::progress(const sim::Simulation& sim, const sim::StageSpec& stage) {
  if (sim::stage_is_painted(scenario_, stage)) return;
  const double every = series_interval(scenario_, stage);
  if (sim.stage_time() < next_row_ * every * (1 - kEventSlack)) return;
  add(series_row(sim, sim.stage_so_far(), sim::measure_motion(sim.world())));
  next_row_ = long(std::floor(sim.stage_time() / every + kEventSlack)) + 1;
}

void SeriesRecorder::stage_ends(const sim::Simulation& sim, const sim::StageSpec& stage,
                                const sim::StageResult& r) {
  if (stage.type == sim::StageType::MaterialChange) return;
  add(series_row(sim, r, r.metrics));
  next_row_ = 0;
  write();
}

nlohmann::json SeriesRecorder::bookkeeping() const {
  return {{"csv", csv()}, {"next_row", next_row_}};
}

void SeriesRecorder::resume(const nlohmann::json& b) {
  rows_ = parse_series(b.at("csv").get<std::string>(), "the checkpoint's series.csv");
  next_row_ = b.at("next_row").get<long>();
}

void SeriesRecorder::restore(std::vector<SeriesRow> rows) { rows_ = std::move(rows); }

void SeriesRecorder::write() {
  if (rows_.empty()) return;
  sim::write_file_atomically((out_ / "series.csv").string(),
                             [&](std::ostream& o) { o << csv(); });
  const render::Image plot =
      series_plot(*font_, rows_, kSeriesPngWidth, kSeriesPngHeight, scenario_.name, {});
  render::write_png(plot, (out_ / "series.png").string());
}

}  // namespace app
