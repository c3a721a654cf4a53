#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "job/job.hpp"
#include "job/job_options.hpp"

using namespace furrow;

namespace {

// The smallest valid job: part, tool, tool path, tolerance, output.
std::string minimal(const std::string& extra = "") {
  return R"({"part": "parts/p.json", "tool": "/abs/tool.json", "toolpath": "paths/p.nc", "tolerance": 0.05,)" + extra +
         R"( "output": "../out/x"})";
}

std::string error_of(const std::string& text) {
  try {
    parse_job(text, "job.json", "jobs");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a minimal job resolves paths against its folder and takes the commands' defaults") {
  const Job job = parse_job(minimal(), "jobs/mould.json", "jobs");
  CHECK(job.name == "mould");  // the file's stem
  CHECK(job.part == "jobs/parts/p.json");
  CHECK(job.tool == "/abs/tool.json");  // absolute stays
  REQUIRE(job.toolpath_file);
  CHECK(*job.toolpath_file == "jobs/paths/p.nc");
  CHECK_FALSE(job.generate);
  CHECK(job.output == "out/x");  // jobs/../out/x, normalised
  CHECK_FALSE(job.has_measurements());
  // Bilateral zone of width 0.05; robust scale and outlier floor follow it as in `furrow compare`.
  CHECK(job.compare.tolerance.width == 0.05);
  CHECK(job.compare.tolerance.lower() == doctest::Approx(-0.025));
  CHECK(job.compare.registration.loss_scale == 0.025);
  CHECK(job.compare.registration.outlier_floor == 0.025);
  // Everything else is the library's default.
  CHECK(job.prediction.tolerance == PathPredictionOptions{}.tolerance);
  CHECK(job.plan.probe_diameter == PlannerOptions{}.probe_diameter);
  CHECK(job.plan.min_per_region == PlannerOptions{}.min_per_region);
  CHECK(job.compare.gouges.site_margin == GougeConfirmationOptions{}.site_margin);
  CHECK(job.plan_with_prediction);
  CHECK(job.compare_with_prediction);
}

TEST_CASE("every stage's options are read into the library's option structs") {
  const Job job = parse_job(R"({
    "version": 1, "name": "n", "description": "d",
    "part": "p.json", "tool": "t.json",
    "toolpath": {"generate": {"tolerance": 0.02, "scallop": 0.01, "direction": "plane:30", "rule": "chord",
                              "max_step": 4, "clearance": 7, "feed": 500}},
    "tolerance": {"zone": 0.1, "outside": 0.1},
    "partition": {"grid": [40, 30], "eps": 0.001, "min_area": 3},
    "prediction": {"tolerance": 0.005, "gouge_threshold": 0.03, "resolution": 0.2, "cell": 2, "map_scale": 0.05},
    "plan": {"prediction": false, "points": 60, "min_per_region": 2, "strategy": "halton", "seed": 9,
             "probe_diameter": 3, "stylus_diameter": 2, "max_tilt": 60, "gouge_points": 2},
    "measurements": {"simulate": {"prediction": false, "misalign": [1, 2, 3, 4, 5, 6], "noise": 0.001,
                                  "blunders": 3, "blunder_size": [0.2, 0.5], "seed": 11, "points": "contact",
                                  "bumps": [[10, 20, 5, 4, -0.03]]}},
    "comparison": {"align": "cmm", "dof": "translation", "loss": "huber", "outlier_sigma": 4, "outlier_rejection": false,
                   "prediction": false, "probe_sigma": 0.003, "overcut_sigmas": 2, "overcut_fraction": 0.25,
                   "site_margin": 2, "contact_cluster": 3, "overcut_cluster": 6},
    "output": "o"})",
                            "job.json", "");
  CHECK(job.name == "n");
  CHECK(job.description == "d");
  REQUIRE(job.generate);
  CHECK(job.generate->contacts.forward.tolerance == 0.02);
  CHECK(job.generate->contacts.scallop == 0.01);
  CHECK(job.generate->direction.kind == PassDirection::plane);
  CHECK(job.generate->direction.angle_deg == 30);
  CHECK(job.generate->contacts.forward.rule == StepRule::chord);
  CHECK(job.generate->contacts.forward.max_step == 4);
  CHECK(job.generate->write.clearance == 7);
  CHECK(job.generate->write.feed == 500);
  CHECK(job.compare.tolerance.upper() == 0.1);  // unilateral outside
  CHECK(job.compare.tolerance.lower() == 0);
  REQUIRE(job.partition.grid);
  CHECK(job.partition.grid->nu == 40);
  CHECK(job.partition.grid->nv == 30);
  CHECK(*job.partition.eps == 0.001);
  CHECK(*job.partition.min_area == 3);
  CHECK(job.prediction.tolerance == 0.005);
  CHECK(job.prediction.gouge_threshold == 0.03);
  CHECK(job.prediction.resolution == 0.2);
  CHECK(job.prediction.map.cell_size == 2);
  CHECK(job.prediction_map_scale == 0.05);
  CHECK_FALSE(job.plan_with_prediction);
  CHECK(*job.plan.points == 60);
  CHECK(job.plan.min_per_region == 2);
  CHECK(job.plan.strategy == SamplingStrategy::halton);
  CHECK(job.plan.seed == 9);
  CHECK(job.plan.probe_diameter == 3);
  CHECK(job.plan.max_tilt_degrees == 60);
  CHECK(job.plan.gouge_points == 2);
  REQUIRE(job.simulate);
  CHECK_FALSE(job.simulate->from_prediction);
  const SimulationOptions& s = job.simulate->options;
  CHECK(s.misalignment.rotation_deg == Eigen::Vector3d(1, 2, 3));
  CHECK(s.misalignment.translation == Eigen::Vector3d(4, 5, 6));
  CHECK(s.noise_sigma == 0.001);
  CHECK(s.blunders == 3);
  CHECK(s.blunder_min == 0.2);
  CHECK(s.blunder_max == 0.5);
  CHECK(s.seed == 11);
  CHECK(s.kind == ProbePointKind::contact);
  REQUIRE(s.bumps.size() == 1);
  CHECK(s.bumps[0].centre == Eigen::Vector3d(10, 20, 5));
  CHECK(s.bumps[0].radius == 4);
  CHECK(s.bumps[0].height == -0.03);
  CHECK(job.compare.align == AlignMethod::cmm);
  CHECK(job.compare.registration.dof.to_string() == "translation");
  CHECK(job.compare.registration.loss == RobustLoss::huber);
  CHECK(job.compare.registration.outlier_sigma == 4);
  CHECK_FALSE(job.compare.registration.flag_outliers);
  CHECK_FALSE(job.compare_with_prediction);
  CHECK(job.compare.prediction.probe_sigma == 0.003);
  CHECK(job.compare.gouges.overcut_sigmas == 2);
  CHECK(job.compare.gouges.tolerance_fraction == 0.25);
  CHECK(job.compare.gouges.site_margin == 2);
  CHECK(job.compare.gouges.contact_cluster_distance == 3);
  CHECK(job.compare.gouges.overcut_cluster_distance == 6);
}

