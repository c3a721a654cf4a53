#include "partition/regions_file.hpp"

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "base/atomic_file.hpp"
#include "base/json_fields.hpp"
#include "partition/face_grid.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

// ------------------------------------------------------------------ writing

json box_json(const Eigen::AlignedBox2d& b) {
  return {{"min", jf::vector_json(Eigen::Vector2d(b.min()))},
          {"max", jf::vector_json(Eigen::Vector2d(b.max()))}};
}

json box_json(const Eigen::AlignedBox3d& b) {
  return {{"min", jf::vector_json(Eigen::Vector3d(b.min()))},
          {"max", jf::vector_json(Eigen::Vector3d(b.max()))}};
}

json stats_json(const ValueStats& s, const char* what) {
  return {{"mean", jf::finite(s.mean, what)}, {"min", jf::finite(s.min, what)},
          {"max", jf::finite(s.max, what)}};
}

json face_json(const RegionFace& f) {
  json j;
  j["name"] = f.name;
  j["fingerprint"] = f.fingerprint;
  j["grid"] = {f.nu, f.nv};
  j["domain"] = {{"u", {jf::finite(f.domain.u0, "u0"), jf::finite(f.domain.u1, "u1")}},
                 {"v", {jf::finite(f.domain.v0, "v0"), jf::finite(f.domain.v1, "v1")}}};
  j["eps"] = jf::finite(f.eps, "eps");
  j["eps_source"] = f.eps_from_user ? "option" : "default";
  j["curvature_scale"] = jf::finite(f.curvature_scale, "curvature scale");
  j["min_area_mm2"] = jf::finite(f.min_area, "min area");
  j["area_mm2"] = jf::finite(f.area, "face area");
  j["cells"] = {{"valid", f.valid_cells}, {"trimmed", f.trimmed_cells},
                {"degenerate", f.degenerate_cells}};
  json classes = json::object();
  for (int c = 0; c < kCurvatureClassCount; ++c)
    classes[to_string(static_cast<CurvatureClass>(c))] = jf::finite(f.class_area[c], "class area");
  j["class_area_mm2"] = std::move(classes);
  j["regions"] = f.regions;
  return j;
}

json region_json(const Region& r) {
  json j;
  j["id"] = r.id;
  j["face"] = r.face;
  j["class"] = to_string(r.curvature_class);
  j["area_mm2"] = jf::finite(r.area, "region area");
  j["absorbed_area_mm2"] = jf::finite(r.absorbed_area, "absorbed area");
  j["cells"] = r.cells;
  j["merged_components"] = r.merged_components;
  j["uv_box"] = box_json(r.uv_box);
  j["xyz_box"] = box_json(r.xyz_box);
  j["centroid"] = jf::vector_json(r.centroid);
  j["interior_point"] = {{"uv", jf::vector_json(r.interior_uv)},
                         {"xyz", jf::vector_json(r.interior_xyz)}};
  j["K"] = stats_json(r.K, "K");
  j["H"] = stats_json(r.H, "H");
  j["k1"] = stats_json(r.k1, "k1");
  j["k2"] = stats_json(r.k2, "k2");
  json neighbours = json::array();
  for (const RegionNeighbour& n : r.neighbours)
    neighbours.push_back({{"id", n.id}, {"border_mm", jf::finite(n.length, "border length")}});
  j["neighbours"] = std::move(neighbours);
  json border = json::array();
  for (const BorderLoop& loop : r.border) {
    json uv = json::array(), xyz = json::array();
    for (const Eigen::Vector2d& p : loop.uv) uv.push_back(jf::vector_json(p));
    for (const Eigen::Vector3d& p : loop.xyz) xyz.push_back(jf::vector_json(p));
    border.push_back({{"kind", loop.hole ? "hole" : "outer"}, {"uv", std::move(uv)},
                      {"xyz", std::move(xyz)}});
  }
  j["border"] = std::move(border);
  return j;
}

// ------------------------------------------------------------------ reading

// A member and its path, so every read names the field it came from.
struct Field {
  const json& value;
  std::string where;
};

Field get(const json& object, const std::string& key, const std::string& where) {
  return {jf::member(object, key, where), jf::child(where, key)};
}

double number_at(const json& o, const std::string& key, const std::string& where) {
  const Field f = get(o, key, where);
  return jf::number(f.value, f.where);
}

