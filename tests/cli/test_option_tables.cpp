// The stage option tables (base/option_table.hpp) read the same value the
// same way from the command line and from a job file. The oracle for each
// option is the other reader: `--flag VALUE` through Args and {"key": VALUE}
// through JsonCursor must leave identical options, differing from the
// defaults in that one member only. Every option is also shown by its
// command's --help and the man page, and docs/options.md is what
// `furrow help --options` writes.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "base/error.hpp"
#include "base/json_cursor.hpp"
#include "base/number_text.hpp"
#include "cli/option_flags.hpp"
#include "stage/compare_options.hpp"
#include "stage/compensate_options.hpp"
#include "stage/partition_options.hpp"
#include "stage/plan_options.hpp"
#include "stage/prediction_options.hpp"
#include "stage/results_options.hpp"
#include "stage/scan_options.hpp"
#include "stage/scan_simulation_options.hpp"
#include "stage/simulation_options.hpp"
#include "stage/toolpath_options.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using nlohmann::json;

namespace {

// A valid value other than the default, as command-line text: the table's
// example, else made from the written default.
std::string sample_text(const OptionDoc& doc, const std::string& example, const json& written_default) {
  if (!example.empty()) return example;
  switch (doc.kind) {
    case OptionKind::number: {
      if (written_default.is_null()) return "7.25";
      const double d = written_default.get<double>();
      return shortest(d > 0 && d <= 1 ? d / 2 : d + 1.5);
    }
    case OptionKind::integer:
      return written_default.is_null() ? "7" : std::to_string(written_default.get<long>() + 3);
    case OptionKind::text:
      return written_default.get<std::string>() + "X";
    case OptionKind::toggle:
    case OptionKind::numbers:  // every list option has its example
      return "";
  }
  return "";
}

// The same value as a job file holds it.
json sample_json(const OptionDoc& doc, const std::string& text, const json& written_default) {
  switch (doc.kind) {
    case OptionKind::number:
      return std::stod(text);
    case OptionKind::integer:
      return std::stol(text);
    case OptionKind::text:
      return text;
    case OptionKind::toggle:
      return !written_default.get<bool>();
    case OptionKind::numbers: {
      json list = json::array();
      std::stringstream items(text);
      for (std::string item; std::getline(items, item, ',');) list.push_back(std::stod(item));
      return list;
    }
  }
  return nullptr;
}

template <class Options>
json from_command_line(const OptionTable<Options>& table, std::vector<std::string> words) {
  cli::Args args("test", std::move(words));
  Options o;
  cli::read_option_flags(args, table, o);
  args.finish();
  return option_members(table, o);
}

template <class Options>
json from_job(const OptionTable<Options>& table, const json& section) {
  const JsonCursor cursor(section, "job.json: section");
  Options o;
  read_option_members(cursor, table, o);
  cursor.finish("docs/options.md");
  return option_members(table, o);
}

template <class Options>
void check_both_readers_agree(const OptionTable<Options>& table) {
  const std::vector<OptionDoc> docs = describe(table);
  const json defaults = option_members(table, Options{});
  REQUIRE(docs.size() == table.size());
  for (std::size_t k = 0; k < table.size(); ++k) {
    const OptionDoc& doc = docs[k];
    const std::string key = doc.key;
    CAPTURE(key);
    const std::string text = sample_text(doc, table[k].example, defaults[key]);
    std::vector<std::string> words = {doc.flag};
    if (doc.kind != OptionKind::toggle) words.push_back(text);
    const json cli = from_command_line(table, words);
    const json job = from_job(table, json{{key, sample_json(doc, text, defaults[key])}});
    CHECK(cli == job);
    CHECK(cli[key] != defaults[key]);
    // Nothing else moved, but for the defaults resolved from others (the
    // border from the probe, the search from the approach, ...).
    for (std::size_t j = 0; j < table.size(); ++j) {
      const std::string& other = table[j].key;
      if (other != key && table[j].default_text.empty()) CHECK(cli[other] == defaults[other]);
    }
  }
  // What the writer writes reads back to the same options.
  CHECK(from_job(table, defaults) == defaults);
}

template <class Options>
std::string error_of(const OptionTable<Options>& table, const std::vector<std::string>& words) {
  try {
    from_command_line(table, words);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

template <class Options>
std::string job_error_of(const OptionTable<Options>& table, const json& section) {
  try {
    from_job(table, section);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("every plan option reads the same from the command line and from a job file") {
  check_both_readers_agree(plan_option_table());
}

TEST_CASE("every comparison option reads the same from the command line and from a job file") {
  check_both_readers_agree(compare_option_table());
}

TEST_CASE("every partition, tool-path, prediction and simulation option reads the same both ways") {
  check_both_readers_agree(partition_option_table());
  check_both_readers_agree(toolpath_option_table());
  check_both_readers_agree(prediction_option_table());
  check_both_readers_agree(simulation_option_table());
  check_both_readers_agree(scan_simulation_option_table());
}

TEST_CASE("every compensation option reads the same both ways, and a gain above 2 is refused by both") {
  check_both_readers_agree(compensate_option_table());
  const auto& table = compensate_option_table();
  CHECK(error_of(table, {"--gain", "2.5"}).find("--gain: must be in (0, 2]") != std::string::npos);
  CHECK(job_error_of(table, json{{"gain", 2.5}}).find("section.gain: must be in (0, 2]") != std::string::npos);
  CHECK(error_of(table, {"--gain", "0"}).find("--gain") != std::string::npos);
  CHECK(error_of(table, {"--smoothing", "-3"}).find("positive length") != std::string::npos);
  CHECK(from_command_line(table, {"--smoothing", "auto"}) == from_job(table, json::object()));
}

TEST_CASE("a renamed flag is still taken, once") {
  const auto& sim = simulation_option_table();
  CHECK(from_command_line(sim, {"--outliers", "4"}) == from_command_line(sim, {"--blunders", "4"}));
  CHECK(from_command_line(sim, {"--outlier-size", "0.2,0.4"}) == from_command_line(sim, {"--blunder-size", "0.2,0.4"}));
  CHECK(error_of(sim, {"--outliers", "4", "--blunders", "4"}).find("given twice") != std::string::npos);
  // The command line's older spelling of a step rule reads as the job file's.
  const auto& path = toolpath_option_table();
  CHECK(from_command_line(path, {"--rule", "circular-arc"}) == from_job(path, json{{"rule", "circular_arc"}}));
}

TEST_CASE("both readers refuse a bad value and name where it came from") {
  const auto& plan = plan_option_table();
  const auto& compare = compare_option_table();
  struct Bad {
    std::string key;
    std::string text;
    json value;
    std::string says;
  };
  const std::vector<Bad> plan_cases = {
      {"probe_diameter", "-1", -1, "must be positive"},
      {"probe_diameter", "0", 0, "must be positive"},
      {"clearance", "-1e-300", -1e-300, "must not be negative"},
      {"min_per_region", "-1", -1, "must be at least 0"},
      {"points", "0", 0, "must be at least 1"},
      {"gouge_points", "2.5", 2.5, "integer"},
      {"strategy", "sobol", "sobol", "sobol"},
      {"seed", "1e308", 1e308, "integer"},
  };
  for (const Bad& b : plan_cases) {
    CAPTURE(b.key);
    const std::string cli = error_of(plan, {option_flag(b.key), b.text});
    CHECK(cli.find(option_flag(b.key)) != std::string::npos);
    CHECK(cli.find(b.says) != std::string::npos);
    const std::string job = job_error_of(plan, json{{b.key, b.value}});
    CHECK(job.find("section." + b.key) != std::string::npos);
    CHECK(job.find(b.says) != std::string::npos);
  }
  // A value that is not a number at all, and one beyond double range.
  CHECK(error_of(plan, {"--approach", "nan"}).find("--approach") != std::string::npos);
  CHECK(error_of(plan, {"--approach", "1e999"}).find("--approach") != std::string::npos);
  CHECK(job_error_of(plan, json{{"approach", "3"}}).find("section.approach") != std::string::npos);
  // A fraction above one, on both sides.
  CHECK(error_of(compare, {"--overcut-fraction", "1.5"}).find("between 0 and 1") != std::string::npos);
  CHECK(job_error_of(compare, json{{"overcut_fraction", 1.5}}).find("between 0 and 1") != std::string::npos);
  CHECK(job_error_of(compare, json{{"outlier_rejection", "no"}}).find("true or false") != std::string::npos);
  // A member no table knows is refused by the section's finish().
  CHECK(job_error_of(compare, json{{"outlier_sigmas", 4}}).find("unknown member") != std::string::npos);
}

TEST_CASE("every table option is in its command's help, in the man page and in docs/options.md") {
  const test::CliResult reference = test::run_furrow({"help", "--options"});
  REQUIRE(reference.status == 0);
  CHECK(reference.out == text_file(test::source_path("docs/options.md")));
  const test::CliResult man = test::run_furrow({"help", "--man"});
  REQUIRE(man.status == 0);
  const auto check = [&](const std::string& command, const std::vector<OptionDoc>& docs) {
    const test::CliResult help = test::run_furrow({command, "--help"});
    REQUIRE(help.status == 0);
    for (const OptionDoc& d : docs) {
      CAPTURE(d.flag);
      CHECK(help.out.find("\n  " + d.flag) != std::string::npos);
      std::string troff;
      for (char c : d.flag) troff += c == '-' ? std::string("\\-") : std::string(1, c);
      CHECK(man.out.find(troff) != std::string::npos);
      CHECK(reference.out.find("| `" + d.key + "` | `" + d.flag) != std::string::npos);
    }
  };
  check("partition", describe(partition_option_table()));
  check("toolpath", describe(toolpath_option_table()));
  check("predict", describe(prediction_option_table()));
  check("simulate-measurement", describe(simulation_option_table()));
  check("simulate-measurement", describe(scan_simulation_option_table()));
  check("plan", describe(plan_option_table()));
  check("compare", describe(compare_option_table()));
  check("remeasure", describe(only_options(plan_option_table(), kProbeMotionKeys)));
  check("compensate", describe(compensate_option_table()));
  check("compare", describe(results_storage_option_table()));
  check("compare", describe(scan_option_table()));
  check("run", describe(results_storage_option_table()));
}