TEST_CASE("measurements and tool paths come as a file name or as an object") {
  const Job a = parse_job(minimal(R"( "measurements": "cmm/run1.csv",)"), "job.json", "jobs");
  REQUIRE(a.measurement_files.size() == 1);
  CHECK(a.measurement_files[0] == "jobs/cmm/run1.csv");
  CHECK(a.has_measurements());
  const Job b = parse_job(
      R"({"part": "p", "tool": "t", "toolpath": {"file": "x.csv", "units": "inch"}, "tolerance": {"zone": 0.02},
          "measurements": {"file": "m.dmi", "points": "contact", "probe_diameter": 4, "units": "inch"}, "output": "o"})",
      "job.json", "");
  CHECK(*b.toolpath_file == "x.csv");
  CHECK(b.toolpath_read.units == "inch");
  CHECK(b.measurement_files == std::vector<std::string>{"m.dmi"});
  CHECK(*b.measurement_read.kind == ProbePointKind::contact);
  CHECK(b.measurement_read.probe_diameter == 4);
  CHECK(b.measurement_read.units == "inch");
}

TEST_CASE("measurements: a list of files is a re-measure, merged in list order") {
  const Job a = parse_job(minimal(R"( "measurements": ["cmm/run1.csv", "cmm/remeasure.csv"],)"), "job.json", "jobs");
  CHECK(a.measurement_files == std::vector<std::string>{"jobs/cmm/run1.csv", "jobs/cmm/remeasure.csv"});
  const Job b = parse_job(minimal(R"( "measurements": {"file": ["a.csv", "b.dmo"], "units": "mm"},)"), "job.json", "");
  CHECK(b.measurement_files == std::vector<std::string>{"a.csv", "b.dmo"});
  CHECK(error_of(minimal(R"( "measurements": [],)")).find("measurements: an empty list") != std::string::npos);
  CHECK(error_of(minimal(R"( "measurements": ["a.csv", 3],)")).find("measurements[1]") != std::string::npos);
}