double non_negative_at(const json& o, const std::string& key, const std::string& where) {
  const Field f = get(o, key, where);
  return jf::non_negative_number(f.value, f.where);
}

int count_at(const json& o, const std::string& key, const std::string& where, int min_value) {
  const Field f = get(o, key, where);
  const int n = jf::integer(f.value, f.where);
  if (n < min_value)
    throw InputError(f.where + ": must be at least " + std::to_string(min_value) + ", got " +
                     std::to_string(n));
  return n;
}

std::pair<double, double> interval(const json& v, const std::string& where) {
  const Eigen::Vector2d x = jf::vector2(v, where);
  if (!(x[0] < x[1])) throw InputError(where + ": expected [low, high] with low < high");
  return {x[0], x[1]};
}

ValueStats stats_at(const json& o, const std::string& key, const std::string& where) {
  const Field f = get(o, key, where);
  jf::object(f.value, f.where);
  return {number_at(f.value, "mean", f.where), number_at(f.value, "min", f.where),
          number_at(f.value, "max", f.where)};
}

template <class Box, class Vector, class Read>
Box box_at(const json& o, const std::string& key, const std::string& where, Read read) {
  const Field f = get(o, key, where);
  const Field lo = get(f.value, "min", f.where), hi = get(f.value, "max", f.where);
  const Vector a = read(lo.value, lo.where), b = read(hi.value, hi.where);
  if (!(a.array() <= b.array()).all()) throw InputError(f.where + ": min exceeds max");
  return Box(a, b);
}

RegionFace parse_face(const json& j, const std::string& where) {
  jf::object(j, where);
  RegionFace f;
  f.name = jf::string(get(j, "name", where).value, jf::child(where, "name"));
  f.fingerprint = jf::string(get(j, "fingerprint", where).value, jf::child(where, "fingerprint"));
  const Field grid = get(j, "grid", where);
  const std::vector<double> g = jf::numbers(grid.value, grid.where);
  if (g.size() != 2 || g[0] < 1 || g[1] < 1 || g[0] != std::floor(g[0]) || g[1] != std::floor(g[1]))
    throw InputError(grid.where + ": expected two cell counts [nu, nv], each at least 1");
  // The same bounds as a partition's grid (face_grid.hpp): a file can hold no
  // finer grid, and a count beyond int would make the conversion below
  // undefined behaviour (UBSan in fuzz_regions_json, docs/testing.md).
  if (g[0] > kMaxCellsPerDirection || g[1] > kMaxCellsPerDirection || g[0] * g[1] > kMaxCellsPerFace)
    throw InputError(grid.where + ": " + grid.value.dump() + " is finer than a partition makes (at most " + std::to_string(kMaxCellsPerDirection) +
                     " per direction and " + std::to_string(kMaxCellsPerFace) + " cells per face)");
  f.nu = static_cast<int>(g[0]);
  f.nv = static_cast<int>(g[1]);
  const Field dom = get(j, "domain", where);
  const Field du = get(dom.value, "u", dom.where), dv = get(dom.value, "v", dom.where);
  std::tie(f.domain.u0, f.domain.u1) = interval(du.value, du.where);
  std::tie(f.domain.v0, f.domain.v1) = interval(dv.value, dv.where);
  f.eps = non_negative_at(j, "eps", where);
  const Field source = get(j, "eps_source", where);
  const std::string s = jf::string(source.value, source.where);
  if (s != "option" && s != "default")
    throw InputError(source.where + ": expected \"option\" or \"default\", got " + quote_field(s));
  f.eps_from_user = s == "option";
  f.curvature_scale = non_negative_at(j, "curvature_scale", where);
  f.min_area = non_negative_at(j, "min_area_mm2", where);
  f.area = non_negative_at(j, "area_mm2", where);
  const Field cells = get(j, "cells", where);
  f.valid_cells = count_at(cells.value, "valid", cells.where, 0);
  f.trimmed_cells = count_at(cells.value, "trimmed", cells.where, 0);
  f.degenerate_cells = count_at(cells.value, "degenerate", cells.where, 0);
  const Field classes = get(j, "class_area_mm2", where);
  for (int c = 0; c < kCurvatureClassCount; ++c)
    f.class_area[c] = non_negative_at(classes.value, to_string(static_cast<CurvatureClass>(c)),
                                      classes.where);
  const Field ids = get(j, "regions", where);
  jf::array(ids.value, ids.where);
  for (std::size_t k = 0; k < ids.value.size(); ++k)
    f.regions.push_back(jf::integer(ids.value[k], jf::child(ids.where, k)));
  return f;
}

