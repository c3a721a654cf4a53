#include "results/spc_qif.hpp"

#include <optional>
#include <vector>

#include "base/text_fields.hpp"
#include "io/qif/qif_uuid.hpp"
#include "io/qif/xs_decimal.hpp"

namespace furrow {
namespace {

constexpr int kDecimalDigits = 24;  // libxml2's limit for an xs:decimal (xs_decimal.hpp)

std::string esc(const std::string& s) { return markup_escape(s); }
std::string decimal(double v) { return xs_decimal_text(v, kDecimalDigits); }

const char* profile_kind(const CharacteristicSpc& c) { return c.kind == "region" ? "Surface" : "Point"; }

// Appends <Tag><Value>v</Value></Tag> for a figure that is there.
void stat(std::string& s, const char* tag, const std::optional<double>& v) {
  if (v) s += std::string("              <") + tag + "><Value>" + decimal(*v) + "</Value></" + tag + ">\n";
}

std::string id_list(const char* tag, const std::vector<int>& ids) {
  std::string s = std::string("<") + tag + " n=\"" + std::to_string(ids.size()) + "\">";
  for (int id : ids) s += "<Id>" + std::to_string(id) + "</Id>";
  return s + "</" + tag + ">";
}

void inspection_status(std::string& s, const std::string& verdict) {
  s += "        <InspectionStatus>\n";
  if (verdict == "PASS" || verdict == "FAIL")
    s += "          <InspectionStatusEnum>" + verdict + "</InspectionStatusEnum>\n";
  else if (verdict.empty())
    s += "          <InspectionStatusEnum>UNKNOWN</InspectionStatusEnum>\n";
  else  // INCONCLUSIVE has no enum value (docs/qif.md "Status values")
    s += "          <OtherInspectionStatus>" + esc(verdict) + "</OtherInspectionStatus>\n";
  s += "        </InspectionStatus>\n";
}

}  // namespace

std::string spc_qif(const SpcResult& r, const SpcSelection& selection) {
  const auto& cs = r.characteristics;
  const std::size_t k = cs.size();
  int next = 1;  // ids in document order
  std::string s;
  s += "  <Header>\n    <Application>\n      <Name>Furrow</Name>\n    </Application>\n";
  s += "    <Description>" +
       esc("statistical process control of " + std::to_string(r.parts.size()) + " parts from " + selection.source) +
       "</Description>\n    <Scope>Statistics</Scope>\n  </Header>\n";
  const int standard = next++;
  s += "  <StandardsDefinitions n=\"1\">\n    <Standard id=\"" + std::to_string(standard) +
       "\">\n      <Organization>\n        <StandardsOrganizationEnum>ISO</StandardsOrganizationEnum>\n"
       "      </Organization>\n      <Designator>1101</Designator>\n"
       "      <Title>Geometrical product specifications (GPS) - Geometrical tolerancing</Title>\n"
       "    </Standard>\n  </StandardsDefinitions>\n";
  s += "  <FileUnits>\n    <PrimaryUnits>\n      <LinearUnit>\n        <SIUnitName>meter</SIUnitName>\n"
       "        <UnitName>mm</UnitName>\n        <UnitConversion>\n          <Factor>0.001</Factor>\n"
       "        </UnitConversion>\n      </LinearUnit>\n    </PrimaryUnits>\n  </FileUnits>\n";

  // Characteristics: definition (the zone), nominal, item (the id) of each.
  std::vector<int> item(k);
  if (k > 0) {
    std::vector<int> definition(k), nominal(k);
    s += "  <Characteristics>\n    <FormalStandardId>" + std::to_string(standard) + "</FormalStandardId>\n";
    s += "    <CharacteristicDefinitions n=\"" + std::to_string(k) + "\">\n";
    for (std::size_t i = 0; i < k; ++i) {
      definition[i] = next++;
      const std::string tag = std::string(profile_kind(cs[i])) + "ProfileCharacteristicDefinition";
      s += "      <" + tag + " id=\"" + std::to_string(definition[i]) + "\"><ToleranceValue>" +
           decimal(cs[i].upper - cs[i].lower) + "</ToleranceValue>";
      // The part of the zone on the + side, when the zone is not centred.
      if (cs[i].upper != -cs[i].lower) s += "<OuterDisposition>" + decimal(cs[i].upper) + "</OuterDisposition>";
      s += "</" + tag + ">\n";
    }
    s += "    </CharacteristicDefinitions>\n    <CharacteristicNominals n=\"" + std::to_string(k) + "\">\n";
    for (std::size_t i = 0; i < k; ++i) {
      nominal[i] = next++;
      const std::string tag = std::string(profile_kind(cs[i])) + "ProfileCharacteristicNominal";
      s += "      <" + tag + " id=\"" + std::to_string(nominal[i]) + "\"><CharacteristicDefinitionId>" +
           std::to_string(definition[i]) + "</CharacteristicDefinitionId></" + tag + ">\n";
    }
    s += "    </CharacteristicNominals>\n    <CharacteristicItems n=\"" + std::to_string(k) + "\">\n";
    for (std::size_t i = 0; i < k; ++i) {
      item[i] = next++;
      const std::string tag = std::string(profile_kind(cs[i])) + "ProfileCharacteristicItem";
      s += "      <" + tag + " id=\"" + std::to_string(item[i]) + "\"><Name>" + esc(cs[i].id) +
           "</Name><CharacteristicNominalId>" + std::to_string(nominal[i]) + "</CharacteristicNominalId></" + tag +
           ">\n";
    }
    s += "    </CharacteristicItems>\n  </Characteristics>\n";
  }

  // Results: one MeasurementResults per part, with the values it has.
  std::vector<int> results(r.parts.size());
  std::vector<std::vector<int>> measurement(k);  // per characteristic, per value
  std::vector<std::size_t> cursor(k, 0);
  if (!r.parts.empty()) {
    s += "  <Results>\n    <MeasurementResultsSet n=\"" + std::to_string(r.parts.size()) + "\">\n";
    for (std::size_t p = 0; p < r.parts.size(); ++p) {
      const PartRecord& part = r.parts[p];
      results[p] = next++;
      s += "      <MeasurementResults id=\"" + std::to_string(results[p]) + "\">\n";
      s += std::string("        <Attributes n=\"") + (part.date.empty() ? "1" : "2") +
           "\">\n          <AttributeStr name=\"serial\" value=\"" + esc(part.serial) + "\"/>\n";
      if (!part.date.empty()) s += "          <AttributeStr name=\"date\" value=\"" + esc(part.date) + "\"/>\n";
      s += "        </Attributes>\n";
      std::string rows;
      std::size_t count = 0;
      for (std::size_t i = 0; i < k; ++i) {
        const CharacteristicSpc& c = cs[i];
        if (cursor[i] >= c.part_index.size() || c.part_index[cursor[i]] != p) continue;
        const double v = c.values[cursor[i]++];
        const int id = next++;
        measurement[i].push_back(id);
        const std::string tag = std::string(profile_kind(c)) + "ProfileCharacteristicMeasurement";
        rows += "            <" + tag + " id=\"" + std::to_string(id) + "\"><Status><CharacteristicStatusEnum>" +
                (v >= c.lower && v <= c.upper ? "PASS" : "FAIL") + "</CharacteristicStatusEnum></Status>" +
                "<CharacteristicItemId>" + std::to_string(item[i]) + "</CharacteristicItemId><Value>" + decimal(v) +
                "</Value></" + tag + ">\n";
        ++count;
      }
      if (count > 0)
        s += "        <MeasuredCharacteristics>\n          <CharacteristicMeasurements n=\"" + std::to_string(count) +
             "\">\n" + rows + "          </CharacteristicMeasurements>\n        </MeasuredCharacteristics>\n";
      inspection_status(s, part.verdict);
      s += "      </MeasurementResults>\n";
    }
    s += "    </MeasurementResultsSet>\n  </Results>\n";
  }

  // Statistics: one capability study over every part (it needs a sample).
  if (!r.parts.empty() && k > 0) {
    s += "  <Statistics>\n    <StatisticalStudiesResults n=\"1\">\n      <CapabilityStudyResults id=\"" +
         std::to_string(next++) + "\">\n";
    // Informational: the statistics apply no acceptance criterion (docs/spc.md).
    s += "        <Status><StatsEvalStatusEnum>INFORMATIONAL</StatsEvalStatusEnum></Status>\n";
    s += "        <Name>SPC</Name>\n        <Description>individuals and moving-range chart, capability, "
         "Nelson rules (Furrow docs/spc.md)</Description>\n";
    s += "        " + id_list("ResultsIds", results) + "\n";
    s += "        <CharacteristicsStats n=\"" + std::to_string(k) + "\">\n";
    for (std::size_t i = 0; i < k; ++i) {
      const CharacteristicSpc& c = cs[i];
      const std::string tag = std::string(profile_kind(c)) + "ProfileCharacteristicStats";
      s += "          <" + tag + ">\n";
      if (!c.violations.empty()) {
        s += "            <Attributes n=\"" + std::to_string(c.violations.size()) + "\">\n";
        for (const SpcViolation& v : c.violations)
          s += "              <AttributeStr name=\"nelson rule " + std::to_string(v.rule) + "\" value=\"" +
               esc(v.serial) + ", values " + std::to_string(v.index + 1) + " to " + std::to_string(v.last + 1) +
               "\"/>\n";
        s += "            </Attributes>\n";
      }
      if (!measurement[i].empty()) s += "            <MeasuredIds>" + id_list("Ids", measurement[i]) + "</MeasuredIds>\n";
      s += "            <Status><StatsEvalStatusEnum>INFORMATIONAL</StatsEvalStatusEnum></Status>\n";
      s += "            <ValueStats linearUnit=\"mm\">\n";
      s += "              <TotalNumber><Value>" + std::to_string(c.n) + "</Value></TotalNumber>\n";
      stat(s, "Average", c.mean);
      stat(s, "StandardDeviation", c.sigma_overall);
      stat(s, "EstimatedStandardDeviation", c.sigma_within);
      stat(s, "AverageRange", c.mr_mean);
      stat(s, "UpperControlLimit", c.ucl);
      stat(s, "LowerControlLimit", c.lcl);
      stat(s, "UpperControlLimitRange", c.mr_ucl);
      if (c.sigma_within && *c.sigma_within > 0) {
        // The values that take part in a violation, as the chart marks them.
        std::vector<int> out;
        std::vector<bool> marked(c.n, false);
        for (const SpcViolation& v : c.violations)
          for (std::size_t j = v.index; j <= v.last; ++j) marked[j] = true;
        for (std::size_t j = 0; j < c.n; ++j)
          if (marked[j]) out.push_back(measurement[i][j]);
        s += "              <NumberOutOfControl><Value>" + std::to_string(out.size()) + "</Value>" +
             (out.empty() ? std::string() : id_list("Ids", out)) + "</NumberOutOfControl>\n";
      }
      if (c.slope) {
        stat(s, "RegressionSlope", c.slope->value);
        stat(s, "LowerConfidenceLimit", c.slope->low);
        stat(s, "UpperConfidenceLimit", c.slope->high);
      }
      stat(s, "Cp", c.cp);
      stat(s, "Cpk", c.cpk);
      stat(s, "Pp", c.pp);
      stat(s, "Ppk", c.ppk);
      s += "            </ValueStats>\n          </" + tag + ">\n";
    }
    s += "        </CharacteristicsStats>\n        <NumberOfSamples>" + std::to_string(r.parts.size()) +
         "</NumberOfSamples>\n        <SubgroupSize>1</SubgroupSize>\n      </CapabilityStudyResults>\n"
         "    </StatisticalStudiesResults>\n  </Statistics>\n";
  }
  // The QPId identifies this content: derived from it, not random.
  const std::string qpid = uuid_from_content(qif_sha256_hex(s) + " QPId");
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<QIFDocument xmlns=\"http://qifstandards.org/xsd/qif3\" "
         "versionQIF=\"3.0.0\" idMax=\"" +
         std::to_string(next - 1) + "\">\n  <QPId>" + qpid + "</QPId>\n" + s + "</QIFDocument>\n";
}

}  // namespace furrow