TEST_CASE("job errors name the file and the member") {
  CHECK(error_of(minimal(R"( "plan": {"densty": 2},)")).find("job.json: plan.densty: unknown member") == 0);
  CHECK(error_of(minimal(R"( "colour": 1,)")).find("job.json: colour: unknown member") == 0);
  CHECK(error_of(R"({"tool": "t", "toolpath": "p", "tolerance": 0.05, "output": "o"})").find("part") !=
        std::string::npos);
  CHECK(error_of(minimal(R"( "plan": {"density": -1},)")).find("job.json: plan.density") == 0);
  CHECK(error_of(minimal(R"( "plan": {"points": 5, "density": 1},)")).find("job.json: plan: --points and --density") ==
        0);
  CHECK(error_of(minimal(R"( "plan": {"prediction": false, "strategy": "risk"},)")).find("plan.strategy") !=
        std::string::npos);
  CHECK(error_of(minimal(R"( "partition": {"grid": [10, 0]},)")).find("job.json: partition.grid") == 0);
  CHECK(error_of(minimal(R"( "partition": {"grid": [10, 10], "spacing": 1},)")).find("exclude") != std::string::npos);
  CHECK(error_of(minimal(R"( "measurements": {"simulate": {"bumps": [[1, 2, 3, 0, 0.1]]}},)"))
            .find("job.json: measurements.simulate.bumps[0]: the radius must be positive") == 0);
  CHECK(error_of(minimal(R"( "measurements": {"simulate": {"misalign": [1, 2]}},)"))
            .find("measurements.simulate.misalign") != std::string::npos);
  CHECK(error_of(minimal(R"( "measurements": {"url": "x"},)")).find("job.json: measurements: expected") == 0);
  CHECK(error_of(minimal(R"( "comparison": {"overcut_fraction": 2},)")).find("comparison.overcut_fraction") !=
        std::string::npos);
  CHECK(error_of(minimal(R"( "comparison": {"dof": "sideways"},)")).find("comparison.dof") != std::string::npos);
  CHECK(error_of(minimal(R"( "comparison": {"align": "rps"},)")).find("comparison.align") != std::string::npos);
  CHECK(error_of(minimal(R"( "version": 2,)")).find("job.json: version") == 0);
  CHECK(error_of(R"({"part": "p", "tool": "t", "toolpath": {"generate": {"direction": "w"}}, "tolerance": 0.05,
                     "output": "o"})")
            .find("toolpath.generate.direction") != std::string::npos);
  CHECK(error_of(R"({"part": "p", "tool": "t", "toolpath": "p", "tolerance": {"zone": 0.05, "outside": 0.08},
                     "output": "o"})")
            .find("tolerance") != std::string::npos);
  CHECK(error_of("{\"part\": ").find("job.json") == 0);  // not JSON: line and column
}

TEST_CASE("the resolved options name every default a stage used") {
  const Job job = parse_job(minimal(R"( "measurements": {"simulate": {"seed": 3}},)"), "job.json", "");
  const nlohmann::json j = nlohmann::json::parse(job_options_json(job));
  CHECK(j["plan"]["border"] == 2.0);     // probe radius 1 + 1 mm (planner default)
  CHECK(j["plan"]["search"] == 3.0);     // = approach
  CHECK(j["plan"]["density"] == 1.0);    // kDefaultDensity
  CHECK(j["prediction"]["gouge_threshold"] == 0.02);  // twice the tolerance
  CHECK(j["prediction"]["resolution"].is_null());     // chosen from the tool and tolerance
  CHECK(j["partition"]["grid"].is_null());
  CHECK(j["measurements"]["simulate"]["seed"] == 3);
  CHECK(j["measurements"]["simulate"]["noise"] == 0.002);
  CHECK(j["comparison"]["dof"] == "all");
  CHECK(j["comparison"]["align"] == "bestfit");
  CHECK(j["tolerance"]["outside"] == 0.025);
  // Deterministic text.
  CHECK(job_options_json(job) == job_options_json(job));
}

