#include "partition/regions_file.hpp"

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "base/atomic_file.hpp"
#include "base/json_cursor.hpp"
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

json region_json(const Region& r, int group) {
  json j;
  j["id"] = r.id;
  j["face"] = r.face;
  j["class"] = to_string(r.curvature_class);
  j["area_mm2"] = jf::finite(r.area, "region area");
  j["absorbed_area_mm2"] = jf::finite(r.absorbed_area, "absorbed area");
  j["cells"] = r.cells;
  j["merged_components"] = r.merged_components;
  j["group"] = group;
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

std::pair<double, double> interval(const JsonCursor& o, const std::string& key) {
  const Eigen::Vector2d x = o.vector2(key);
  if (!(x[0] < x[1])) throw InputError(o.path(key) + ": expected [low, high] with low < high");
  return {x[0], x[1]};
}

ValueStats stats_at(const JsonCursor& o, const std::string& key) {
  const JsonCursor s = o.at(key);
  return {s.number("mean"), s.number("min"), s.number("max")};
}

Eigen::AlignedBox2d box2_at(const JsonCursor& o, const std::string& key) {
  const JsonCursor b = o.at(key);
  const Eigen::Vector2d lo = b.vector2("min"), hi = b.vector2("max");
  if (!(lo.array() <= hi.array()).all()) throw InputError(b.where() + ": min exceeds max");
  return {lo, hi};
}

Eigen::AlignedBox3d box3_at(const JsonCursor& o, const std::string& key) {
  const JsonCursor b = o.at(key);
  const Eigen::Vector3d lo = b.vector3("min"), hi = b.vector3("max");
  if (!(lo.array() <= hi.array()).all()) throw InputError(b.where() + ": min exceeds max");
  return {lo, hi};
}

RegionFace parse_face(const json& j, const std::string& where) {
  const JsonCursor o(j, where);
  RegionFace f;
  f.name = o.string("name");
  f.fingerprint = o.string("fingerprint");
  const std::vector<double> g = o.numbers("grid");
  const std::string grid = o.path("grid");
  if (g.size() != 2 || g[0] < 1 || g[1] < 1 || g[0] != std::floor(g[0]) || g[1] != std::floor(g[1]))
    throw InputError(grid + ": expected two cell counts [nu, nv], each at least 1");
  // The same bounds as a partition's grid (face_grid.hpp): a file can hold no
  // finer grid, and a count beyond int would make the conversion below
  // undefined behaviour (UBSan in fuzz_regions_json, docs/testing.md).
  if (g[0] > kMaxCellsPerDirection || g[1] > kMaxCellsPerDirection || g[0] * g[1] > kMaxCellsPerFace)
    throw InputError(grid + ": " + o.raw("grid").dump() + " is finer than a partition makes (at most " +
                     std::to_string(kMaxCellsPerDirection) + " per direction and " +
                     std::to_string(kMaxCellsPerFace) + " cells per face)");
  f.nu = static_cast<int>(g[0]);
  f.nv = static_cast<int>(g[1]);
  const JsonCursor domain = o.at("domain");
  std::tie(f.domain.u0, f.domain.u1) = interval(domain, "u");
  std::tie(f.domain.v0, f.domain.v1) = interval(domain, "v");
  f.eps = o.non_negative("eps");
  const std::string s = o.string("eps_source");
  if (s != "option" && s != "default")
    throw InputError(o.path("eps_source") + ": expected \"option\" or \"default\", got " + quote_field(s));
  f.eps_from_user = s == "option";
  f.curvature_scale = o.non_negative("curvature_scale");
  f.min_area = o.non_negative("min_area_mm2");
  f.area = o.non_negative("area_mm2");
  const JsonCursor cells = o.at("cells");
  f.valid_cells = cells.integer("valid", 0);
  f.trimmed_cells = cells.integer("trimmed", 0);
  f.degenerate_cells = cells.integer("degenerate", 0);
  const JsonCursor classes = o.at("class_area_mm2");
  for (int c = 0; c < kCurvatureClassCount; ++c)
    f.class_area[c] = classes.non_negative(to_string(static_cast<CurvatureClass>(c)));
  const json& ids = o.array("regions");
  for (std::size_t k = 0; k < ids.size(); ++k)
    f.regions.push_back(jf::integer(ids[k], jf::child(o.path("regions"), k)));
  return f;
}

BorderLoop parse_loop(const json& j, const std::string& where) {
  const JsonCursor o(j, where);
  BorderLoop loop;
  const std::string k = o.string("kind");
  if (k != "outer" && k != "hole")
    throw InputError(o.path("kind") + ": expected \"outer\" or \"hole\", got " + quote_field(k));
  loop.hole = k == "hole";
  const json& uv = o.array("uv");
  const json& xyz = o.array("xyz");
  if (uv.size() < 3)
    throw InputError(o.path("uv") + ": a border loop needs at least 3 vertices, got " + std::to_string(uv.size()));
  if (xyz.size() != uv.size())
    throw InputError(o.path("xyz") + ": " + std::to_string(xyz.size()) + " points, but uv has " +
                     std::to_string(uv.size()));
  for (std::size_t p = 0; p < uv.size(); ++p) {
    loop.uv.push_back(jf::vector2(uv[p], jf::child(o.path("uv"), p)));
    loop.xyz.push_back(jf::vector3(xyz[p], jf::child(o.path("xyz"), p)));
  }
  return loop;
}

Region parse_region(const json& j, const std::string& where) {
  const JsonCursor o(j, where);
  Region r;
  r.id = o.integer("id", 0);
  r.face = o.integer("face", 0);
  const std::string c = o.string("class");
  if (!parse_curvature_class(c, r.curvature_class))
    throw InputError(o.path("class") + ": expected planar, convex, concave or saddle, got " + quote_field(c));
  r.area = o.non_negative("area_mm2");
  r.absorbed_area = o.non_negative("absorbed_area_mm2");
  r.cells = o.integer("cells", 1);
  r.merged_components = o.integer("merged_components", 1);
  r.group = o.has("group") ? o.integer("group", 0) : r.id;  // files before groups: each region alone
  r.uv_box = box2_at(o, "uv_box");
  r.xyz_box = box3_at(o, "xyz_box");
  r.centroid = o.vector3("centroid");
  const JsonCursor inner = o.at("interior_point");
  r.interior_uv = inner.vector2("uv");
  r.interior_xyz = inner.vector3("xyz");
  r.K = stats_at(o, "K");
  r.H = stats_at(o, "H");
  r.k1 = stats_at(o, "k1");
  r.k2 = stats_at(o, "k2");
  const json& neighbours = o.array("neighbours");
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    const JsonCursor n(neighbours[k], jf::child(o.path("neighbours"), k));
    r.neighbours.push_back({n.integer("id", 0), n.non_negative("border_mm")});
  }
  const json& border = o.array("border");
  if (border.empty()) throw InputError(o.path("border") + ": a region needs a border loop");
  std::vector<BorderLoop> loops;
  for (std::size_t k = 0; k < border.size(); ++k) loops.push_back(parse_loop(border[k], jf::child(o.path("border"), k)));
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

// Group ids run 0..n-1, each used, and a group has one class: the
// consumers index groups by id and report a group's class.
void check_groups(const RegionMap& map, const std::string& root) {
  const int count = static_cast<int>(map.regions.size());
  std::vector<int> class_of(map.regions.size(), -1);
  int groups = 0;
  for (const Region& r : map.regions) {
    const std::string where = jf::child(jf::child(root, "regions"), static_cast<std::size_t>(r.id)) + ".group";
    if (r.group < 0 || r.group >= count)
      throw InputError(where + ": " + std::to_string(r.group) + " is not a group id (0 to " + std::to_string(count - 1) + ")");
    int& c = class_of[static_cast<std::size_t>(r.group)];
    if (c >= 0 && c != static_cast<int>(r.curvature_class))
      throw InputError(where + ": group " + std::to_string(r.group) + " holds regions of different classes");
    c = static_cast<int>(r.curvature_class);
    groups = std::max(groups, r.group + 1);
  }
  for (int g = 0; g < groups; ++g)
    if (class_of[static_cast<std::size_t>(g)] < 0)
      throw InputError(jf::child(root, "regions") + ": no region is in group " + std::to_string(g) +
                       " (group ids run 0, 1, 2, ...)");
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
  // A map that was never grouped (built by hand, not by partition_part)
  // is written with every region a group of its own.
  const bool alone = map.groups.empty();
  for (const Region& r : map.regions) regions.push_back(region_json(r, alone ? r.id : r.group));
  doc["regions"] = std::move(regions);
  json groups = json::array();
  auto group_json = [](const RegionGroup& g) {
    return json{{"id", g.id},
                {"class", to_string(g.curvature_class)},
                {"area_mm2", jf::finite(g.area, "group area")},
                {"regions", g.regions},
                {"faces", g.faces}};
  };
  if (alone)
    for (const Region& r : map.regions) groups.push_back(group_json({r.id, r.curvature_class, r.area, {r.id}, {r.face}}));
  else
    for (const RegionGroup& g : map.groups) groups.push_back(group_json(g));
  doc["groups"] = std::move(groups);
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
  const JsonCursor root(doc, name + ":");
  const json& format = root.raw("format");
  if (!format.is_string() || format.get<std::string>() != kRegionsFormat)
    throw InputError(root.path("format") + ": expected " + quote_field(kRegionsFormat) +
                     " (is this a regions file from furrow partition?)");
  if (root.integer("version") != kRegionsVersion)
    throw InputError(root.path("version") + ": version " + root.raw("version").dump() +
                     " is not supported (this furrow reads version " + std::to_string(kRegionsVersion) + ")");
  if (root.string("units") != "mm") throw InputError(root.path("units") + ": regions files are in \"mm\"");
  RegionMap map;
  map.source_units = root.string("source_units");
  map.part_fingerprint = root.string("part_fingerprint");
  const json& faces = root.array("faces");
  for (std::size_t f = 0; f < faces.size(); ++f)
    map.faces.push_back(parse_face(faces[f], jf::child(root.path("faces"), f)));
  const json& regions = root.array("regions");
  for (std::size_t r = 0; r < regions.size(); ++r)
    map.regions.push_back(parse_region(regions[r], jf::child(root.path("regions"), r)));
  check_references(map, root.where());
  check_groups(map, root.where());
  map.collect_groups();
  if (root.has("groups")) {
    // The list must say what the regions say (it is derived from them).
    const json& groups = root.array("groups");
    if (groups.size() != map.groups.size())
      throw InputError(root.path("groups") + ": " + std::to_string(groups.size()) + " groups, but the regions name " +
                       std::to_string(map.groups.size()));
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const JsonCursor o(groups[g], jf::child(root.path("groups"), g));
      std::vector<int> members;
      const json& ids = o.array("regions");
      for (std::size_t k = 0; k < ids.size(); ++k) members.push_back(jf::integer(ids[k], jf::child(o.path("regions"), k)));
      if (o.integer("id", 0) != static_cast<int>(g) || members != map.groups[g].regions)
        throw InputError(o.where() + ": its id and regions disagree with the regions' \"group\" members");
    }
  }
  return map;
}

}  // namespace furrow
