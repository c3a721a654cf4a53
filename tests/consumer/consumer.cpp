// Uses only installed public headers: a cylinder of radius 25 built as an
// exact rational NURBS must show principal curvatures 0 and -1/25 (convex,
// normal out of the material) at every sampled point; and, given a STEP file
// that holds no shape, import_cad() must reach the installed CAD module and
// refuse the file for it (an InputError from OpenCASCADE's reading, not a
// module that could not be found). Exits 0 when both hold.
#include <cmath>
#include <cstdio>
#include <string>

#include <furrow/base/error.hpp>
#include <furrow/geometry/differential_geometry.hpp>
#include <furrow/geometry/primitives.hpp>
#include <furrow/io/cad/cad_import.hpp>

int main(int argc, char** argv) {
  if (argc > 1) {
    try {
      furrow::import_cad(argv[1]);
      std::printf("consumer: %s was imported, but it holds no shape\n", argv[1]);
      return 1;
    } catch (const furrow::InputError& e) {
      const bool read = std::string(e.what()).find("no shape to import") != std::string::npos;
      std::printf("consumer: the CAD module read %s: %s\n", argv[1], e.what());
      if (!read) return 1;
    } catch (const std::exception& e) {
      std::printf("consumer: the CAD import failed: %s\n", e.what());
      return 1;
    }
  }
  const double radius = 25.0;
  const furrow::NurbsSurface cylinder = furrow::make_cylinder(radius, 40.0, 0.0, 2.0);
  int bad = 0;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      const double u = cylinder.domain().u0 + (cylinder.domain().u1 - cylinder.domain().u0) * i / 4.0;
      const double v = cylinder.domain().v0 + (cylinder.domain().v1 - cylinder.domain().v0) * j / 4.0;
      const furrow::DifferentialGeometry g = furrow::differential_geometry(cylinder, u, v, false);
      const double k_round = std::abs(g.k1) > std::abs(g.k2) ? g.k1 : g.k2;
      const double k_flat = std::abs(g.k1) > std::abs(g.k2) ? g.k2 : g.k1;
      if (std::abs(std::abs(k_round) - 1 / radius) > 1e-12 || std::abs(k_flat) > 1e-12) ++bad;
    }
  std::printf("furrow %s consumer: %d of 25 points off the analytic curvature\n", FURROW_VERSION, bad);
  return bad == 0 ? 0 : 1;
}
