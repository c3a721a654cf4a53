#include "io/machining/contact_point_file.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/json_fields.hpp"
#include "io/part_file.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace {

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, separator)) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == separator) cells.push_back({});
  return cells;
}

// A header is a line of words: every cell starts with a letter.
bool is_header(const std::vector<std::string>& cells) {
  for (const std::string& c : cells)
    if (c.empty() || !std::isalpha(static_cast<unsigned char>(c[0]))) return false;
  return true;
}

// Column index of each field, -1 when absent.
struct Columns {
  int x = 0, y = 1, z = 2, nx = -1, ny = -1, nz = -1, id = -1;
  std::size_t count = 3;
};

Columns parse_header(const std::vector<std::string>& cells, const std::string& where) {
  Columns c{-1, -1, -1, -1, -1, -1, -1, cells.size()};
  for (std::size_t i = 0; i < cells.size(); ++i) {
    std::string name = cells[i];
    for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    int* slot = name == "x" ? &c.x : name == "y" ? &c.y : name == "z" ? &c.z
              : name == "nx" ? &c.nx : name == "ny" ? &c.ny : name == "nz" ? &c.nz
              : name == "id" ? &c.id : nullptr;
    if (!slot)
      throw InputError(where + ": unknown column " + quote_field(cells[i]) +
                       " in the header (expected x, y, z, optional nx, ny, nz, id)");
    if (*slot >= 0) throw InputError(where + ": column " + quote_field(cells[i]) + " appears twice");
    *slot = static_cast<int>(i);
  }
  if (c.x < 0 || c.y < 0 || c.z < 0)
    throw InputError(where + ": the header must name the columns x, y and z");
  const int normals = (c.nx >= 0) + (c.ny >= 0) + (c.nz >= 0);
  if (normals != 0 && normals != 3)
    throw InputError(where + ": the header names some of nx, ny, nz but not all three");
  return c;
}

}  // namespace

std::vector<ContactPointRecord> parse_contact_points_csv(const std::string& text,
                                                         const std::string& name,
                                                         const std::string& units) {
  const double scale = units_to_mm(units, name + ": units");
  std::vector<ContactPointRecord> points;
  // A byte-order mark (Excel's "CSV UTF-8") is not content.
  std::istringstream in(strip_bom(text));
  std::string raw;
  int line_no = 0;
  char separator = 0;  // from the first line with content
  bool header_allowed = true, have_columns = false;
  Columns columns;
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string where = name + ":" + std::to_string(line_no);
    std::string line = raw;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    line = trim(line);
    if (line.empty()) continue;
    if (!separator) separator = csv_separator(line);
    const std::vector<std::string> cells = split(line, separator);
    if (header_allowed && is_header(cells)) {
      columns = parse_header(cells, where);
      have_columns = true;
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (!have_columns) {
      if (cells.size() != 3 && cells.size() != 6)
        throw InputError(where + ": expected 3 numbers x,y,z or 6 x,y,z,nx,ny,nz, got " +
                         std::to_string(cells.size()) + " values");
      columns = Columns{};
      if (cells.size() == 6) columns = Columns{0, 1, 2, 3, 4, 5, -1, 6};
      have_columns = true;
    }
    if (cells.size() != columns.count)
      throw InputError(where + ": expected " + std::to_string(columns.count) + " values, got " +
                       std::to_string(cells.size()));
    auto value = [&](int column, const char* what) {
      double v = 0;
      if (!parse_finite(cells[column], v))
        throw InputError(where + ": " + what + " " + quote_field(cells[column]) + " is not a finite number");
      return v;
    };
    ContactPointRecord p;
    p.line = line_no;
    p.position = scale * Eigen::Vector3d(value(columns.x, "x"), value(columns.y, "y"),
                                         value(columns.z, "z"));
    // After unit conversion (docs/formats.md "Limits").
    for (int a = 0; a < 3; ++a) limits::check_coordinate(p.position[a], where + ": " + char('x' + a));
    if (static_cast<long>(points.size()) >= limits::kMaxFilePoints)
      throw InputError(where + ": more than " + std::to_string(limits::kMaxFilePoints) +
                       " contact points (docs/formats.md \"Limits\")");
    if (columns.nx >= 0) {
      const Eigen::Vector3d n(value(columns.nx, "nx"), value(columns.ny, "ny"), value(columns.nz, "nz"));
      if (!(n.norm() > 0)) throw InputError(where + ": the normal (0, 0, 0) has no direction");
      p.normal = n.normalized();
      p.has_normal = true;
    }
    if (columns.id >= 0) p.id = cells[columns.id];
    points.push_back(std::move(p));
  }
  if (points.empty()) throw InputError(name + ": no contact points in the file");
  return points;
}

std::vector<ContactPointRecord> read_contact_points(const std::string& path,
                                                    const std::string& units) {
  return parse_contact_points_csv(json_fields::read_text(path), path, units);
}

}  // namespace furrow
