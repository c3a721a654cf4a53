#include "stage/prediction_options.hpp"

#include "base/error.hpp"

namespace furrow {

namespace {

OptionTable<PathPredictionOptions> make_table() {
  using O = PathPredictionOptions;
  using nlohmann::json;
  OptionTable<O> t;
  t.push_back(number_option<O>("tolerance", "MM", "the path's tolerance: steps are compared with it",
                               [](auto& o) -> auto& { return o.tolerance; }));
  t.push_back(written_as(
      number_option<O>("gouge_threshold", "MM", "overcut deeper than this is a gouge site (a path planned to the tolerance overcuts up to it)",
                       [](auto& o) -> auto& { return o.gouge_threshold; }),
      [](const O& o) {
        return json_fields::finite(o.gouge_threshold > 0 ? o.gouge_threshold : 2 * o.tolerance, "gouge threshold");
      },
      "twice the tolerance"));
  t.push_back(written_as(
      number_option<O>("resolution", "MM", "z-map node spacing; by default a tenth of the flat side step whose scallop is the tolerance, "
                       "rounded to 1/2/5 (ball 6 mm at 0.01: 0.05)",
                       [](auto& o) -> auto& { return o.resolution; }),
      [](const O& o) { return o.resolution > 0 ? json_fields::finite(o.resolution, "resolution") : json(nullptr); },
      "from the tool and the tolerance"));
  t.push_back(number_option<O>("cell", "MM", "size of the stored error cells on the surface",
                               [](auto& o) -> auto& { return o.map.cell_size; }));
  OptionSpec<O> stock = numbers_option<O>(
      "stock", "X0,Y0,Z0,X1,Y1,Z1",
      "raw stock box in the part frame, mm: a rapid whose tip is below its top while the cutter is over it "
      "is a rapid gouge (docs/architecture.md \"Rapid moves\")",
      6,
      [](const std::vector<double>& b, const std::string& where, O& o) {
        for (int k = 0; k < 3; ++k)
          if (!(b[k] < b[k + 3]))
            throw InputError(where + ": each min must be below its max (" + std::string(1, char('x' + k)) + ")");
        o.stock = Eigen::AlignedBox3d(Eigen::Vector3d(b[0], b[1], b[2]), Eigen::Vector3d(b[3], b[4], b[5]));
      },
      [](const O& o) -> std::optional<std::vector<double>> {
        if (!o.stock) return std::nullopt;
        return std::vector<double>{o.stock->min().x(), o.stock->min().y(), o.stock->min().z(),
                                   o.stock->max().x(), o.stock->max().y(), o.stock->max().z()};
      });
  stock.example = "-10,-10,-5,110,90,40";
  t.push_back(stock);
  return t;
}

}  // namespace

const OptionTable<PathPredictionOptions>& prediction_option_table() {
  static const OptionTable<PathPredictionOptions> table = make_table();
  return table;
}

}  // namespace furrow
