// The QPIds and the time of a QIF document (docs/qif.md "Identity and
// time"): the UUIDs are derived from the SHA-256 of the document written
// with placeholders, and only the QPId and time elements are filled in -
// checked here by putting the placeholders back and hashing again, on a
// document whose names spell the placeholders and whose time is shorter
// than its placeholder.
#include <doctest/doctest.h>

#include <string>

#include "io/qif/qif_document.hpp"
#include "io/qif/qif_uuid.hpp"
#include "qif_schema.hpp"

using namespace furrow;

namespace {

const std::string kQpid = "00000000-0000-0000-0000-00000000000d";
const std::string kResultsQpid = "00000000-0000-0000-0000-00000000000r";
const std::string kTime = "0000-00-00T00:00:00 (time)";

// The text between <tag> and </tag>, first occurrence after `from`.
std::string element(const std::string& text, const std::string& tag, std::size_t from = 0) {
  const std::size_t a = text.find("<" + tag + ">", from);
  REQUIRE(a != std::string::npos);
  const std::size_t b = text.find("</" + tag + ">", a);
  return text.substr(a + tag.size() + 2, b - a - tag.size() - 2);
}

// `text` with the element's content replaced (every occurrence of the tag).
std::string put_back(std::string text, const std::string& tag, const std::string& content) {
  for (std::size_t a = text.find("<" + tag + ">"); a != std::string::npos; a = text.find("<" + tag + ">", a + 1)) {
    const std::size_t start = a + tag.size() + 2, end = text.find("</" + tag + ">", start);
    text.replace(start, end - start, content);
  }
  return text;
}

QifDocumentData tricky(const std::optional<std::string>& time) {
  QifDocumentData d;
  d.part_name = kQpid;  // a name that spells a placeholder is a name
  d.description = "made " + kTime + " " + kResultsQpid;
  d.time = time;
  for (int i = 0; i < 3; ++i) {
    QifPoint p;
    p.id = i == 1 ? kResultsQpid : "P" + std::to_string(i);
    p.nominal = {1e308, -0.0, 1e-300};
    p.actual = Eigen::Vector3d(0.0001, 0, 2);
    p.deviation = -0.0;
    p.status = "PASS";
    d.points.push_back(p);
  }
  QifProfile profile;
  profile.tolerance = 0.05;
  profile.value = 0.0;
  profile.status = "PASS";
  d.profile = profile;
  d.inspection_status = "PASS";
  d.traceability = QifTraceability{};
  return d;
}

}  // namespace

TEST_CASE("qif identity: QPIds hash the placeholder text, and only QPId and time elements are filled in") {
  for (const std::optional<std::string>& time :
       {std::optional<std::string>("2024-01-01T00:00:00Z"),
        std::optional<std::string>("2024-01-01T00:00:00.123456789+01:00"),  // longer than its placeholder
        std::optional<std::string>("2024-01-01T00:00:00.12345Z"),            // as long
        std::optional<std::string>()}) {
    REQUIRE(kTime.size() == 26);
    CAPTURE(time.value_or("none"));
    const QifDocumentData d = tricky(time);
    const std::string text = qif_results_text(d);
    // The user's strings stay as written.
    CHECK(element(text, "ModelNumber") == kQpid);
    CHECK(element(text, "Description") == d.description);
    CHECK(text.find("<FeatureName>" + kResultsQpid + "</FeatureName>") != std::string::npos);
    // The time where the document carries one; valid by the schema either way.
    test::check_qif_valid(text, test::scratch_dir("qif-identity") + "/results.qif");
    if (time) {
      CHECK(element(text, "TimeCreated") == *time);
      CHECK(element(text, "ReportPreparationDate") == *time);
    } else {
      CHECK(text.find("<TimeCreated>") == std::string::npos);
    }
    // Oracle: the placeholders back in, hashed, give the UUIDs written.
    std::string original = put_back(put_back(text, "QPId", kQpid), "ThisResultsInstanceQPId", kResultsQpid);
    if (time) original = put_back(put_back(original, "TimeCreated", kTime), "ReportPreparationDate", kTime);
    const std::string digest = qif_sha256_hex(original);
    CHECK(element(text, "QPId") == uuid_from_content(digest + " QPId"));
    CHECK(element(text, "ThisResultsInstanceQPId") == uuid_from_content(digest + " ThisResultsInstanceQPId"));
    // The time does not enter the identity.
    QifDocumentData other = d;
    other.time = time ? std::optional<std::string>("1999-12-31T23:59:59Z") : std::nullopt;
    CHECK(element(qif_results_text(other), "QPId") == element(text, "QPId"));
  }
}

TEST_CASE("qif identity: the plan's QPId likewise") {
  const QifDocumentData d = tricky(std::nullopt);
  const std::string text = qif_plan_text(d);
  CHECK(element(text, "ModelNumber") == kQpid);
  const std::string digest = qif_sha256_hex(put_back(text, "QPId", kQpid));
  CHECK(element(text, "QPId") == uuid_from_content(digest + " QPId"));
}

TEST_CASE("qif identity: a time that is not an xs:dateTime is refused, not written") {
  for (const char* bad : {"2024-01-01 00:00:00", "yesterday", "2024-01-01T00:00:00Z <&>", ""}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(qif_results_text(tricky(std::string(bad))), std::invalid_argument);
    CHECK_THROWS_AS(qif_plan_text(tricky(std::string(bad))), std::invalid_argument);
  }
}
