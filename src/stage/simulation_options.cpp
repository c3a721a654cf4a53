#include "stage/simulation_options.hpp"

#include "base/error.hpp"

namespace furrow {

namespace {

OptionTable<SimulationOptions> make_table() {
  using O = SimulationOptions;
  OptionTable<O> t;
  OptionSpec<O> misalign = numbers_option<O>(
      "misalign", "RX,RY,RZ,TX,TY,TZ",
      "the part on the table: x_cmm = Rz Ry Rx x_part + t (degrees, mm)", 6,
      [](const std::vector<double>& v, const std::string&, O& o) {
        o.misalignment.rotation_deg = {v[0], v[1], v[2]};
        o.misalignment.translation = {v[3], v[4], v[5]};
      },
      [](const O& o) -> std::optional<std::vector<double>> {
        const Misalignment& m = o.misalignment;
        return std::vector<double>{m.rotation_deg.x(), m.rotation_deg.y(), m.rotation_deg.z(),
                                   m.translation.x(),  m.translation.y(),  m.translation.z()};
      });
  misalign.example = "2,-1.5,91,120,60,-15";
  t.push_back(misalign);
  t.push_back(number_option<O>("noise", "S", "probing noise sigma in mm, along the normal",
                               [](auto& o) -> auto& { return o.noise_sigma; }, Bound::non_negative));
  t.push_back(formerly(integer_option<O>("blunders", "N", "number of blunders",
                                         [](auto& o) -> auto& { return o.blunders; }, 0),
                       "--outliers"));
  OptionSpec<O> sizes = numbers_option<O>(
      "blunder_size", "A,B", "blunder size range in mm, random sign, 0 < A <= B", 2,
      [](const std::vector<double>& v, const std::string& where, O& o) {
        if (!(v[0] > 0) || !(v[1] >= v[0]))
          throw InputError(where + ": expected the smallest and largest blunder in mm, 0 < smallest <= largest");
        o.blunder_min = v[0];
        o.blunder_max = v[1];
      },
      [](const O& o) -> std::optional<std::vector<double>> { return std::vector<double>{o.blunder_min, o.blunder_max}; });
  sizes.example = "0.2,0.5";
  t.push_back(formerly(sizes, "--outlier-size"));
  t.push_back(integer_option<O>("seed", "N", "random seed of every draw", [](auto& o) -> auto& { return o.seed; }, 0));
  OptionSpec<O> points = parsed_option<O>(
      "points", "K", "what the CMM reports: centre (the probe ball's centre) or contact",
      [](auto& o) -> auto& { return o.kind; }, parse_probe_point_kind,
      [](ProbePointKind k) { return std::string(to_string(k)); }, {"centre", "contact"});
  points.example = "contact";
  t.push_back(points);
  t.push_back(toggle_option<O>("anonymous", "no ids, points shuffled (as an unplanned scan)",
                               [](auto& o) -> auto& { return o.anonymous; }));
  return t;
}

}  // namespace

const OptionTable<SimulationOptions>& simulation_option_table() {
  static const OptionTable<SimulationOptions> table = make_table();
  return table;
}

}  // namespace furrow
