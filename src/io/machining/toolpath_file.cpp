#include "io/machining/toolpath_file.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/json_fields.hpp"
#include "io/part_file.hpp"
#include "base/text_fields.hpp"

namespace furrow {

std::size_t Toolpath::point_count() const {
  std::size_t n = 0;
  for (const auto& p : passes) n += p.points.size();
  return n;
}

std::size_t Toolpath::move_count() const {
  std::size_t n = 0;
  for (const auto& p : passes) n += p.points.size() - 1;
  return n;
}

namespace {

[[noreturn]] void fail_line(const std::string& name, int line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  // A byte-order mark (as Excel and some CAM packages write) is not content.
  std::istringstream in(strip_bom(text));
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

}  // namespace

// ---------------------------------------------------------------- CSV

Toolpath parse_toolpath_csv(const std::string& text, const std::string& name,
                            const ToolpathReadOptions& options) {
  Toolpath path;
  path.source = name;
  const double scale = units_to_mm(options.units, name + ": units");
  const std::vector<std::string> lines = split_lines(text);
  std::map<std::string, int> column;  // name -> index, from the header
  int columns = -1;
  int pass_column = -1;
  double last_pass = 0;  // a whole number; kept as read (see the pass column below)
  ToolpathPass current;
  auto close_pass = [&](int line) {
    if (current.points.size() == 1)
      fail_line(name, line, "a pass needs at least 2 points");
    if (current.points.size() >= 2) path.passes.push_back(std::move(current));
    current = ToolpathPass{};
  };
  char separator = 0;  // from the first line with content
  long points = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const int number = static_cast<int>(k) + 1;
    std::string line = lines[k];
    const auto hash = line.find('#');
    if (hash != std::string::npos) line = line.substr(0, hash);
    if (!separator && line.find_first_not_of(" \t") != std::string::npos) separator = csv_separator(line);
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, separator ? separator : ',')) {
      field.erase(0, field.find_first_not_of(" \t"));
      field.erase(field.find_last_not_of(" \t") + 1);
      fields.push_back(field);
    }
    const bool blank = std::all_of(fields.begin(), fields.end(), [](const std::string& f) { return f.empty(); });
    if (blank) {
      if (pass_column < 0 && !current.points.empty()) close_pass(number);
      continue;
    }
    double probe = 0;
    if (columns < 0 && !parse_finite(fields[0], probe)) {
      // Header line.
      for (std::size_t c = 0; c < fields.size(); ++c) {
        std::string key = fields[c];
        std::transform(key.begin(), key.end(), key.begin(), [](unsigned char ch) { return std::tolower(ch); });
        if (column.count(key)) fail_line(name, number, "column " + quote_field(key) + " appears twice");
        column[key] = static_cast<int>(c);
      }
      for (const char* needed : {"x", "y", "z"})
        if (!column.count(needed)) fail_line(name, number, std::string("the header has no \"") + needed + "\" column");
      const int normals = static_cast<int>(column.count("nx") + column.count("ny") + column.count("nz"));
      if (normals != 0 && normals != 3) fail_line(name, number, "give all of nx, ny, nz or none");
      if (column.count("u") != column.count("v")) fail_line(name, number, "give both u and v columns or neither");
      if (column.count("face") && !column.count("u"))
        fail_line(name, number, "a face column needs u and v columns");
      // Not a structured binding: C++17 does not let a lambda capture one
      // (GCC accepts it, clang rejects it; the sanitizer build uses clang).
      for (const auto& entry : column) {
        const std::string& key = entry.first;
        static const char* const kKnown[] = {"x", "y", "z", "nx", "ny", "nz", "pass", "u", "v", "face"};
        if (std::find_if(std::begin(kKnown), std::end(kKnown), [&](const char* k) { return key == k; }) ==
            std::end(kKnown))
          fail_line(name, number, "unknown column " + quote_field(key) + " (known: x y z nx ny nz pass u v face)");
      }
      path.kind = normals == 3 ? ToolpathKind::contact_points : ToolpathKind::tool_tips;
      if (column.count("pass")) pass_column = column["pass"];
      columns = static_cast<int>(fields.size());
      continue;
    }
    if (columns < 0) {
      // No header: 3 columns are tips, 6 contact points with normals.
      if (fields.size() != 3 && fields.size() != 6)
        fail_line(name, number, "expected 3 columns (x,y,z) or 6 (x,y,z,nx,ny,nz), found " +
                                    std::to_string(fields.size()));
      columns = static_cast<int>(fields.size());
      const char* names[] = {"x", "y", "z", "nx", "ny", "nz"};
      for (int c = 0; c < columns; ++c) column[names[c]] = c;
      path.kind = columns == 6 ? ToolpathKind::contact_points : ToolpathKind::tool_tips;
    }
    if (static_cast<int>(fields.size()) != columns)
      fail_line(name, number, "expected " + std::to_string(columns) + " columns, found " +
                                  std::to_string(fields.size()));
    auto value = [&](const char* key) {
      double x = 0;
      const std::string& f = fields[column.at(key)];
      if (!parse_finite(f, x)) fail_line(name, number, std::string(key) + " " + quote_field(f) + " is not a finite number");
      return x;
    };
    if (pass_column >= 0) {
      double pv = 0;
      // Whole numbers up to 1e15 (exact in a double); beyond that a "pass
      // number" is no count of passes. Kept as read, never converted: 1e300
      // converted to an integer type was undefined behaviour (UBSan in
      // fuzz_toolpath_csv, docs/testing.md). Only the order matters.
      if (!parse_finite(fields[pass_column], pv) || pv != std::floor(pv) || std::abs(pv) > 1e15)
        fail_line(name, number, "pass " + quote_field(fields[pass_column]) + " is not a whole number up to 1e15");
      const double pass = pv;
      if (!current.points.empty() && pass != last_pass) {
        if (pass < last_pass) fail_line(name, number, "pass numbers must not decrease");
        close_pass(number);
      }
      last_pass = pass;
    }
    ToolpathPoint p;
    p.line = number;
    p.position = scale * Eigen::Vector3d(value("x"), value("y"), value("z"));
    // After unit conversion (docs/formats.md "Limits").
    for (int a = 0; a < 3; ++a)
      limits::check_coordinate(p.position[a], name + ":" + std::to_string(number) + ": " + char('x' + a));
    if (++points > limits::kMaxFilePoints)
      fail_line(name, number, "more than " + std::to_string(limits::kMaxFilePoints) +
                                  " tool-path points (docs/formats.md \"Limits\")");
    if (path.kind == ToolpathKind::contact_points) {
      const Eigen::Vector3d n(value("nx"), value("ny"), value("nz"));
      if (!(n.norm() > 1e-9)) fail_line(name, number, "the normal (nx, ny, nz) is zero");
      p.normal = n.normalized();
    }
    if (column.count("u")) {
      p.has_uv = true;
      p.uv = Eigen::Vector2d(value("u"), value("v"));
    }
    if (column.count("face")) {
      p.face = fields[column.at("face")];
      if (p.face.empty()) fail_line(name, number, "the face name is empty");
    }
    current.points.push_back(p);
  }
  if (!current.points.empty()) close_pass(static_cast<int>(lines.size()));
  if (path.passes.empty()) throw InputError(name + ": no tool-path points in the file");
  return path;
}

