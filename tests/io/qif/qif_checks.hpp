#pragma once
// Structural checks of a QIF 3.0 document against the schema, without the
// schema files (which this repository does not store): the child order of
// every complex element Furrow writes, transcribed from the QIF 3.0 XSDs
// (qif-community, bindings/CPP-Kramer/schema), the `n` count of every list,
// unique ids up to idMax, and every *Id reference resolving to an element.
#include <doctest/doctest.h>

#include <cstring>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <cstdlib>
#include <cctype>
#include <string>
#include <vector>

namespace furrow::test {

struct Sequence {
  std::vector<std::string> order;     // the xs:sequence, in order
  std::vector<std::string> required;  // minOccurs 1
};

// Element name -> its type's sequence. Where a type's sequence was read
// from a schema-valid sample of the same repository (data/QIF_PTS_SAMPLE.QIF,
// mitutoyo_results_serialized_pass_fail_sample.QIF) rather than from the XSD
// text, the comment says so.
inline const std::map<std::string, Sequence>& qif_sequences() {
  static const std::map<std::string, Sequence> table = {
      // QIFDocument.xsd, QIFDocumentType
      {"QIFDocument",
       {{"QPId", "Attributes", "VersionHistory", "Version", "Header", "ValidationCounts", "ProductDataQuality",
         "ExternalQIFReferences", "StandardsDefinitions", "SoftwareDefinitions", "AlgorithmDefinitions",
         "PreInspectionTraceability", "FileUnits", "DatumDefinitions", "DatumTargetDefinitions", "Transforms",
         "CoordinateSystems", "DatumReferenceFrames", "MeasurementResources", "ThreadSpecifications", "Product",
         "Features", "FeatureZones", "Characteristics", "Plan", "Results", "Statistics",
         "ManufacturingProcessTraceabilities", "Rules", "UserDataXML", "Signature"},
        {"QPId"}}},
      // QIFDocument.xsd, QIFDocumentHeaderType
      {"Header", {{"Application", "Author", "ApplicationSource", "Description", "Scope"}, {}}},
      // QIFProduct.xsd, ProductType (PartSet after the geometry/topology/view sets)
      {"Product",
       {{"Header", "GeometrySet", "TopologySet", "NoteSet", "NoteFlagSet", "PartNoteSet", "ViewSet", "LayerSet",
         "CoordinateSystemSet", "VisualizationSet", "AuxiliarySet", "PartSet", "AssemblySet", "ComponentSet",
         "RootPart", "AsmPaths", "MaterialLibrary"},
        {}}},
      // QIFResults.xsd, ResultsType
      {"Results", {{"Version", "MeasurementResultsSet", "ActualComponentSets", "InspectionTraceability"},
                   {"MeasurementResultsSet"}}},
      // QIFResults.xsd, MeasurementResultsType
      {"MeasurementResults",
       {{"Attributes", "InspectionTraceability", "ThisResultsInstanceQPId", "ExternalFileReferences",
         "MeasuredFeatures", "MeasuredPointSets", "MeasuredCharacteristics", "ActualTransforms",
         "CoordinateSystemActualTransformAssociations", "InspectionStatus", "ActualComponentIds"},
        {"InspectionStatus"}}},
      // Traceability.xsd, InspectionTraceabilityType
      {"InspectionTraceability",
       {{"InspectingOrganization", "CustomerOrganization", "SupplierCode", "PurchaseOrderNumber", "OrderNumber",
         "ReportNumber", "InspectionScope", "InspectionMode", "PartialInspection", "NotableEvents", "NotedEvents",
         "InspectionStart", "InspectionEnd", "InspectionSoftwareItems", "InspectionProgram", "InspectionOperator",
         "ReportPreparer", "ReportPreparationDate", "ReportType", "SecurityClassification", "PlantLocation",
         "ReferencedQIFPlanInstance", "ReferencedQIFPlan", "Errors", "Attributes"},
        {}}},
      // Characteristics.xsd, ProfileCharacteristicDefinitionBaseType and
      // SurfaceProfileCharacteristicDefinitionType (Extent last)
      {"SurfaceProfileCharacteristicDefinition",
       {{"ToleranceValue", "ToleranceDualValue", "OuterDisposition", "UnequallyDisposedZone", "OffsetZone",
         "VariableAngle", "SecondCompositeSegmentProfileDefinition", "ThirdCompositeSegmentProfileDefinition",
         "FourthCompositeSegmentProfileDefinition", "DatumReferenceFrameId", "OrientationOnly", "Extent"},
        {}}},
      {"PointProfileCharacteristicDefinition",
       {{"ToleranceValue", "ToleranceDualValue", "OuterDisposition", "UnequallyDisposedZone", "OffsetZone",
         "VariableAngle", "SecondCompositeSegmentProfileDefinition", "ThirdCompositeSegmentProfileDefinition",
         "FourthCompositeSegmentProfileDefinition", "DatumReferenceFrameId", "OrientationOnly"},
        {}}},
      // Units.xsd, the units of FileUnits (order as in QIF_PTS_SAMPLE.QIF)
      {"FileUnits", {{"PrimaryUnits", "OtherUnits"}, {"PrimaryUnits"}}},
      {"PrimaryUnits", {{"AngularUnit", "LinearUnit"}, {}}},
      {"LinearUnit", {{"SIUnitName", "UnitName", "UnitConversion"}, {"UnitName"}}},
      {"AngularUnit", {{"SIUnitName", "UnitName", "UnitConversion"}, {"UnitName"}}},
      // Features.xsd (orders as in QIF_PTS_SAMPLE.QIF)
      {"Features", {{"FeatureDefinitions", "FeatureNominals", "FeatureItems"}, {}}},
      {"PointFeatureNominal", {{"Attributes", "FeatureDefinitionId", "Location", "Normal"},
                               {"FeatureDefinitionId", "Location"}}},
      {"PointFeatureItem", {{"Attributes", "FeatureNominalId", "FeatureName", "DeterminationMode"},
                            {"FeatureNominalId"}}},
      {"PointFeatureMeasurement", {{"Attributes", "FeatureItemId", "PointList", "Location", "Normal"},
                                   {"FeatureItemId"}}},
      {"MeasuredPointSet", {{"Points", "Compensated", "ProbeRadius"}, {"Points"}}},
      // Characteristics.xsd (orders as in QIF_PTS_SAMPLE.QIF)
      {"Characteristics", {{"FormalStandardId", "CharacteristicDefinitions", "CharacteristicNominals",
                            "CharacteristicItems"},
                           {}}},
      {"SurfaceProfileCharacteristicNominal", {{"CharacteristicDefinitionId", "TargetValue"},
                                               {"CharacteristicDefinitionId"}}},
      {"PointProfileCharacteristicNominal", {{"CharacteristicDefinitionId", "TargetValue"},
                                             {"CharacteristicDefinitionId"}}},
      {"SurfaceProfileCharacteristicItem", {{"Name", "CharacteristicDesignator", "FeatureItemIds",
                                             "MeasurementDeviceIds", "CharacteristicNominalId"},
                                            {"CharacteristicNominalId"}}},
      {"PointProfileCharacteristicItem", {{"Name", "CharacteristicDesignator", "FeatureItemIds",
                                           "MeasurementDeviceIds", "CharacteristicNominalId"},
                                          {"CharacteristicNominalId"}}},
      {"SurfaceProfileCharacteristicMeasurement", {{"Status", "CharacteristicItemId", "FeatureMeasurementIds", "Value"},
                                                   {"Status", "CharacteristicItemId"}}},
      {"PointProfileCharacteristicMeasurement", {{"Status", "CharacteristicItemId", "FeatureMeasurementIds", "Value"},
                                                 {"Status", "CharacteristicItemId"}}},
      // QIFPlan.xsd, PlanType: PlanRoot is abstract; OrderedPlanRoot substitutes it
      {"Plan", {{"Version", "RulesUsedQPId", "RulesToUseQPId", "WorkInstructions", "ActionMethods", "Measurands",
                 "LocalVariables", "OrderedPlanRoot"},
                {"OrderedPlanRoot"}}},
      // QIFPlan.xsd, OrderedActionGroupType (PlanElementBaseType, ActionGroupBaseType, then Steps)
      {"OrderedPlanRoot", {{"WorkInstructionIds", "Attributes", "MeasureActionGroupFunction", "Steps"}, {"Steps"}}},
      // QIFPlan.xsd, NumberedPlanElementType: SequenceNumber, then one PlanElement
      {"NumberedPlanElement",
       {{"SequenceNumber", "MeasureSpecifiedFeatures", "EvaluateSpecifiedCharacteristics"}, {"SequenceNumber"}}},
      // QIFPlan.xsd, MeasureSpecifiedFeaturesActionType (ActionBaseType members first)
      {"MeasureSpecifiedFeatures",
       {{"WorkInstructionIds", "Attributes", "PreferredActionMethodId", "AlternativeActionMethodIds",
         "PreferredResourceIds", "FeatureItemIds"},
        {"FeatureItemIds"}}},
      // QIFPlan.xsd, EvaluateSpecifiedCharacteristicsActionType
      {"EvaluateSpecifiedCharacteristics",
       {{"WorkInstructionIds", "Attributes", "PreferredActionMethodId", "AlternativeActionMethodIds",
         "PreferredResourceIds", "CharacteristicItemIds"},
        {"CharacteristicItemIds"}}},
      // IntermediatesPMI.xsd TransformInstanceType (TransformMatrixType's
      // Rotation and Origin, then its own Attributes and Name) and
      // Primitives.xsd TransformRotationType
      {"Transform", {{"Rotation", "Origin", "Attributes", "Name"}, {}}},
      {"Rotation", {{"XDirection", "YDirection", "ZDirection"}, {"XDirection", "YDirection", "ZDirection"}}},
      // QIFResults.xsd / Primitives: ExternalFileReferenceType (order as in QIF_PTS_SAMPLE.QIF)
      {"ExternalFileReference", {{"URI", "FileSpec", "Description"}, {"URI"}}},
  };
  return table;
}

// Enumerations (Traceability.xsd InspectionStatusEnumType, Characteristics.xsd
// CharacteristicStatusEnumType).
inline const std::set<std::string>& inspection_status_enum() {
  static const std::set<std::string> v = {"PASS", "FAIL", "REWORK", "SYSERROR", "UNKNOWN",
                                          "NOT_CALCULATED", "NOT_MEASURED", "UNDEFINED"};
  return v;
}
inline const std::set<std::string>& characteristic_status_enum() {
  static const std::set<std::string> v = {"PASS", "FAIL", "REWORK", "SYSERROR", "INDETERMINATE",
                                          "NOT_ANALYZED", "BASIC_OR_TED", "UNDEFINED"};
  return v;
}

inline std::vector<pugi::xml_node> element_children(pugi::xml_node n) {
  std::vector<pugi::xml_node> out;
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element) out.push_back(c);
  return out;
}

