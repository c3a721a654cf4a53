#include "stage/scan_options.hpp"

namespace furrow {

namespace {

OptionTable<ScanPreprocessOptions> make_table() {
  using O = ScanPreprocessOptions;
  OptionTable<O> t;
  t.push_back(number_option<O>("voxel", "MM",
                               "edge of the voxel grid that picks the registration's points, one real point per "
                               "occupied voxel; every point is still compared (docs/scan.md)",
                               [](auto& o) -> auto& { return o.voxel; }));
  t.push_back(toggle_option<O>("spray_removal", "flag no point as spray",
                               [](auto& o) -> auto& { return o.remove_spray; }));
  t.push_back(integer_option<O>("spray_neighbours", "K", "neighbours of the statistical spray rule",
                                [](auto& o) -> auto& { return o.outlier_neighbours; }, 2));
  t.push_back(number_option<O>("spray_far_sigmas", "K",
                               "standard deviations of the mean neighbour distance above its mean at which the "
                               "statistical rule fires (it names spray far; alone it flags nothing)",
                               [](auto& o) -> auto& { return o.outlier_sigmas; }));
  t.push_back(number_option<O>("spray_near_sigmas", "K",
                               "robust standard deviations off the quadric surface of its neighbours that make a point spray",
                               [](auto& o) -> auto& { return o.spray_sigmas; }));
  t.push_back(integer_option<O>("normal_neighbours", "K",
                                "neighbours of a point's local surface (normals and the spray rule)",
                                [](auto& o) -> auto& { return o.normal_neighbours; }, 3));
  t.push_back(parsed_option<O>(
      "scan_start", "START",
      "the registration's coarse start: global (the global search), features (PCL's FPFH features matched to "
      "the part; the global search where they place nothing) or best (both fitted, the lower robust cost kept; "
      "docs/scan.md \"Registration\")",
      [](auto& o) -> auto& { return o.start; }, parse_scan_start, [](ScanStart s) { return to_string(s); },
      choice_names({ScanStart::global, ScanStart::features, ScanStart::best})));
  return t;
}

}  // namespace

const OptionTable<ScanPreprocessOptions>& scan_option_table() {
  static const OptionTable<ScanPreprocessOptions> table = make_table();
  return table;
}

}  // namespace furrow
