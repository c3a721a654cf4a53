// The inspection record: checked up front (every error names the member),
// shown escaped in the report header, carried into report.json and
// results.qif, the sign-off block in the page.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "io/qif/qif_points_reader.hpp"
#include "io/qif/qif_schema.hpp"
#include "report/inspection_record.hpp"
#include "report/qa_report.hpp"
#include "report_fixture.hpp"

using namespace furrow;
using nlohmann::json;

namespace {

const test::ReportFixture& fixture() {
  static const test::ReportFixture f = test::make_report_fixture();
  return f;
}

const char* kFull = R"({
  "part_number": "M-100-A", "revision": "C", "serial": "SN 0042", "lot": "L7",
  "customer": "Acme <Moulds> & Sons", "operator": "J. O'Neil", "cmm": "Contura 7/10/6",
  "probe": "2 mm ruby, 40 mm stylus", "qualification_date": "2026-11-24",
  "temperature": {"value": 20.4, "unit": "C"}, "program": "mould_v3.dmi",
  "notes": "First article.\nFixture B.",
  "sign_off": {"prepared": {"name": "A. Prep", "date": "2026-11-25"},
               "checked": {"name": "B. Check"}, "approved": {"date": "2026-11-26T09:30Z"}}
})";

std::string error_of(const std::string& text) {
  try {
    parse_inspection_record(text, "record.json:");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

const std::string& file(const std::vector<FolderFile>& files, const std::string& path) {
  for (const FolderFile& f : files)
    if (f.path == path) return f.bytes;
  FAIL("no " << path);
  throw std::logic_error("unreachable");
}

ReportContext context_with(const std::optional<InspectionRecord>& record) {
  ReportContext c;
  c.title = "record";
  c.generated = "2026-11-25T12:00:00Z";
  c.inputs.push_back(digest_generated("comparison", "comparison.json", "{}"));
  c.record = record;
  return c;
}

}  // namespace

TEST_CASE("a full record is read member by member") {
  const InspectionRecord r = parse_inspection_record(kFull, "record.json:");
  CHECK(r.part_number == "M-100-A");
  CHECK(r.serial == "SN 0042");
  CHECK(r.operator_name == "J. O'Neil");
  REQUIRE(r.temperature);
  CHECK(r.temperature->value == 20.4);
  CHECK(r.temperature->unit == "C");
  CHECK(r.notes == "First article.\nFixture B.");
  CHECK(r.prepared.name == "A. Prep");
  CHECK(r.checked.date.empty());
  CHECK(r.approved.date == "2026-11-26T09:30Z");
  CHECK(r.fields().size() == 12);  // every field filled
  CHECK(parse_inspection_record(R"({"serial": "", "lot": null})", "r:").fields().empty());
}

TEST_CASE("a bad record is refused naming the member") {
  CHECK(error_of(R"({"serail": "1"})") == "record.json: serail: unknown member (see docs/formats.md \"Inspection record\")");
  CHECK(error_of(R"({"sign_off": {"reviewed": {}}})").find("record.json: sign_off.reviewed: unknown member") == 0);
  CHECK(error_of(R"({"sign_off": {"checked": {"nam": "x"}}})").find("sign_off.checked.nam: unknown") != std::string::npos);
  CHECK(error_of(R"({"serial": 42})").find("record.json: serial") == 0);
  CHECK(error_of("{\"operator\": \"" + std::string(201, 'x') + "\"}").find("longer than 200 characters") !=
        std::string::npos);
  CHECK(error_of("{\"operator\": \"" + std::string(200, 'x') + "\"}") == "(accepted)");
  CHECK(error_of(R"({"operator": "a\nb"})").find("record.json: operator: a control character") == 0);
  CHECK(error_of(R"({"notes": "a\nb\tc"})") == "(accepted)");
  CHECK(error_of(R"({"notes": "a\u0007"})").find("record.json: notes") == 0);
  CHECK(error_of(R"({"qualification_date": "2026-02-29"})").find("record.json: qualification_date") == 0);
  CHECK(error_of(R"({"qualification_date": "2024-02-29"})") == "(accepted)");  // a leap year
  CHECK(error_of(R"({"qualification_date": "25.11.2026"})").find("not an ISO 8601 date") != std::string::npos);
  CHECK(error_of(R"({"sign_off": {"approved": {"date": "2026-11-25T24:00"}}})")
            .find("sign_off.approved.date") != std::string::npos);
  CHECK(error_of(R"({"temperature": 20})").find("record.json: temperature") == 0);
  CHECK(error_of(R"({"temperature": {"value": 20}})").find("temperature.unit: missing") != std::string::npos);
  CHECK(error_of(R"({"temperature": {"value": 20, "unit": "degC"}})").find("not a temperature unit") !=
        std::string::npos);
  CHECK(error_of(R"({"temperature": {"value": 293.15, "unit": "C"}})").find("outside -50..100 degC") !=
        std::string::npos);
  CHECK(error_of(R"({"temperature": {"value": 293.15, "unit": "K"}})") == "(accepted)");
  // Beyond a double: refused as JSON, naming the file once.
  CHECK(error_of(R"({"temperature": {"value": 1e400, "unit": "C"}})").find("record.json: not valid JSON") == 0);
  CHECK(error_of(R"({"serial": "S")").find("record.json: line 1, column") == 0);
  CHECK(error_of(R"({"temperature": {"value": 68, "unit": "F", "at": 1}})").find("temperature.at: unknown") !=
        std::string::npos);
  CHECK(error_of("[]").find("record.json:") == 0);
  CHECK(error_of("{\"serial\": \"\xff\"}").find("record.json") == 0);  // not UTF-8
}

TEST_CASE("ISO 8601 dates: calendar checked with time and offset optional") {
  for (const char* good : {"2026-11-25", "2000-02-29", "2026-11-25T14:30", "2026-11-25T14:30:59Z",
                           "2026-11-25T14:30+01:00", "2026-11-25T00:00:00-05:30"})
    CHECK_MESSAGE(is_iso8601_date(good), good);
  for (const char* bad : {"", "2026-1-25", "1900-02-29", "2026-13-01", "2026-04-31", "2026-11-25 14:30",
                          "2026-11-25T14", "2026-11-25T14:60", "2026-11-25T14:30:00ZZ", "2026-11-25T14:30+1",
                          "2026-11-25x"})
    CHECK_MESSAGE(!is_iso8601_date(bad), bad);
}

TEST_CASE("the record is in the report header escaped and in report.json and results.qif and the sign-off block") {
  const test::ReportFixture& f = fixture();
  const InspectionRecord record = parse_inspection_record(kFull, "record.json:");
  const std::vector<FolderFile> files = make_report(f.doc, f.part, nullptr, context_with(record));
  const std::string& html = file(files, "report.html");
  const std::size_t header = html.find("<header>"), header_end = html.find("</header>");
  const std::size_t grid = html.find("id=\"record\"");
  CHECK(grid > header);
  CHECK(grid < header_end);
  CHECK(html.find("Acme &lt;Moulds&gt; &amp; Sons") != std::string::npos);
  CHECK(html.find("Acme <Moulds>") == std::string::npos);
  CHECK(html.find("J. O&#39;Neil") != std::string::npos);
  CHECK(html.find("20.4 degC") != std::string::npos);
  CHECK(html.find("record-absent") == std::string::npos);
  // Sign-off: one row per role with the given names and dates.
  const std::size_t signoff = html.find("<section id=\"signoff\">");
  REQUIRE(signoff != std::string::npos);
  CHECK(html.find("<tr><th>Prepared</th><td>A. Prep</td><td>2026-11-25</td>", signoff) != std::string::npos);
  CHECK(html.find("<tr><th>Checked</th><td>B. Check</td><td></td>", signoff) != std::string::npos);
  CHECK(html.find("<tr><th>Approved</th><td></td><td>2026-11-26T09:30Z</td>", signoff) != std::string::npos);

  const json report = json::parse(file(files, "report.json"));
  CHECK(report["record"]["part_number"] == "M-100-A");
  CHECK(report["record"]["customer"] == "Acme <Moulds> & Sons");
  CHECK(report["record"]["temperature"]["value"].get<double>() == 20.4);
  CHECK(report["record"]["temperature"]["unit"] == "C");
  CHECK(report["record"]["sign_off"]["checked"] == json({{"name", "B. Check"}}));
  CHECK(report["record"].size() == 13);  // 12 fields + sign_off

  const std::string& qif = file(files, "results.qif");
  test::check_qif_valid(qif, test::scratch_dir("record-qif") + "/results.qif");  // docs/qif.md "Validity"
  CHECK(qif.find("<InspectionOperator>\n            <Name>J. O'Neil</Name>") != std::string::npos);
  // QIF's CustomerOrganization and InspectionProgram require a customer
  // number, a program standard and author: customer and program are attributes.
  CHECK(qif.find("<AttributeStr name=\"customer\" value=\"Acme &lt;Moulds&gt; &amp; Sons\"/>") != std::string::npos);
  CHECK(qif.find("<CustomerOrganization>") == std::string::npos);
  CHECK(qif.find("<ReportPreparer>\n            <Name>A. Prep</Name>") != std::string::npos);
  CHECK(qif.find("<AttributeStr name=\"serial\" value=\"SN 0042\"/>") != std::string::npos);
  CHECK(qif.find("<AttributeStr name=\"notes\" value=\"First article.&#10;Fixture B.\"/>") != std::string::npos);
  CHECK(qif.find("<AttributeStr name=\"checked_by\" value=\"B. Check\"/>") != std::string::npos);
  // Elements in the schema's sequence order.
  const std::size_t op = qif.find("<InspectionOperator>"), preparer = qif.find("<ReportPreparer>"),
                    date = qif.find("<ReportPreparationDate>"), attributes = qif.find("<Attributes n=\"");
  CHECK(op < preparer);
  CHECK(preparer < date);
  CHECK(date < attributes);
  CHECK(attributes < qif.find("</InspectionTraceability>"));
  // Customer and program, 9 fields without a QIF element of their own,
  // checked_by, and the two sign-off dates given (empty ones are left out).
  CHECK(qif.find("<Attributes n=\"14\">") != std::string::npos);
  // The project's own QIF reader still reads the document's points.
  const QifMeasuredPoints back = parse_qif_points(qif, "results.qif");
  CHECK(back.points.size() == f.doc.points.size());
}

TEST_CASE("without a record the header says so while report.json has null and the QIF no record") {
  const test::ReportFixture& f = fixture();
  const std::vector<FolderFile> files = make_report(f.doc, f.part, nullptr, context_with(std::nullopt));
  const std::string& html = file(files, "report.html");
  CHECK(html.find("id=\"record-absent\"") < html.find("</header>"));
  CHECK(html.find("No inspection record was given") != std::string::npos);
  CHECK(html.find("id=\"record\"") == std::string::npos);
  CHECK(json::parse(file(files, "report.json"))["record"].is_null());
  const std::string& qif = file(files, "results.qif");
  // The only user attributes are the alignment's, inside ActualTransforms.
  CHECK(qif.find("<Attributes") > qif.find("<ActualTransforms"));
  CHECK(qif.find("<Attributes", qif.find("<Attributes") + 1) == std::string::npos);
  CHECK(qif.find("<InspectionOperator>") == std::string::npos);
}

TEST_CASE("long job options and file names wrap instead of widening the page") {
  const test::ReportFixture& f = fixture();
  ReportContext c = context_with(std::nullopt);
  c.job_options_json = "{\"measurements\": \"" + std::string(400, 'm') + "\"}";
  const std::vector<FolderFile> files = make_report(f.doc, f.part, nullptr, c);
  const std::string& html = file(files, "report.html");
  const std::size_t pre = html.find("<pre class=\"options\">");
  REQUIRE(pre != std::string::npos);
  CHECK(html.find(std::string(400, 'm'), pre) != std::string::npos);
  // The page's style wraps that block and the key/value and file tables.
  const std::string style = html.substr(html.find("<style>"), html.find("</style>") - html.find("<style>"));
  CHECK(style.find("pre.options{white-space:pre-wrap;overflow-wrap:anywhere") != std::string::npos);
  CHECK(style.find("table.kv td,table.files td{overflow-wrap:anywhere") != std::string::npos);
}