TEST_CASE("measurements: the CSV dialect and the I++ DME program are read and checked up front") {
  const Job j = parse_job(
      minimal(R"( "measurements": {"file": "m.csv", "delimiter": "tab", "decimal_comma": true,
                                    "columns": {"id": "Name", "x": "X act", "y": "Y act", "z": "Z act"},
                                    "ipp_program": "run.prg"},)"),
      "job.json", "jobs");
  const CsvDialect& d = j.measurement_read.dialect;
  CHECK(d.delimiter == '\t');
  CHECK(d.decimal_comma == true);
  CHECK(d.columns.at("x") == "X act");
  CHECK(d.columns.size() == 4);
  CHECK(j.measurement_read.ippdme_program == "jobs/run.prg");
  CHECK(error_of(minimal(R"( "measurements": {"file": "m.csv", "delimiter": "|"},)")) ==
        "job.json: measurements.delimiter: \"|\" is not a delimiter (expected \",\", \";\", \"tab\" or \"whitespace\")");
  CHECK(error_of(minimal(R"( "measurements": {"file": "m.csv", "delimiter": ",", "decimal_comma": true},)")) ==
        "job.json: measurements: a decimal comma needs a delimiter other than ','");
  CHECK(error_of(minimal(R"( "measurements": {"file": "m.csv", "columns": {"q": "Q"}},)"))
            .find("job.json: measurements.columns.q: unknown member") == 0);
  CHECK(error_of(minimal(R"( "measurements": {"file": "m.csv", "units": "cubit"},)")).find("units") != std::string::npos);
}

TEST_CASE("the job's record: inline or a file relative to the job with errors naming the member") {
  // Inline: read with the record's own rules.
  const Job inline_job =
      parse_job(minimal(R"( "record": {"serial": "SN 7", "temperature": {"value": 68, "unit": "F"}},)"), "job.json",
                "jobs");
  REQUIRE(inline_job.record);
  CHECK(inline_job.record->serial == "SN 7");
  CHECK(inline_job.record->temperature->celsius() == doctest::Approx(20.0));
  CHECK(inline_job.record_file.empty());
  CHECK_FALSE(parse_job(minimal(), "job.json", "jobs").record);  // optional

  CHECK(error_of(minimal(R"( "record": {"serail": "SN 7"},)")) ==
        "job.json: record.serail: unknown member (see docs/formats.md \"Inspection record\")");
  CHECK(error_of(minimal(R"( "record": {"qualification_date": "2026-13-01"},)"))
            .find("job.json: record.qualification_date: ") == 0);
  CHECK(error_of(minimal(R"( "record": 3,)")).find("job.json: record: expected a record file name") == 0);

  // A file: resolved against the job's folder and read at once (a missing
  // file is refused before any work).
  const std::string folder = std::string(FURROW_SOURCE_DIR) + "/examples";
  const Job file_job = parse_job(minimal(R"( "record": "records/mould_first_article.json",)"), "job.json", folder);
  CHECK(file_job.record_file == folder + "/records/mould_first_article.json");
  REQUIRE(file_job.record);
  CHECK(file_job.record->part_number == "MOULD-100-A");
  CHECK(file_job.record->prepared.name == "J. Doe");
  CHECK(error_of(minimal(R"( "record": "no_such_record.json",)")).find("no_such_record.json") != std::string::npos);
}

TEST_CASE("pdf and paper: report.pdf on request, a4 or letter, recorded with the options") {
  const Job plain = parse_job(minimal(), "job.json", "");
  CHECK_FALSE(plain.pdf);
  CHECK(plain.paper == "a4");
  const Job job = parse_job(minimal(R"( "pdf": true, "paper": "letter",)"), "job.json", "");
  CHECK(job.pdf);
  CHECK(job.paper == "letter");
  const nlohmann::json j = nlohmann::json::parse(job_options_json(job));
  CHECK(j["pdf"] == true);
  CHECK(j["paper"] == "letter");
  CHECK(error_of(minimal(R"( "paper": "a3",)")).find("job.json: paper: expected a4 or letter") == 0);
  CHECK(error_of(minimal(R"( "pdf": "yes",)")).find("job.json: pdf") == 0);
}

