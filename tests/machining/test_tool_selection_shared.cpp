// Shared interference verdicts of tool selection (docs/tool_selection.md):
// the nesting rule against sampled cutter geometry, and the shared selection
// against the exhaustive one (every tool's own search) on the mould example
// and on a random part and tool set, with every difference checked by a
// brute-force drop cutter.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "io/part_file.hpp"
#include "io/machining/tool_file.hpp"
#include "machining/gouge/tool_selection.hpp"
#include "support/run_cli.hpp"

#include <nlohmann/json.hpp>

using namespace furrow;

namespace {

// Uniform in [lo, hi) from the raw generator (std distributions differ
// between standard libraries; the raw mt19937 sequence does not).
double uniform(std::mt19937& rng, double lo, double hi) {
  return lo + (hi - lo) * (rng() / 4294967296.0);
}

// Whether x lies in the cutter with its tip at T (the solid under the
// envelope: within R of the axis and not below the lower envelope).
bool inside(const Cutter& c, const Eigen::Vector3d& T, const Eigen::Vector3d& x, double slack) {
  const double rho = (x.head<2>() - T.head<2>()).norm();
  if (rho > c.radius() + slack) return false;
  // At the rim the envelope's height is r (height_at's R - (R - r) may round
  // above r and read as off the cutter).
  const double envelope = rho >= c.radius() - slack ? c.corner_radius() : c.height_at(rho);
  return x.z() - T.z() >= envelope - slack;
}

// Points of the cutter's lower envelope and of its shank up to 2R above the
// tip, located at tip T: rings at the profile's contact angles and heights.
std::vector<Eigen::Vector3d> surface_samples(const Cutter& c, const Eigen::Vector3d& T) {
  std::vector<Eigen::Vector3d> out;
  const int around = 72;
  auto ring = [&](double rho, double h) {
    for (int k = 0; k < around; ++k) {
      const double phi = 2 * M_PI * k / around;
      out.push_back(T + Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), h));
    }
  };
  for (int i = 0; i <= 8; ++i) ring(c.flat_radius() * i / 8, 0);  // the flat bottom
  for (int i = 0; i <= 24; ++i) {                                  // the corner arc
    const double theta = 0.5 * M_PI * i / 24;
    ring(c.flat_radius() + c.corner_radius() * std::sin(theta),
         c.corner_radius() * (1 - std::cos(theta)));
  }
  for (int i = 0; i <= 8; ++i) ring(c.radius(), c.corner_radius() + 2 * c.radius() * i / 8);  // shank
  return out;
}

// Contact normals from straight up to horizontal, several azimuths.
std::vector<Eigen::Vector3d> test_normals() {
  std::vector<Eigen::Vector3d> out;
  for (const double theta : {0.0, 0.3, 0.8, 1.2, 1.5, 0.5 * M_PI})
    for (const double phi : {0.0, 1.0, 2.5, 4.0}) {
      out.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      if (theta == 0) break;
    }
  return out;
}

// Lower bound on how far the cutter with its tip at T cuts into the face
// (its true rest height minus T.z, by sampling the face): > 0 proves it
// cuts in by at least that.
double sampled_cut_in(const Face& face, const Cutter& c, const Eigen::Vector3d& T, int n) {
  const ParameterDomain& d = face.domain();
  double best = -1e300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = d.u0 + (d.u1 - d.u0) * i / n, v = d.v0 + (d.v1 - d.v0) * j / n;
      if (!face.contains(u, v)) continue;
      const Eigen::Vector3d q = face.surface().point(u, v);
      const double rho = (q.head<2>() - T.head<2>()).norm();
      if (rho <= c.radius()) best = std::max(best, q.z() - c.height_at(rho) - T.z());
    }
  return best;
}

// The tip the selection uses for `cutter` at a site.
Eigen::Vector3d located_tip(const Part& part, const Cutter& cutter, const ContactSite& site) {
  const BorderLocator locator(part);
  const ContactSurfaces surfaces = contact_surfaces(locator, site.face, site.uv);
  const LocalGouge g = check_contact(cutter, surfaces);
  CutterLocationOptions placed;
  placed.horizontal_side = g.cutter.toward_axis;
  return cutter_location(cutter, surfaces.geometry.point, g.cutter.normal, placed).tip;
}

