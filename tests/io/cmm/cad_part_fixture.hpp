#pragma once
// A part as a user brings it to the alignment planner: an OpenCASCADE shape
// written to a STEP file and imported, with its closest-point finder, the
// default probe and a clearance plane 2 mm over the part (shared by the
// alignment tests).
#include <memory>
#include <string>

#include "../cad/cad_reference.hpp"
#include "geometry/closest_point.hpp"
#include "io/cad/cad_import.hpp"
#include "planning/accessibility.hpp"
#include "support/run_cli.hpp"

namespace furrow::test {

struct CadPart {
  Part part;
  std::unique_ptr<ClosestPointFinder> finder;
  ProbeGeometry probe;
  AccessOptions access;
  // `name`: the scratch directory and the STEP file's stem.
  CadPart(const TopoDS_Shape& shape, const std::string& name) {
    const std::string path = scratch_dir(name) + "/" + name + ".step";
    write_step(shape, path);
    part = import_cad(path).part;
    finder = std::make_unique<ClosestPointFinder>(part);
    access.clearance_z = part.control_box().max().z() + probe.ball_radius + 2;
  }
};

}  // namespace furrow::test
