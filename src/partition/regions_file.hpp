#pragma once
// regions.json: the curvature partition on disk (docs/formats.md
// "regions.json"). Written by `furrow partition`, read by the planner,
// inspection and the report.
//
// Writing is deterministic (same map, same bytes) and exact: every double is
// written in its shortest round-trip form, so read(write(map)) reproduces
// every number bit for bit and region_at answers the same after a round trip.
// Reading validates the whole file and throws InputError naming the file and
// the field ("regions.json: regions[3].border[0].uv: ..."); a file from
// another part is caught by RegionMap::check_belongs_to, not here.
#include <string>

#include "partition/region_map.hpp"

namespace furrow {

constexpr const char* kRegionsFormat = "furrow-regions";
constexpr int kRegionsVersion = 1;

std::string regions_to_json_text(const RegionMap& map);
// Atomic (write_file_atomically).
void write_regions(const RegionMap& map, const std::string& path);

RegionMap read_regions(const std::string& path);
// `name` stands for the source in error messages.
RegionMap parse_regions_json(const std::string& text, const std::string& name);

}  // namespace furrow