// The shared selection against the exhaustive one: every per-site result
// equal; a verdict differs only as exhaustive "interferes", shared "clear",
// where a container was reported clear, and the brute-force drop cutter
// shows that container does cut in there (the exhaustive search missed it).
// Returns the number of differing verdicts.
std::size_t compare_with_exhaustive(const Part& part, const std::vector<Cutter>& library,
                                    const std::vector<ContactSite>& sites) {
  ToolSelectionOptions exhaustive_options, shared_options;
  exhaustive_options.share_interference = false;
  shared_options.share_interference = true;
  const ToolSelection full = select_tools(part, library, sites, exhaustive_options);
  const ToolSelection shared = select_tools(part, library, sites, shared_options);
  REQUIRE(shared.library.size() == full.library.size());
  const std::size_t tools = full.library.size();
  CHECK(shared.whole_surface == full.whole_surface);
  CHECK(shared.without_tool == full.without_tool);
  CHECK(shared.unmachinable == full.unmachinable);
  CHECK(shared.interference_searches < full.interference_searches);
  REQUIRE(shared.sites.size() == full.sites.size());
  for (std::size_t k = 0; k < full.sites.size(); ++k) {
    const SiteSelection &a = full.sites[k], &b = shared.sites[k];
    CAPTURE(k);
    CHECK(a.tool == b.tool);
    CHECK(a.machinable == b.machinable);
    CHECK(a.smallest_gouges_locally == b.smallest_gouges_locally);
    CHECK(a.interference == b.interference);
    CHECK(a.needed.excess == b.needed.excess);
    CHECK(a.needed.design_curvature == b.needed.design_curvature);
  }
  std::size_t differing = 0;
  for (std::size_t t = 0; t < tools; ++t) {
    CHECK(shared.gouging_sites[t] <= full.gouging_sites[t]);
    CHECK(full.gouging_sites[t] - shared.gouging_sites[t] ==
          full.interfering_sites[t] - shared.interfering_sites[t]);
  }
  for (std::size_t k = 0; k < full.sites.size(); ++k) {
    for (std::size_t t = 0; t < tools; ++t) {
      const ToolVerdict a = full.verdicts[k * tools + t], b = shared.verdicts[k * tools + t];
      if (a == b) continue;
      ++differing;
      CAPTURE(k);
      CAPTURE(full.library[t].name());
      CHECK(a == ToolVerdict::interferes);
      CHECK(b == ToolVerdict::clear);
      // The container the exhaustive search cleared, which the brute force shows cutting in.
      double deepest = -1e300;
      for (std::size_t o = 0; o < t; ++o) {
        if (!cutter_contains(full.library[o], full.library[t]) || full.verdicts[k * tools + o] != ToolVerdict::clear)
          continue;
        const Cutter& outer = full.library[o];
        const Face& face = part.faces[sites[k].face];
        deepest = std::max(deepest, sampled_cut_in(face, outer, located_tip(part, outer, sites[k]), 1200));
      }
      CHECK(deepest > 10 * ToolSelectionOptions().interference_tolerance);
    }
  }
  return differing;
}

}  // namespace

