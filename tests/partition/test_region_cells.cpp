// Components, merging and border tracing on synthetic class grids, where the
// right answer is known by construction.
#include <doctest/doctest.h>

#include <random>

#include "geometry/trim.hpp"
#include "partition/region_adjacency.hpp"
#include "partition/region_boundary.hpp"
#include "partition/region_labels.hpp"
#include "partition/region_merge.hpp"

using namespace furrow;

namespace {

constexpr unsigned char P = 0, X = 1, C = 2, S = 3, T = kTrimmedCell;  // planar convex concave saddle

// A field of unit square cells (area 1, sides 1) over an nu x nv grid.
CurvatureField unit_field(int nu, int nv) {
  CurvatureField f;
  f.nu = nu;
  f.nv = nv;
  f.samples.resize(static_cast<std::size_t>(nu) * nv);
  for (CurvatureSample& s : f.samples) {
    s.status = SampleStatus::valid;
    s.area = 1;
    s.length_u = s.length_v = 1;
  }
  return f;
}

// rows[i] is the row of cells at u index i (j along v).
std::vector<unsigned char> grid_of(const std::vector<std::vector<unsigned char>>& rows) {
  std::vector<unsigned char> out;
  for (const auto& r : rows) out.insert(out.end(), r.begin(), r.end());
  return out;
}

// Even-odd over a label's node loops, tested at every cell centre, must give
// back exactly the label's cells; the shoelace areas must add up to its cell
// count. Returns the number of disagreeing cells.
int check_loops(const RegionLabels& labels) {
  const auto loops = trace_region_boundaries(labels);
  int wrong = 0;
  for (int l = 0; l < labels.count(); ++l) {
    std::vector<UvLoop> uv;
    long long twice_area = 0;
    for (const NodeLoop& loop : loops[static_cast<std::size_t>(l)]) {
      UvLoop poly;
      for (const Eigen::Vector2i& n : loop.nodes) poly.emplace_back(n.x(), n.y());
      uv.push_back(poly);
      twice_area += loop.twice_area;
    }
    const Trim outline(uv);
    long long cells = 0;
    for (int i = 0; i < labels.nu; ++i) {
      for (int j = 0; j < labels.nv; ++j) {
        const bool in = labels.at(i, j) == l;
        cells += in;
        const bool inside = !uv.empty() && outline.contains({i + 0.5, j + 0.5});  // empty Trim keeps all
        if (inside != in) ++wrong;
      }
    }
    CHECK(twice_area == 2 * cells);
  }
  return wrong;
}

}  // namespace

TEST_CASE("components are 4-connected, per class, numbered in raster order") {
  // Two convex cells touching only at a corner are two regions.
  const auto classes = grid_of({{X, P, P},
                                {P, X, P},
                                {P, P, T}});
  const RegionLabels L = connected_regions(classes, 3, 3);
  // Convex (0,0) and (1,1) are apart; the planar cells split into two
  // L-shapes that meet only at corners (around the trimmed cell).
  CHECK(L.count() == 4);
  CHECK(L.at(0, 0) == 0);
  CHECK(L.at(0, 1) == 1);
  CHECK(L.at(0, 2) == 1);
  CHECK(L.at(1, 2) == 1);
  CHECK(L.at(1, 0) == 2);
  CHECK(L.at(2, 1) == 2);
  CHECK(L.at(1, 1) == 3);
  CHECK(L.at(2, 2) == -1);  // trimmed: no region
  CHECK(L.region_class[0] == CurvatureClass::convex);
  CHECK(L.region_class[1] == CurvatureClass::planar);
  CHECK(L.region_class[2] == CurvatureClass::planar);
  CHECK(L.region_class[3] == CurvatureClass::convex);
  CHECK(L.components == std::vector<int>{1, 1, 1, 1});
}

TEST_CASE("a speck merges into the neighbour with the longest shared border") {
  // Planar left half, convex right half; a saddle speck of three cells along
  // u, two on the planar side and one on the convex side: it shares 5 cell
  // edges with planar and 3 with convex.
  const int n = 10;
  std::vector<unsigned char> classes(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) classes[i * n + j] = i < 5 ? P : X;
  classes[3 * n + 4] = classes[4 * n + 4] = classes[5 * n + 4] = S;
  const CurvatureField field = unit_field(n, n);
  RegionLabels L = connected_regions(classes, n, n);
  REQUIRE(L.count() == 3);
  const auto borders = shared_borders(L, field);
  const int speck = L.at(4, 4), planar = L.at(0, 0), convex = L.at(9, 9);
  CHECK(borders[speck].at(planar) == 5.0);
  CHECK(borders[speck].at(convex) == 3.0);
  CHECK(borders[planar].at(convex) == 9.0);  // 10 rows minus the one crossed by the speck

  const MergeReport report = merge_small_regions(L, field, 4.0);
  CHECK(report.merges == 1);
  REQUIRE(L.count() == 2);
  CHECK(L.at(4, 4) == L.at(0, 0));
  CHECK(L.at(5, 4) == L.at(0, 0));  // the convex-side cell went with the speck
  CHECK(L.region_class[static_cast<std::size_t>(L.at(5, 4))] == CurvatureClass::planar);
  CHECK(L.components[static_cast<std::size_t>(L.at(0, 0))] == 2);
  CHECK(check_loops(L) == 0);
}

