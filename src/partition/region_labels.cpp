#include "partition/region_labels.hpp"

#include <opencv2/imgproc.hpp>

namespace furrow {

std::vector<unsigned char> classify_cells(const CurvatureField& field, double eps) {
  std::vector<unsigned char> out(field.samples.size(), kTrimmedCell);
  const auto n = static_cast<long>(out.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const CurvatureSample& s = field.samples[static_cast<std::size_t>(k)];
    unsigned char& code = out[static_cast<std::size_t>(k)];
    if (s.valid())
      code = static_cast<unsigned char>(classify_curvature(s.k1, s.k2, eps));
    else if (s.status == SampleStatus::degenerate)
      code = kDegenerateCell;
  }
  return out;
}

RegionLabels connected_regions(const std::vector<unsigned char>& cell_class, int nu, int nv) {
  RegionLabels out;
  out.nu = nu;
  out.nv = nv;
  out.label.assign(cell_class.size(), -1);
  // The class grid seen as an image: rows along u, columns along v (the
  // field's own memory layout, no copy of the data needed).
  const cv::Mat classes(nu, nv, CV_8U, const_cast<unsigned char*>(cell_class.data()));
  cv::Mat mask, component;
  for (int c = 0; c < kCurvatureClassCount; ++c) {
    cv::compare(classes, c, mask, cv::CMP_EQ);
    const int found = cv::connectedComponents(mask, component, 4, CV_32S);
    if (found <= 1) continue;  // background only
    const int base = out.count() - 1;  // OpenCV's label 1 becomes base + 1
    for (int i = 0; i < nu; ++i) {
      const int* row = component.ptr<int>(i);
      int* dst = out.label.data() + static_cast<std::size_t>(i) * nv;
      for (int j = 0; j < nv; ++j)
        if (row[j] > 0) dst[j] = base + row[j];
    }
    out.region_class.insert(out.region_class.end(), static_cast<std::size_t>(found - 1),
                            static_cast<CurvatureClass>(c));
  }
  out.components.assign(out.region_class.size(), 1);
  renumber_in_raster_order(out);
  return out;
}

void renumber_in_raster_order(RegionLabels& labels) {
  std::vector<int> map(labels.region_class.size(), -1);
  std::vector<CurvatureClass> region_class;
  std::vector<int> components;
  for (int& l : labels.label) {
    if (l < 0) continue;
    if (map[static_cast<std::size_t>(l)] < 0) {
      map[static_cast<std::size_t>(l)] = static_cast<int>(region_class.size());
      region_class.push_back(labels.region_class[static_cast<std::size_t>(l)]);
      components.push_back(labels.components[static_cast<std::size_t>(l)]);
    }
    l = map[static_cast<std::size_t>(l)];
  }
  labels.region_class = std::move(region_class);
  labels.components = std::move(components);
}

}  // namespace furrow
