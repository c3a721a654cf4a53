#include "render/png.hpp"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <stdexcept>
#include <string>

namespace furrow {

namespace {

void append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

void no_flush(png_structp) {}

}  // namespace

std::vector<unsigned char> encode_png(const ImageRows& image) {
  if (image.width <= 0 || image.height <= 0 || !image.data)
    throw std::invalid_argument("encode_png: empty image");
  int colour_type = 0;
  switch (image.channels) {
    case 1: colour_type = PNG_COLOR_TYPE_GRAY; break;
    case 3: colour_type = PNG_COLOR_TYPE_RGB; break;
    case 4: colour_type = PNG_COLOR_TYPE_RGB_ALPHA; break;
    default: throw std::invalid_argument("encode_png: " + std::to_string(image.channels) + " channels");
  }
  std::vector<unsigned char> out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) throw std::runtime_error("encode_png: libpng could not start");
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw std::runtime_error("encode_png: libpng could not start");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("encode_png: libpng failed");
  }
  png_set_write_fn(png, &out, append, no_flush);
  // Fast settings, as figures are written once and read in a browser.
  png_set_compression_level(png, 1);
  png_set_compression_strategy(png, Z_RLE);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               colour_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (image.bgr && image.channels >= 3) png_set_bgr(png);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, const_cast<png_bytep>(image.data + static_cast<std::size_t>(y) * image.stride));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace furrow
