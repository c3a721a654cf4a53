// Strict CAD import (docs/formats.md "CAD import"): an entity OpenCASCADE
// cannot read is an error naming it; --skip-bad-faces leaves it out with one
// warning line.
#include <doctest/doctest.h>

#include <BRepPrimAPI_MakeBox.hxx>

#include <filesystem>
#include <string>

#include "base/error.hpp"
#include "io/cad/cad_import.hpp"
#include "io/cad/cad_reference.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// A 10 x 20 x 30 box written by OpenCASCADE, its first ADVANCED_FACE
// misspelt; returns the path and the misspelt entity's id ("#17").
std::string broken_box(const std::string& dir, std::string& entity_id) {
  write_step(BRepPrimAPI_MakeBox(10, 20, 30).Shape(), dir + "/box.step");
  std::string text = slurp(dir + "/box.step");
  const auto pos = text.find("= ADVANCED_FACE(");
  REQUIRE(pos != std::string::npos);
  const auto line_start = text.rfind('\n', pos) + 1;
  entity_id = text.substr(line_start, text.find(' ', line_start) - line_start);
  text.replace(pos, 15, "= ADVANCED_FACX");
  write_text(dir + "/bad.step", text);
  return dir + "/bad.step";
}

}  // namespace

TEST_CASE("CAD import: a misspelt ADVANCED_FACE is an error naming the entity, not a silent 5-face box") {
  const std::string dir = scratch_dir("cad-strict");
  std::string entity_id;
  const std::string path = broken_box(dir, entity_id);
  REQUIRE(entity_id.rfind("#", 0) == 0);
  // The intact box has 6 faces.
  CHECK(import_cad(dir + "/box.step").part.faces.size() == 6);

  std::string message;
  try {
    import_cad(path);
  } catch (const InputError& e) {
    message = e.what();
  }
  CAPTURE(message);
  CHECK(message.rfind(path + ": entity " + entity_id + " (\"ADVANCED_FACX\")", 0) == 0);

  CadImportOptions skip;
  skip.skip_bad_faces = true;
  const CadImportResult result = import_cad(path, skip);
  CHECK(result.part.faces.size() == 5);
  REQUIRE(result.skipped.size() == 1);
  CHECK(result.skipped[0].entity.find(entity_id) != std::string::npos);
}

TEST_CASE("CAD import: furrow import refuses the broken box, --skip-bad-faces warns once per face") {
  const std::string dir = scratch_dir("cad-strict-cli");
  std::string entity_id;
  const std::string path = broken_box(dir, entity_id);
  const CliResult strict = run_furrow({"import", path, "--out", dir + "/part.json"});
  CHECK(strict.status == 2);
  CHECK(line_count(strict.err) == 1);
  CHECK(strict.err.find(entity_id) != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/part.json"));

  const CliResult lenient = run_furrow({"import", path, "--out", dir + "/part.json", "--skip-bad-faces"});
  CHECK(lenient.status == 0);
  CHECK(line_count(lenient.err) == 1);
  CHECK(lenient.err.rfind("warning: " + path + ": entity " + entity_id, 0) == 0);
  REQUIRE(std::filesystem::exists(dir + "/part.json"));
  const CliResult info = run_furrow({"info", dir + "/part.json", "--json", "--grid", "10"});
  CHECK(info.out.find("\"face_count\": 5") != std::string::npos);
}
