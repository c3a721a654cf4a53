#pragma once
// spc.qif: the SPC of a batch as a QIF 3.0 (ISO 23952) document with
// Statistics (docs/qif.md "spc.qif"), valid by the official XSD set:
// one profile characteristic per SPC characteristic (point profile for a
// point, surface profile for a region; Name = its id, ToleranceValue the
// zone's width), one MeasurementResults per part (serial and date as
// attributes, its verdict as InspectionStatus, the characteristic values it
// has as characteristic measurements), and one CapabilityStudyResults whose
// CharacteristicsStats give, per characteristic, the measurements they rest
// on and the figures of spc_statistics.hpp under QIF's names.
//
// Deterministic: the same result and selection give the same bytes; the
// QPId is derived from the content (io/qif/qif_uuid.hpp). Absent figures
// are left out. Numbers are xs:decimal text (io/qif/xs_decimal.hpp).
#include <string>

#include "results/spc_json.hpp"
#include "results/spc_statistics.hpp"

namespace furrow {

std::string spc_qif(const SpcResult& result, const SpcSelection& selection);

}  // namespace furrow