// References whose value is a QPId (a UUID), not a QIF id.
inline bool is_reference(const std::string& name) {
  if (name == "Id") return true;
  if (name.size() < 3 || name.compare(name.size() - 2, 2, "Id") != 0) return false;
  return name.find("QPId") == std::string::npos && name != "FeatureItemIds";
}

// Every departure from the schema's structure, one line each (empty: none).
struct QifStructure {
  std::vector<std::string> problems;
  std::size_t sequenced = 0;  // elements checked against a sequence of the table
};

inline QifStructure qif_structure(const std::string& text) {
  QifStructure out;
  auto& problems = out.problems;
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_string(text.c_str());
  if (!parsed) return {{std::string("not XML: ") + parsed.description()}, 0};
  const pugi::xml_node root = doc.document_element();
  if (std::string(root.name()) != "QIFDocument") problems.push_back("root is not QIFDocument");
  if (std::string(root.attribute("xmlns").value()) != "http://qifstandards.org/xsd/qif3")
    problems.push_back("no QIF 3 namespace");
  if (std::string(root.attribute("versionQIF").value()) != "3.0.0") problems.push_back("versionQIF is not 3.0.0");
  const unsigned long id_max = std::strtoul(root.attribute("idMax").value(), nullptr, 10);

  std::map<unsigned long, std::string> ids;  // id -> element name
  std::vector<pugi::xml_node> references;
  std::vector<pugi::xml_node> stack = {root};
  while (!stack.empty()) {
    const pugi::xml_node n = stack.back();
    stack.pop_back();
    const std::string name = n.name();
    const std::vector<pugi::xml_node> kids = element_children(n);
    if (const pugi::xml_attribute id = n.attribute("id")) {
      const unsigned long v = std::strtoul(id.value(), nullptr, 10);
      if (v < 1 || v > id_max) problems.push_back(name + ": id " + id.value() + " outside 1..idMax");
      if (!ids.emplace(v, name).second) problems.push_back(name + ": duplicate id " + id.value());
    }
    if (const pugi::xml_attribute count = n.attribute("n")) {
      if (std::strtoul(count.value(), nullptr, 10) != kids.size())
        problems.push_back(name + ": n=" + count.value() + " but " + std::to_string(kids.size()) + " children");
      if (kids.empty()) problems.push_back(name + ": an empty list");
    }
    if (is_reference(name) && kids.empty()) references.push_back(n);
    if (const auto it = qif_sequences().find(name); it != qif_sequences().end()) {
      ++out.sequenced;
      const Sequence& seq = it->second;
      std::size_t at = 0;
      std::set<std::string> present;
      for (const pugi::xml_node k : kids) {
        const std::string kn = k.name();
        present.insert(kn);
        std::size_t pos = at;
        while (pos < seq.order.size() && seq.order[pos] != kn) ++pos;
        if (pos == seq.order.size())
          problems.push_back(name + ": child " + kn + " out of the sequence order or not in it");
        else
          at = pos;
      }
      for (const std::string& r : seq.required)
        if (present.count(r) != 1) problems.push_back(name + ": no " + r);
    }
    if (name == "InspectionStatusEnum" && inspection_status_enum().count(n.child_value()) != 1)
      problems.push_back(std::string("InspectionStatusEnum ") + n.child_value());
    if (name == "CharacteristicStatusEnum" && characteristic_status_enum().count(n.child_value()) != 1)
      problems.push_back(std::string("CharacteristicStatusEnum ") + n.child_value());
    if (name == "MeasuredPointSet") {
      std::istringstream points(n.child("Points").child_value());
      double v;
      int values = 0;
      while (points >> v) ++values;
      if (values != 3 * n.attribute("count").as_int()) problems.push_back("MeasuredPointSet: count differs");
    }
    for (auto k = kids.rbegin(); k != kids.rend(); ++k) stack.push_back(*k);
  }
  if (ids.empty() || ids.rbegin()->first != id_max) problems.push_back("idMax is not the largest id");
  for (const pugi::xml_node r : references)
    if (ids.count(std::strtoul(r.child_value(), nullptr, 10)) != 1)
      problems.push_back(std::string(r.name()) + " " + r.child_value() + " names no element");
  // QPId: a UUID, 8-4-4-4-12 lower-case hex.
  const std::string uuid = root.child("QPId").child_value();
  bool uuid_ok = uuid.size() == 36;
  for (std::size_t i = 0; uuid_ok && i < uuid.size(); ++i)
    uuid_ok = (i == 8 || i == 13 || i == 18 || i == 23) ? uuid[i] == '-'
                                                         : std::isxdigit(static_cast<unsigned char>(uuid[i])) &&
                                                               !std::isupper(static_cast<unsigned char>(uuid[i]));
  if (!uuid_ok) problems.push_back("QPId " + uuid + " is not a UUID");
  return out;
}

// For tests: CHECKs that there is no problem (printing them) and returns the
// number of elements checked against a sequence, so that a test can require
// that the table was used at all.
inline std::size_t check_qif_structure(const std::string& text) {
  const QifStructure s = qif_structure(text);
  std::string all;
  for (const std::string& p : s.problems) all += p + "\n";
  CHECK_MESSAGE(s.problems.empty(), all);
  return s.sequenced;
}

}  // namespace furrow::test