TEST_CASE("cutter_contains: the inner cutter, located at the same contact, lies inside the outer one") {
  std::vector<Cutter> tools;
  for (const ToolSpec& t : read_tool_library(test::source_path("examples/tools/library.json"))) tools.emplace_back(t);
  std::mt19937 rng(20261125);
  for (int i = 0; i < 8; ++i) {
    const double R = uniform(rng, 0.5, 8);
    tools.emplace_back("random" + std::to_string(i), R, uniform(rng, 0, R));
  }
  const Eigen::Vector3d P(1.5, -2, 3);
  int contained = 0, separate = 0;
  for (const Cutter& outer : tools) {
    for (const Cutter& inner : tools) {
      if (&outer == &inner) continue;
      bool all_inside = true;
      for (const Eigen::Vector3d& n : test_normals()) {
        const Eigen::Vector3d Ti = cutter_location(inner, P, n).tip, To = cutter_location(outer, P, n).tip;
        for (const Eigen::Vector3d& x : surface_samples(inner, Ti)) all_inside &= inside(outer, To, x, 1e-9);
      }
      CAPTURE(outer.name());
      CAPTURE(inner.name());
      CHECK(cutter_contains(outer, inner) == all_inside);
      (all_inside ? contained : separate) += 1;
    }
  }
  CHECK(contained > 100);  // both answers are exercised
  CHECK(separate > 100);
}

TEST_CASE("shared interference verdicts on the mould example: every per-site result and per-tool verdict of the exhaustive run, fewer searches") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  std::vector<Cutter> library;
  for (const ToolSpec& t : read_tool_library(test::source_path("examples/tools/library.json"))) library.emplace_back(t);
  // The bounded search proves each clear verdict, so nothing differs (the
  // seeded search alone left one verdict per grid to the sharing).
  for (const int n : {30, 57}) {
    CAPTURE(n);
    CHECK(compare_with_exhaustive(part, library, grid_sites(part, n)) == 0);
  }
}

TEST_CASE("shared interference verdicts on a random bumpy part and tool set (fixed seed): the exhaustive per-site results") {
  std::mt19937 rng(7);
  const int m = 9;  // bicubic, 9 x 9 control points over 60 x 60 mm
  std::vector<std::vector<Eigen::Vector3d>> net(m, std::vector<Eigen::Vector3d>(m));
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) net[i][j] = {60.0 * i / (m - 1), 60.0 * j / (m - 1), uniform(rng, -4, 4)};
  std::vector<double> knots = {0, 0, 0, 0};
  for (int k = 1; k <= m - 4; ++k) knots.push_back(double(k) / (m - 3));
  knots.insert(knots.end(), {1, 1, 1, 1});
  Part part;
  part.faces.emplace_back("bumps", NurbsSurface(3, 3, knots, knots, net));
  std::vector<Cutter> library;
  for (int i = 0; i < 14; ++i) {
    const double R = uniform(rng, 1, 9);
    const double kind = uniform(rng, 0, 3);  // ball, flat or bull-nose
    const double r = kind < 1 ? R : kind < 2 ? 0 : uniform(rng, 0.2, 0.8) * R;
    library.emplace_back("T" + std::to_string(i), R, r);
  }
  const std::size_t differing = compare_with_exhaustive(part, library, grid_sites(part, 24));
  MESSAGE("random part, 24 x 24 grid: " << differing << " verdicts differ");
}

TEST_CASE("furrow select-tool shares interference verdicts by default, --no-share-interference searches for every tool") {
  const std::string dir = test::scratch_dir("select_tool_shared");
  const std::string part = test::source_path("examples/parts/two_face.json");
  const std::string library = test::source_path("examples/tools/library.json");
  const auto plain = test::run_furrow({"select-tool", part, "--library", library, "--grid", "12", "--out",
                                       dir + "/plain.json", "--no-share-interference"});
  const auto shared = test::run_furrow({"select-tool", part, "--library", library, "--grid", "12", "--out",
                                        dir + "/shared.json"});
  const auto both = test::run_furrow({"select-tool", part, "--library", library, "--grid", "12",
                                      "--share-interference", "--no-share-interference"});
  CHECK(both.status == 2);
  CHECK(plain.status == shared.status);
  const auto a = nlohmann::json::parse(test::slurp(dir + "/plain.json"));
  const auto b = nlohmann::json::parse(test::slurp(dir + "/shared.json"));
  CHECK_FALSE(a.contains("interference_shared"));
  CHECK(b.at("interference_shared") == true);
  CHECK(a.at("points") == b.at("points"));
  CHECK(a.at("whole_surface") == b.at("whole_surface"));
  CHECK(a.at("tools") == b.at("tools"));
}
