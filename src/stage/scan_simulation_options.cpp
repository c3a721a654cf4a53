#include "stage/scan_simulation_options.hpp"

#include "base/error.hpp"

namespace furrow {

namespace {

OptionTable<ScanSimulationOptions> make_table() {
  using O = ScanSimulationOptions;
  OptionTable<O> t;
  OptionSpec<O> view = numbers_option<O>(
      "view", "X,Y,Z", "the direction the scanner looks along, part frame (any length)", 3,
      [](const std::vector<double>& v, const std::string& where, O& o) {
        const Eigen::Vector3d d(v[0], v[1], v[2]);
        if (!(d.norm() > 0)) throw InputError(where + ": the view direction must not be zero");
        o.scanner.view = d;
      },
      [](const O& o) -> std::optional<std::vector<double>> {
        return std::vector<double>{o.scanner.view.x(), o.scanner.view.y(), o.scanner.view.z()};
      });
  view.example = "0.3,0,-1";
  t.push_back(view);
  t.push_back(number_option<O>("stripe_pitch", "MM", "distance between the scanner's stripes",
                               [](auto& o) -> auto& { return o.scanner.stripe_pitch; }));
  t.push_back(number_option<O>("point_pitch", "MM", "distance between points along a stripe",
                               [](auto& o) -> auto& { return o.scanner.point_pitch; }));
  t.push_back(number_option<O>("scan_noise", "S", "noise sigma in mm along the line of sight",
                               [](auto& o) -> auto& { return o.scanner.noise_sigma; }, Bound::non_negative));
  t.push_back(toggle_option<O>("noise_grows_with_incidence",
                               "make the noise along the line of sight grow as 1 / cos^2(incidence), its part "
                               "along the normal as 1 / cos(incidence) (docs/scan.md \"Weights\")",
                               [](auto& o) -> auto& { return o.scanner.noise_grows_with_incidence; }));
  t.push_back(number_option<O>("max_incidence", "DEG",
                               "surfaces seen more obliquely than this from their normal give no point (0 to 90)",
                               [](auto& o) -> auto& { return o.scanner.max_incidence_deg; }));
  OptionSpec<O> spray = number_option<O>("spray", "SHARE",
                                         "share of the points thrown off along the line of sight (0 to 1)",
                                         [](auto& o) -> auto& { return o.scanner.spray_share; }, Bound::fraction);
  spray.example = "0.005";
  t.push_back(spray);
  OptionSpec<O> sizes = numbers_option<O>(
      "spray_size", "A,B", "how far spray is thrown, in mm, random sign, 0 < A <= B", 2,
      [](const std::vector<double>& v, const std::string& where, O& o) {
        if (!(v[0] > 0) || !(v[1] >= v[0]))
          throw InputError(where + ": expected the smallest and largest spray offset in mm, 0 < smallest <= largest");
        o.scanner.spray_min = v[0];
        o.scanner.spray_max = v[1];
      },
      [](const O& o) -> std::optional<std::vector<double>> {
        return std::vector<double>{o.scanner.spray_min, o.scanner.spray_max};
      });
  sizes.example = "0.5,2";
  t.push_back(sizes);
  t.push_back(toggle_option<O>("scan_inch", "write the cloud's coordinates in inches", [](auto& o) -> auto& { return o.inch; }));
  return t;
}

}  // namespace

const OptionTable<ScanSimulationOptions>& scan_simulation_option_table() {
  static const OptionTable<ScanSimulationOptions> table = make_table();
  return table;
}

const OptionTable<SimulationOptions>& scan_simulation_placement_table() {
  static const OptionTable<SimulationOptions> table = only_options(simulation_option_table(), {"misalign", "seed"});
  return table;
}

}  // namespace furrow
