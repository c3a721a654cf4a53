#include "partition/region_map.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "partition/part_fingerprint.hpp"

namespace furrow {

void Region::set_border(std::vector<BorderLoop> loops) {
  border = std::move(loops);
  std::vector<UvLoop> uv;
  uv.reserve(border.size());
  for (const BorderLoop& l : border) uv.push_back(l.uv);
  uv_outline = Trim(std::move(uv), "region " + std::to_string(id) + " border");
}

void RegionMap::collect_groups() {
  int count = 0;
  for (const Region& r : regions) count = std::max(count, r.group + 1);
  groups.assign(static_cast<std::size_t>(count), RegionGroup{});
  for (const Region& r : regions) {
    RegionGroup& g = groups[static_cast<std::size_t>(r.group)];
    g.id = r.group;
    g.curvature_class = r.curvature_class;
    g.area += r.area;
    g.regions.push_back(r.id);
    if (std::find(g.faces.begin(), g.faces.end(), r.face) == g.faces.end()) g.faces.push_back(r.face);
  }
  for (RegionGroup& g : groups) std::sort(g.faces.begin(), g.faces.end());
}

std::optional<int> RegionMap::region_at(int face, double u, double v) const {
  if (face < 0 || face >= static_cast<int>(faces.size())) return std::nullopt;
  const Eigen::Vector2d uv(u, v);
  for (int id : faces[static_cast<std::size_t>(face)].regions) {
    const Region& r = regions[static_cast<std::size_t>(id)];
    // The box test is cheap and rejects most regions; the outline is exact.
    if (r.uv_box.contains(uv) && !r.uv_outline.empty() && r.uv_outline.contains(uv)) return id;
  }
  return std::nullopt;
}

void RegionMap::check_belongs_to(const Part& part, const std::string& map_name,
                                 const std::string& part_name) const {
  const std::string other = "; it was computed for another part (run furrow partition again)";
  if (faces.size() != part.faces.size())
    throw InputError(map_name + ": faces: " + std::to_string(faces.size()) + " faces, but " +
                     part_name + " has " + std::to_string(part.faces.size()) + other);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::string where = map_name + ": faces[" + std::to_string(f) + "]";
    if (faces[f].name != part.faces[f].name())
      throw InputError(where + ".name: \"" + faces[f].name + "\", but face " + std::to_string(f) +
                       " of " + part_name + " is \"" + part.faces[f].name() + "\"" + other);
    const std::string fp = face_fingerprint(part.faces[f]);
    if (faces[f].fingerprint != fp)
      throw InputError(where + ".fingerprint: face \"" + faces[f].name + "\" of " + part_name +
                       " has different geometry (fingerprint " + fp + ", regions made for " +
                       faces[f].fingerprint + ")" + other);
  }
}

}  // namespace furrow
