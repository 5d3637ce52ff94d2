#include "sim/io/vtk.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/io/atomic_file.hpp"
#include "sim/io/file_bytes.hpp"

namespace sim {

namespace {

// A number as `out << v` writes it at precision 17 (printf's %.17g, which
// std::to_chars reproduces for the general format), without the stream:
// formatting through std::ostream took about 20 s for the 976 MB of a
// 4 M-point state (issue 17).
void append_number(std::string& text, double v) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17).ptr;
  text.append(buf, end);
}

// Points per piece of text formatted by one thread, and pieces per batch:
// memory holds a batch's text, not the file's.
constexpr std::size_t kPointsPerPiece = 16384;
constexpr std::size_t kPiecesPerBatch = 16;

// One <DataArray> of n tuples; value(p, c) gives component c of point p. The
// points' lines are formatted piece by piece on the OpenMP threads and
// written in order: the same bytes at any thread count.
template <class Value>
void data_array(std::ostream& out, const char* type, const char* name, int components,
                std::size_t n, Value value) {
  out << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\""
      << components << "\" format=\"ascii\">\n";
  const long pieces = static_cast<long>((n + kPointsPerPiece - 1) / kPointsPerPiece);
  std::vector<std::string> text(kPiecesPerBatch);
  for (long first = 0; first < pieces; first += long(kPiecesPerBatch)) {
    const long last = std::min(pieces, first + long(kPiecesPerBatch));
#pragma omp parallel for schedule(dynamic, 1) if (last - first > 1)
    for (long k = first; k < last; ++k) {
      std::string& t = text[std::size_t(k - first)];
      t.clear();
      const std::size_t end = std::min(n, std::size_t(k + 1) * kPointsPerPiece);
      for (std::size_t p = std::size_t(k) * kPointsPerPiece; p < end; ++p)
        for (int c = 0; c < components; ++c) {
          append_number(t, value(p, c));
          t += c + 1 < components ? ' ' : '\n';
        }
    }
    for (long k = first; k < last; ++k) out << text[std::size_t(k - first)];
  }
  out << "</DataArray>\n";
}

}  // namespace

void write_vtu(const std::string& path, const World& w, double time) {
  const Particles& p = w.points;
  const std::size_t n = p.size();
  write_file_atomically(path, [&](std::ostream& out) {
    out.precision(17);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "<UnstructuredGrid>\n<FieldData>\n"
           "<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">"
        << time << "</DataArray>\n</FieldData>\n"
        << "<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n<Points>\n";
    data_array(out, "Float64", "Points", 3, n,
               [&](std::size_t i, int c) { return c == 0 ? p.x[i] : c == 1 ? p.y[i] : 0.0; });
    out << "</Points>\n<Cells>\n";
    data_array(out, "Int64", "connectivity", 1, n, [](std::size_t i, int) { return double(i); });
    data_array(out, "Int64", "offsets", 1, n, [](std::size_t i, int) { return double(i + 1); });
    data_array(out, "UInt8", "types", 1, n, [](std::size_t, int) { return 1.0; });  // VTK_VERTEX
    out << "</Cells>\n<PointData>\n";
    data_array(out, "Float64", "displacement", 3, n, [&](std::size_t i, int c) {
      return c == 0 ? p.x[i] - p.x0[i] : c == 1 ? p.y[i] - p.y0[i] : 0.0;
    });
    data_array(out, "Float64", "velocity", 3, n,
               [&](std::size_t i, int c) { return c == 0 ? p.vx[i] : c == 1 ? p.vy[i] : 0.0; });
    data_array(out, "Float64", "stress", 4, n, [&](std::size_t i, int c) {
      return c == 0 ? p.sxx[i] : c == 1 ? p.syy[i] : c == 2 ? p.sxy[i] : p.szz[i];
    });
    data_array(out, "Float64", "density", 1, n, [&](std::size_t i, int) { return p.density[i]; });
    data_array(out, "Float64", "volume", 1, n,
               [&](std::size_t i, int) { return p.volume(i); });
    data_array(out, "Int32", "material", 1, n, [&](std::size_t i, int) { return p.material[i]; });
    data_array(out, "UInt8", "yielded", 1, n, [&](std::size_t i, int) { return p.yielded[i]; });
    if (w.strength.active()) {  // a random field's strength, point by point
      data_array(out, "Float64", "cohesion", 1, n,
                 [&](std::size_t i, int) { return w.strength.cohesion[i]; });
      data_array(out, "Float64", "friction_angle", 1, n,
                 [&](std::size_t i, int) { return w.strength.friction_angle[i]; });
    }
    out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  });
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& files) {
  write_file_atomically(path, [&](std::ostream& out) {
    out.precision(17);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto& [t, file] : files)
      out << "<DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << file << "\"/>\n";
    out << "</Collection>\n</VTKFile>\n";
  });
}