TEST_CASE("prediction.stock: the raw stock box for the rapid check, echoed only when given, checked up front") {
  const Job plain = parse_job(minimal(""), "job.json", "");
  CHECK_FALSE(plain.prediction.stock);
  CHECK_FALSE(nlohmann::json::parse(job_options_json(plain))["prediction"].contains("stock"));
  const Job job = parse_job(minimal(R"( "prediction": {"stock": [-1, -2, -3, 101, 82, 30]},)"), "job.json", "");
  REQUIRE(job.prediction.stock);
  CHECK(job.prediction.stock->min() == Eigen::Vector3d(-1, -2, -3));
  CHECK(job.prediction.stock->max() == Eigen::Vector3d(101, 82, 30));
  const nlohmann::json j = nlohmann::json::parse(job_options_json(job));
  CHECK(j["prediction"]["stock"] == nlohmann::json::array({-1, -2, -3, 101, 82, 30}));
  CHECK(error_of(minimal(R"( "prediction": {"stock": [0, 0, 0, 1, 1]},)")).find("job.json: prediction.stock: expected") ==
        0);
  CHECK(error_of(minimal(R"( "prediction": {"stock": [0, 0, 5, 1, 1, 2]},)"))
            .find("job.json: prediction.stock: each min must be below its max (z)") == 0);
}

TEST_CASE("comparison.rps: the reference point system of an rps alignment, read with the job, relative to it") {
  const std::string dir = std::string(FURROW_BINARY_DIR) + "/test-scratch/job-rps";
  std::filesystem::create_directories(dir + "/jobs");
  std::ofstream(dir + "/jobs/rps.json")
      << R"({"format": "furrow-rps", "version": 1, "points": [
        {"id": "R1", "nominal": [10, 10, 0], "normal": [0, 0, -1], "directions": "z"},
        {"id": "R2", "nominal": [90, 10, 0], "normal": [0, 0, -1], "directions": "z"},
        {"id": "R3", "nominal": [50, 55, 0], "normal": [0, 0, -1], "directions": "xyz"},
        {"id": "R4", "nominal": [15, 0, 15], "normal": [0, -1, 0], "directions": "y"}]})";
  const Job job = parse_job(minimal(R"( "comparison": {"align": "rps", "rps": "rps.json"},)"), "job.json", dir + "/jobs");
  REQUIRE(job.compare.rps);
  CHECK(job.compare.rps->points.size() == 4);
  CHECK(job.compare.rps->constraints() == 6);
  CHECK(job.rps_file == dir + "/jobs/rps.json");
  const nlohmann::json echo = nlohmann::json::parse(job_options_json(job));
  CHECK(echo["comparison"]["align"] == "rps");
  CHECK(echo["comparison"]["rps"] == job.rps_file);
  CHECK(error_of(minimal(R"( "comparison": {"align": "rps"},)")).find("job.json: comparison.align: rps needs") == 0);
  std::string stray;
  try {
    parse_job(minimal(R"( "comparison": {"rps": "rps.json"},)"), "job.json", dir + "/jobs");
  } catch (const InputError& e) {
    stray = e.what();
  }
  CHECK(stray.find("job.json: comparison.rps: the reference point system is for") == 0);
}

TEST_CASE("compensate: read with compensate's option table, the command's defaults, echoed only when given") {
  const Job job = parse_job(minimal(R"("measurements": "m.csv", "compensate": {"out": "c.nc", "gain": 0.5},)"),
                            "job.json", "jobs");
  REQUIRE(job.compensate);
  CHECK(job.compensate_out == "c.nc");
  CHECK(job.compensate->gain == 0.5);
  const CompensateOptions defaults;  // what `furrow compensate` takes without the flags
  CHECK(job.compensate->max_offset == defaults.max_offset);
  CHECK(job.compensate->clip_back == defaults.clip_back);
  CHECK_FALSE(job.compensate->smoothing);
  const nlohmann::json echoed = nlohmann::json::parse(job_options_json(job));
  CHECK(echoed["compensate"]["out"] == "c.nc");
  CHECK(echoed["compensate"]["gain"].get<double>() == 0.5);
  CHECK(echoed["compensate"]["smoothing"] == "auto");
  CHECK_FALSE(nlohmann::json::parse(job_options_json(parse_job(minimal(), "job.json", "jobs"))).contains("compensate"));
  // Without measurements there is no comparison to compensate from.
  CHECK(error_of(minimal(R"("compensate": {"out": "c.nc"},)")).find("job.json: compensate: compensation needs") == 0);
}
