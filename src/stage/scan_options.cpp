#include "stage/scan_options.hpp"

#include "base/error.hpp"
#include "base/number_text.hpp"

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
  // The line of sight (docs/scan.md "Line of sight").
  const auto point_of = [](const std::optional<Eigen::Vector3d>& v) -> std::optional<std::vector<double>> {
    if (!v) return std::nullopt;
    return std::vector<double>{v->x(), v->y(), v->z()};
  };
  OptionSpec<O> viewpoint = numbers_option<O>(
      "viewpoint", "X,Y,Z",
      "where the scanner stood, in the scan's frame and units: each point is seen along the line to it (PCL's "
      "viewpoint); enables grazing rejection and weights. Default: a PCD's VIEWPOINT when it is not PCL's "
      "0 0 0 1 0 0 0, else none",
      3,
      [](const std::vector<double>& v, const std::string&, O& o) { o.viewpoint = Eigen::Vector3d(v[0], v[1], v[2]); },
      [point_of](const O& o) { return point_of(o.viewpoint); });
  viewpoint.example = "0,0,500";
  t.push_back(viewpoint);
  OptionSpec<O> direction = numbers_option<O>(
      "view_direction", "X,Y,Z",
      "the direction a parallel scanner looks along, in the scan's frame (any length; a laser line swept over "
      "the part): instead of --viewpoint",
      3,
      [](const std::vector<double>& v, const std::string& where, O& o) {
        const Eigen::Vector3d d(v[0], v[1], v[2]);
        if (!(d.stableNorm() > 0)) throw InputError(where + ": the view direction must not be zero");
        o.view_direction = d;
      },
      [point_of](const O& o) { return point_of(o.view_direction); });
  direction.example = "0,0,-1";
  t.push_back(direction);
  OptionSpec<O> incidence = number_option<O>(
      "max_incidence", "DEG",
      "points seen more obliquely than this from their normal are grazing: reported, out of the fit and the "
      "evaluation (0 to 90; with a view)",
      [](auto& o) -> auto& { return o.max_incidence_deg; });
  const auto read_incidence = incidence.read;
  incidence.read = [read_incidence](const nlohmann::json& v, const std::string& where, O& o) {
    read_incidence(v, where, o);
    if (!(o.max_incidence_deg < 90))
      throw InputError(where + ": must lie between 0 and 90 degrees, got " + general(o.max_incidence_deg));
  };
  incidence.schema["exclusiveMaximum"] = 90;
  incidence.example = "60";
  t.push_back(incidence);
  t.push_back(toggle_option<O>("incidence_weights",
                               "with a view, weight each fit point by cos(incidence), the noise model of "
                               "docs/scan.md \"Weights\" (off: every point weighs the same)",
                               [](auto& o) -> auto& { return o.incidence_weights; }));
  return t;
}

}  // namespace

const OptionTable<ScanPreprocessOptions>& scan_option_table() {
  static const OptionTable<ScanPreprocessOptions> table = make_table();
  return table;
}

}  // namespace furrow