namespace {

// The numbers in [c, stop), appended to `values`; false at a word that is
// not one. std::from_chars reads back exactly what append_number wrote (and
// a leading '+', which strtod, its predecessor here, took too).
bool parse_numbers(const char* c, const char* stop, std::vector<double>& values) {
  while (c < stop) {
    if (std::isspace(static_cast<unsigned char>(*c))) {
      ++c;
      continue;
    }
    if (*c == '+') ++c;
    double v = 0;
    const auto [next, ec] = std::from_chars(c, stop, v);
    if (ec != std::errc() || next == c) return false;
    values.push_back(v);
    c = next;
  }
  return true;
}

// The numbers of the DataArray named `name`; expects `count` of them. The
// text is cut at line ends into pieces parsed on the OpenMP threads and
// joined in order: reading a 4 M-point state with strtod on one thread took
// most of `landslide render`'s 12 s (issue 17).
std::vector<double> read_array(const std::string& text, const std::string& file,
                               const std::string& name, std::size_t count) {
  const std::size_t at = text.find("Name=\"" + name + "\"");
  if (at == std::string::npos) throw std::runtime_error(file + ": no DataArray '" + name + "'");
  const std::size_t begin = text.find('>', at);
  const std::size_t end = text.find("</DataArray>", at);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    throw std::runtime_error(file + ": DataArray '" + name + "' is not closed");
  constexpr std::size_t kPieceBytes = std::size_t(1) << 20;
  std::vector<std::size_t> cuts{begin + 1};
  while (end - cuts.back() > kPieceBytes) {
    const std::size_t line_end = text.find('\n', cuts.back() + kPieceBytes);
    if (line_end >= end) break;
    cuts.push_back(line_end + 1);
  }
  cuts.push_back(end);
  const long pieces = static_cast<long>(cuts.size()) - 1;
  std::vector<std::vector<double>> parts(static_cast<std::size_t>(pieces));
  std::vector<char> good(parts.size(), 0);
#pragma omp parallel for schedule(dynamic, 1) if (pieces > 1)
  for (long k = 0; k < pieces; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    parts[i].reserve((cuts[i + 1] - cuts[i]) / 8);
    good[i] = parse_numbers(text.data() + cuts[i], text.data() + cuts[i + 1], parts[i]);
  }
  if (std::find(good.begin(), good.end(), 0) != good.end())
    throw std::runtime_error(file + ": DataArray '" + name + "' holds a non-number");
  std::vector<double> values;
  values.reserve(count);
  for (const std::vector<double>& part : parts)
    values.insert(values.end(), part.begin(), part.end());
  if (values.size() != count)
    throw std::runtime_error(file + ": DataArray '" + name + "' has " +
                             std::to_string(values.size()) + " values, expected " +
                             std::to_string(count));
  return values;
}

}  // namespace

PointState read_vtu(const std::string& path) {
  const std::string text = read_file_bytes(path, path + ": cannot read");
  const std::size_t at = text.find("NumberOfPoints=\"");
  if (at == std::string::npos) throw std::runtime_error(path + ": not a .vtu point file");
  const std::size_t n = std::strtoull(text.c_str() + at + 16, nullptr, 10);
  PointState s;
  s.time = read_array(text, path, "TimeValue", 1)[0];
  auto split = [&](const std::string& name, int comps, std::vector<std::vector<double>*> out) {
    const std::vector<double> v = read_array(text, path, name, n * comps);
    for (std::size_t k = 0; k < out.size(); ++k) {
      out[k]->resize(n);
      for (std::size_t i = 0; i < n; ++i) (*out[k])[i] = v[i * comps + k];
    }
  };
  split("Points", 3, {&s.x, &s.y});
  split("displacement", 3, {&s.ux, &s.uy});
  split("velocity", 3, {&s.vx, &s.vy});
  split("stress", 4, {&s.sxx, &s.syy, &s.sxy, &s.szz});
  split("density", 1, {&s.density});
  split("volume", 1, {&s.volume});
  for (const double v : read_array(text, path, "material", n)) s.material.push_back(int(v));
  for (const double v : read_array(text, path, "yielded", n)) s.yielded.push_back(int(v));
  if (text.find("Name=\"cohesion\"") != std::string::npos) {
    split("cohesion", 1, {&s.cohesion});
    split("friction_angle", 1, {&s.friction_angle});
  }
  return s;
}

}  // namespace sim
