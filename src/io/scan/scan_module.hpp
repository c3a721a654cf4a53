#pragma once
// The seam between furrow_core and the scan module furrow_scan.so, the only
// place PCL's headers and libraries appear (docs/architecture.md "Modules
// loaded on demand"). Not part of Furrow's interface: read_scan(),
// preprocess_scan() and feature_start() are. Only plain data crosses it (scan_cloud.hpp,
// scan_preprocess.hpp).
//
// Each entry never lets an exception out (an exception crossing dlopen'ed
// code is not something to rely on): it fills its result and returns
// ScanModuleOutcome::ok, or another outcome with the message in `message`,
// which the core turns back into the exception the module caught.
#include <string>

#include "io/scan/scan_cloud.hpp"
#include "io/scan/scan_feature_start.hpp"
#include "io/scan/scan_preprocess.hpp"

namespace furrow::scan {

enum class ScanModuleOutcome : int { ok = 0, input_error = 1, out_of_memory = 2, failure = 3 };

using ReadEntry = int (*)(const std::string* path, ScanCloud* cloud, std::string* message);
using PreprocessEntry = int (*)(const ScanCloud* cloud, const ScanPreprocessOptions* options,
                                ScanPreprocessed* result, std::string* message);
using FeatureStartEntry = int (*)(const FeatureStartInput* input, const FeatureStartOptions* options,
                                  FeatureStart* result, std::string* message);

inline constexpr const char* kModuleName = "furrow_scan";
inline constexpr const char* kModuleOverride = "FURROW_SCAN_MODULE";
inline constexpr const char* kReadEntry = "furrow_scan_read";
inline constexpr const char* kPreprocessEntry = "furrow_scan_preprocess";
inline constexpr const char* kFeatureStartEntry = "furrow_scan_feature_start";
inline constexpr const char* kModuleWhat = "its point-cloud reader (PLY and PCD through PCL)";

// Inside the module; the core checked the path and the options. Throw
// InputError as read_scan() and preprocess_scan() document.
ScanCloud read_with_pcl(const std::string& path);
ScanPreprocessed preprocess_with_pcl(const ScanCloud& cloud, const ScanPreprocessOptions& options);
// `options` complete (feature_start_parameters() applied).
FeatureStart feature_start_with_pcl(const FeatureStartInput& input, const FeatureStartOptions& options);

}  // namespace furrow::scan