BorderLoop parse_loop(const json& j, const std::string& where) {
  jf::object(j, where);
  BorderLoop loop;
  const Field kind = get(j, "kind", where);
  const std::string k = jf::string(kind.value, kind.where);
  if (k != "outer" && k != "hole")
    throw InputError(kind.where + ": expected \"outer\" or \"hole\", got " + quote_field(k));
  loop.hole = k == "hole";
  const Field uv = get(j, "uv", where), xyz = get(j, "xyz", where);
  jf::array(uv.value, uv.where);
  jf::array(xyz.value, xyz.where);
  if (uv.value.size() < 3)
    throw InputError(uv.where + ": a border loop needs at least 3 vertices, got " +
                     std::to_string(uv.value.size()));
  if (xyz.value.size() != uv.value.size())
    throw InputError(xyz.where + ": " + std::to_string(xyz.value.size()) +
                     " points, but uv has " + std::to_string(uv.value.size()));
  for (std::size_t p = 0; p < uv.value.size(); ++p) {
    loop.uv.push_back(jf::vector2(uv.value[p], jf::child(uv.where, p)));
    loop.xyz.push_back(jf::vector3(xyz.value[p], jf::child(xyz.where, p)));
  }
  return loop;
}

Region parse_region(const json& j, const std::string& where) {
  jf::object(j, where);
  Region r;
  r.id = count_at(j, "id", where, 0);
  r.face = count_at(j, "face", where, 0);
  const Field cls = get(j, "class", where);
  const std::string c = jf::string(cls.value, cls.where);
  if (!parse_curvature_class(c, r.curvature_class))
    throw InputError(cls.where + ": expected planar, convex, concave or saddle, got " + quote_field(c));
  r.area = non_negative_at(j, "area_mm2", where);
  r.absorbed_area = non_negative_at(j, "absorbed_area_mm2", where);
  r.cells = count_at(j, "cells", where, 1);
  r.merged_components = count_at(j, "merged_components", where, 1);
  const auto read2 = [](const json& v, const std::string& w) { return jf::vector2(v, w); };
  const auto read3 = [](const json& v, const std::string& w) { return jf::vector3(v, w); };
  r.uv_box = box_at<Eigen::AlignedBox2d, Eigen::Vector2d>(j, "uv_box", where, read2);
  r.xyz_box = box_at<Eigen::AlignedBox3d, Eigen::Vector3d>(j, "xyz_box", where, read3);
  const Field centroid = get(j, "centroid", where);
  r.centroid = jf::vector3(centroid.value, centroid.where);
  const Field inner = get(j, "interior_point", where);
  const Field iuv = get(inner.value, "uv", inner.where), ixyz = get(inner.value, "xyz", inner.where);
  r.interior_uv = jf::vector2(iuv.value, iuv.where);
  r.interior_xyz = jf::vector3(ixyz.value, ixyz.where);
  r.K = stats_at(j, "K", where);
  r.H = stats_at(j, "H", where);
  r.k1 = stats_at(j, "k1", where);
  r.k2 = stats_at(j, "k2", where);
  const Field neighbours = get(j, "neighbours", where);
  jf::array(neighbours.value, neighbours.where);
  for (std::size_t k = 0; k < neighbours.value.size(); ++k) {
    const std::string w = jf::child(neighbours.where, k);
    r.neighbours.push_back({count_at(neighbours.value[k], "id", w, 0),
                            non_negative_at(neighbours.value[k], "border_mm", w)});
  }
  const Field border = get(j, "border", where);
  jf::array(border.value, border.where);
  if (border.value.empty()) throw InputError(border.where + ": a region needs a border loop");
  std::vector<BorderLoop> loops;
  for (std::size_t k = 0; k < border.value.size(); ++k)
    loops.push_back(parse_loop(border.value[k], jf::child(border.where, k)));
  r.set_border(std::move(loops));
  return r;
}

