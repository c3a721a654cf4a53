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
  return t;
}

}  // namespace

const OptionTable<ScanPreprocessOptions>& scan_option_table() {
  static const OptionTable<ScanPreprocessOptions> table = make_table();
  return table;
}

}  // namespace furrow