Toolpath read_toolpath(const std::string& path, const ToolpathReadOptions& options) {
  const std::string text = json_fields::read_text(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(path + ": the file is empty");
  const std::string ext = lower_extension(path);
  if (ext == ".csv" || ext == ".txt") return parse_toolpath_csv(text, path, options);
  if (ext == ".cl" || ext == ".apt" || ext == ".cls") return parse_apt(text, path, options);
  return parse_gcode(text, path, options);
}

std::string toolpath_to_gcode(const Toolpath& path, double safe_z, double feed,
                              const std::string& header_comment) {
  auto coord = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", x);
    std::string s = buf;
    if (s == "-0.0000") s = "0.0000";
    return s;
  };
  std::ostringstream out;
  out << "%\n";
  std::istringstream comment(header_comment);
  std::string line;
  while (std::getline(comment, line)) {
    std::replace(line.begin(), line.end(), '(', '[');
    std::replace(line.begin(), line.end(), ')', ']');
    out << "(" << line << ")\n";
  }
  out << "G21 G90 G17\n";
  char fbuf[32];
  std::snprintf(fbuf, sizeof fbuf, "%.0f", feed);
  bool first_move = true;
  for (const ToolpathPass& pass : path.passes) {
    const Eigen::Vector3d& s = pass.points.front().position;
    out << "G0 Z" << coord(safe_z) << "\n";
    out << "G0 X" << coord(s.x()) << " Y" << coord(s.y()) << "\n";
    out << "G0 Z" << coord(s.z()) << "\n";
    for (std::size_t k = 1; k < pass.points.size(); ++k) {
      const Eigen::Vector3d& p = pass.points[k].position;
      out << "G1 X" << coord(p.x()) << " Y" << coord(p.y()) << " Z" << coord(p.z());
      if (first_move) out << " F" << fbuf;
      first_move = false;
      out << "\n";
    }
  }
  out << "G0 Z" << coord(safe_z) << "\nM30\n%\n";
  return out.str();
}

}  // namespace furrow