// Ids, faces and neighbour references must agree with each other, or
// region_at and the consumers would index out of range.
void check_references(const RegionMap& map, const std::string& root) {
  const int face_count = static_cast<int>(map.faces.size());
  const int region_count = static_cast<int>(map.regions.size());
  std::vector<int> listed(map.regions.size(), 0);
  for (int f = 0; f < face_count; ++f) {
    const std::string where = jf::child(jf::child(root, "faces"), static_cast<std::size_t>(f));
    for (int id : map.faces[static_cast<std::size_t>(f)].regions) {
      if (id < 0 || id >= region_count || map.regions[static_cast<std::size_t>(id)].face != f)
        throw InputError(where + ".regions: region " + std::to_string(id) +
                         " is not a region of this face");
      ++listed[static_cast<std::size_t>(id)];
    }
  }
  for (int r = 0; r < region_count; ++r) {
    const Region& reg = map.regions[static_cast<std::size_t>(r)];
    const std::string where = jf::child(jf::child(root, "regions"), static_cast<std::size_t>(r));
    if (reg.id != r)
      throw InputError(where + ".id: expected " + std::to_string(r) + " (ids run 0, 1, 2, ...), got " +
                       std::to_string(reg.id));
    if (reg.face >= face_count)
      throw InputError(where + ".face: " + std::to_string(reg.face) + " is not a face index (" +
                       std::to_string(face_count) + " faces)");
    if (listed[static_cast<std::size_t>(r)] != 1)
      throw InputError(where + ": listed " + std::to_string(listed[static_cast<std::size_t>(r)]) +
                       " times in faces[" + std::to_string(reg.face) + "].regions, expected once");
    for (const RegionNeighbour& n : reg.neighbours)
      if (n.id >= region_count || map.regions[static_cast<std::size_t>(n.id)].face != reg.face ||
          n.id == r)
        throw InputError(where + ".neighbours: region " + std::to_string(n.id) +
                         " is not another region of the same face");
  }
}

}  // namespace

std::string regions_to_json_text(const RegionMap& map) {
  json doc;
  doc["format"] = kRegionsFormat;
  doc["version"] = kRegionsVersion;
  doc["units"] = "mm";
  doc["source_units"] = map.source_units;
  doc["part_fingerprint"] = map.part_fingerprint;
  json faces = json::array();
  for (const RegionFace& f : map.faces) faces.push_back(face_json(f));
  doc["faces"] = std::move(faces);
  json regions = json::array();
  for (const Region& r : map.regions) regions.push_back(region_json(r));
  doc["regions"] = std::move(regions);
  return jf::to_text(doc);
}

void write_regions(const RegionMap& map, const std::string& path) {
  write_file_atomically(path, regions_to_json_text(map));
}

RegionMap read_regions(const std::string& path) {
  return parse_regions_json(jf::read_text(path), path);
}

RegionMap parse_regions_json(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const std::string root = name + ":";
  jf::object(doc, root);
  const Field format = get(doc, "format", root);
  if (!format.value.is_string() || format.value.get<std::string>() != kRegionsFormat)
    throw InputError(format.where + ": expected " + quote_field(kRegionsFormat) + " (is this a regions file from furrow partition?)");
  const Field version = get(doc, "version", root);
  if (jf::integer(version.value, version.where) != kRegionsVersion)
    throw InputError(version.where + ": version " + version.value.dump() +
                     " is not supported (this furrow reads version " +
                     std::to_string(kRegionsVersion) + ")");
  const Field units = get(doc, "units", root);
  if (jf::string(units.value, units.where) != "mm")
    throw InputError(units.where + ": regions files are in \"mm\"");
  RegionMap map;
  map.source_units = jf::string(get(doc, "source_units", root).value, jf::child(root, "source_units"));
  map.part_fingerprint =
      jf::string(get(doc, "part_fingerprint", root).value, jf::child(root, "part_fingerprint"));
  const Field faces = get(doc, "faces", root);
  jf::array(faces.value, faces.where);
  for (std::size_t f = 0; f < faces.value.size(); ++f)
    map.faces.push_back(parse_face(faces.value[f], jf::child(faces.where, f)));
  const Field regions = get(doc, "regions", root);
  jf::array(regions.value, regions.where);
  for (std::size_t r = 0; r < regions.value.size(); ++r)
    map.regions.push_back(parse_region(regions.value[r], jf::child(regions.where, r)));
  check_references(map, root);
  return map;
}

}  // namespace furrow
