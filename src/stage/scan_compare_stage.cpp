#include "stage/scan_compare_stage.hpp"

#include "geometry/closest_point.hpp"

namespace furrow {

ScanComparison compare_scan_stage(const Part& part, const ScanCloud& cloud, const RegionMap* regions,
                                  const Prediction* prediction, const CompareOptions& options,
                                  const ScanPreprocessOptions& preprocessing) {
  const ScanPreprocessed pre = preprocess_scan(cloud, preprocessing);
  const ClosestPointFinder finder(part);
  ScanComparison c = compare_scan(finder, cloud, pre, preprocessing, regions, options);
  if (prediction) verify_scan_prediction(c, cloud, part, *prediction, options);
  c.fit_options = options.registration;
  // Recorded now: the report of the comparison must not need the raw scan.
  c.display = scan_display(c, cloud);
  c.histogram = scan_histogram(c);
  return c;
}

}  // namespace furrow