TEST_CASE("merging: ties go to the lower label, isolated regions stay, chains resolve") {
  SUBCASE("tie") {
    // A one-cell speck between equal borders with region 0 (above) and 2.
    const auto classes = grid_of({{P, P, P}, {P, S, X}, {X, X, X}});
    const CurvatureField field = unit_field(3, 3);
    RegionLabels L = connected_regions(classes, 3, 3);
    const int speck = L.at(1, 1);
    const auto borders = shared_borders(L, field);
    REQUIRE(borders[speck].size() == 2);
    CHECK(borders[speck].begin()->second == std::next(borders[speck].begin())->second);
    merge_small_regions(L, field, 1.5);
    CHECK(L.at(1, 1) == L.at(0, 0));
  }
  SUBCASE("isolated by trimmed cells") {
    const auto classes = grid_of({{S, T, P, P}, {T, T, P, P}});
    const CurvatureField field = unit_field(2, 4);
    RegionLabels L = connected_regions(classes, 2, 4);
    const MergeReport r = merge_small_regions(L, field, 100.0);
    CHECK(r.isolated_small == 2);  // the speck and, once nothing is left to absorb, the planar block
    CHECK(L.count() == 2);
  }
  SUBCASE("a small region absorbing a speck can itself be absorbed") {
    // Convex speck inside a concave ring (8 cells) inside a planar sea.
    std::vector<unsigned char> classes(8 * 8, P);
    for (int i = 2; i <= 4; ++i)
      for (int j = 2; j <= 4; ++j) classes[i * 8 + j] = C;
    classes[3 * 8 + 3] = X;
    const CurvatureField field = unit_field(8, 8);
    RegionLabels L = connected_regions(classes, 8, 8);
    REQUIRE(L.count() == 3);
    merge_small_regions(L, field, 10.0);
    CHECK(L.count() == 1);
    CHECK(L.region_class[0] == CurvatureClass::planar);
    CHECK(L.components[0] == 3);
  }
}

TEST_CASE("merging conserves the total area to 1e-9 on random speckle") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cls(0, 3);
  std::uniform_real_distribution<double> size(0.2, 3.0);
  const int nu = 60, nv = 45;
  CurvatureField field = unit_field(nu, nv);
  for (CurvatureSample& s : field.samples) {
    s.area = size(rng);
    s.length_u = size(rng);
    s.length_v = size(rng);
  }
  std::vector<unsigned char> classes(static_cast<std::size_t>(nu) * nv);
  for (auto& c : classes) c = static_cast<unsigned char>(cls(rng));
  double total = 0;
  for (const CurvatureSample& s : field.samples) total += s.area;

  RegionLabels L = connected_regions(classes, nu, nv);
  const int before = L.count();
  const MergeReport r = merge_small_regions(L, field, 40.0);
  CHECK(r.initial_regions == before);
  CHECK(L.count() == before - r.merges);
  std::vector<double> area(static_cast<std::size_t>(L.count()), 0.0);
  for (std::size_t k = 0; k < L.label.size(); ++k) area[static_cast<std::size_t>(L.label[k])] += field.samples[k].area;
  double sum = 0;
  for (double a : area) {
    sum += a;
    CHECK(a >= 40.0);  // every region reached min_area (none is isolated here)
  }
  CHECK(std::fabs(sum - total) <= 1e-9 * total);
  CHECK(check_loops(L) == 0);
}

TEST_CASE("crack borders: holes, islands, pinches and the grid edge reproduce every cell") {
  SUBCASE("ring with a hole holding an island") {
    std::vector<unsigned char> classes(7 * 7, P);
    for (int i = 1; i <= 5; ++i)
      for (int j = 1; j <= 5; ++j) classes[i * 7 + j] = X;
    for (int i = 2; i <= 4; ++i)
      for (int j = 2; j <= 4; ++j) classes[i * 7 + j] = C;
    classes[3 * 7 + 3] = S;
    const RegionLabels L = connected_regions(classes, 7, 7);
    REQUIRE(L.count() == 4);
    const auto loops = trace_region_boundaries(L);
    // Planar frame: outer + hole; convex ring: outer + hole; concave ring:
    // outer + hole; saddle island: outer only.
    CHECK(loops[L.at(0, 0)].size() == 2);
    CHECK(loops[L.at(1, 1)].size() == 2);
    CHECK(loops[L.at(2, 2)].size() == 2);
    CHECK(loops[L.at(3, 3)].size() == 1);
    CHECK(loops[L.at(0, 0)][0].twice_area == 2 * 49);
    CHECK(loops[L.at(0, 0)][1].twice_area == -2 * 25);
    CHECK(check_loops(L) == 0);
  }
  SUBCASE("random labels, including diagonal pinches (labels need not be connected)") {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> label(-1, 3);
    for (int trial = 0; trial < 20; ++trial) {
      RegionLabels L;
      L.nu = 17 + trial;
      L.nv = 13;
      L.label.resize(static_cast<std::size_t>(L.nu) * L.nv);
      for (int& l : L.label) l = label(rng);
      L.region_class.assign(4, CurvatureClass::planar);
      L.components.assign(4, 1);
      CHECK(check_loops(L) == 0);
    }
  }
}
