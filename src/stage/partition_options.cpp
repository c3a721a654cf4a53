#include "stage/partition_options.hpp"

#include <cstdlib>

#include "base/error.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace {

constexpr long kMaxCells = 100000;

std::optional<long> count_of(const std::string& text) {
  char* end = nullptr;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || n < 1 || n > kMaxCells) return std::nullopt;
  return n;
}

// A job file writes the grid as [nu, nv]; the command line (and a job file,
// if it likes) as "NUxNV" or "N".
GridSize read_grid(const nlohmann::json& v, const std::string& where) {
  if (v.is_string()) return parse_grid_size(v.get<std::string>(), where);
  const std::vector<double> counts = json_fields::numbers(v, where);
  if (counts.size() != 2) throw InputError(where + ": expected [cells along u, cells along v] or \"NUxNV\"");
  const int nu = json_fields::integer(v[0], json_fields::child(where, 0));
  const int nv = json_fields::integer(v[1], json_fields::child(where, 1));
  if (nu < 1 || nv < 1 || nu > kMaxCells || nv > kMaxCells)
    throw InputError(where + ": cell counts must lie between 1 and " + std::to_string(kMaxCells));
  return GridSize{nu, nv};
}

OptionTable<PartitionOptions> make_table() {
  using O = PartitionOptions;
  using nlohmann::json;
  OptionTable<O> t;
  OptionSpec<O> grid;
  grid.key = "grid";
  grid.kind = OptionKind::text;
  grid.value_name = "NUxNV";
  grid.help = "cells per face along u and v (N for NxN); a job file may also write [NU, NV]";
  grid.default_text = "from --spacing";
  grid.example = "40x30";
  grid.schema = {{"anyOf",
                  json::array({{{"type", "array"},
                                {"items", {{"type", "integer"}, {"minimum", 1}, {"maximum", kMaxCells}}},
                                {"minItems", 2},
                                {"maxItems", 2}},
                               {{"type", "string"}, {"pattern", "^[0-9]+(x[0-9]+)?$"}}})}};
  grid.read = [](const json& v, const std::string& where, O& o) { o.grid = read_grid(v, where); };
  grid.write = [](const O& o) { return o.grid ? json::array({o.grid->nu, o.grid->nv}) : json(nullptr); };
  t.push_back(grid);
  t.push_back(default_is(number_option<O>("spacing", "MM", "cell size on the surface instead of a grid",
                                          [](auto& o) -> auto& { return o.spacing; }),
                         "the largest face gets 400 cells along its longest side"));
  t.push_back(default_is(number_option<O>("eps", "K", "curvature tolerance in 1/mm",
                                          [](auto& o) -> auto& { return o.eps; }, Bound::non_negative),
                         "per face, max(1e-4, 1 % of the face's 90th-percentile |k|)"));
  t.push_back(default_is(number_option<O>("min_area", "MM2", "smallest region kept",
                                          [](auto& o) -> auto& { return o.min_area; }, Bound::non_negative),
                         "0.5 % of each face's area"));
  return t;
}

}  // namespace

GridSize parse_grid_size(const std::string& text, const std::string& where) {
  const auto bad = [&]() -> GridSize {
    throw InputError(where + ": expected COUNTUxCOUNTV with counts of at least 1 (e.g. 400x300), got " +
                     quote_field(text));
  };
  const auto x = text.find('x');
  if (x == std::string::npos) {
    const std::optional<long> n = count_of(text);
    if (!n) return bad();
    return GridSize{static_cast<int>(*n), static_cast<int>(*n)};
  }
  const std::optional<long> nu = count_of(text.substr(0, x)), nv = count_of(text.substr(x + 1));
  if (!nu || !nv) return bad();
  return GridSize{static_cast<int>(*nu), static_cast<int>(*nv)};
}

void check_partition_options(const PartitionOptions& options, const std::string& where) {
  if (options.grid && options.spacing) throw InputError(where + ": grid and spacing exclude each other");
}

const OptionTable<PartitionOptions>& partition_option_table() {
  static const OptionTable<PartitionOptions> table = make_table();
  return table;
}

}  // namespace furrow
