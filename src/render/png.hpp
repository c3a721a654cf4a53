#pragma once
// PNG encoding of 8-bit images (libpng), for every figure Furrow writes.
//
// Why not OpenCV's imencode: Debian's libopencv_imgcodecs loads some 140
// shared libraries (GDAL and its formats) into every process that links it,
// for the one format we write. libpng is what imgcodecs uses for PNG anyway.
// Output is deterministic: fixed compression settings, no time stamp.
#include <cstddef>
#include <vector>

namespace furrow {

struct ImageRows {
  int width = 0;
  int height = 0;
  int channels = 3;                   // 1 grey, 3 colour, 4 colour + alpha
  const unsigned char* data = nullptr;
  std::size_t stride = 0;             // bytes from one row to the next
  bool bgr = true;                    // colour channels in B, G, R order (OpenCV's)
};

// Throws std::invalid_argument for an empty image or an unsupported channel
// count, std::runtime_error if libpng fails.
std::vector<unsigned char> encode_png(const ImageRows& image);

}  // namespace furrow
