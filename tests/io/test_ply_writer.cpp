// The PLY writer (ply_writer.hpp) byte by byte: the header as the PLY
// format has it, records little-endian whatever the host (the bytes of
// 1.0 as a double are 00 00 00 00 00 00 f0 3f), and programming errors
// refused.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "io/ply_writer.hpp"

using namespace furrow;

TEST_CASE("ply writer: header and little-endian records, byte for byte") {
  const std::string text = ply_vertex_text({{"x", PlyScalar::float64, {1.0, -2.0}},
                                            {"deviation", PlyScalar::float32, {0.5, 1.0}},
                                            {"outlier", PlyScalar::uchar, {0, 255}}},
                                           {"made by a test"});
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment made by a test\nelement vertex 2\n"
      "property double x\nproperty float deviation\nproperty uchar outlier\nend_header\n";
  REQUIRE(text.size() == header.size() + 2 * (8 + 4 + 1));
  CHECK(text.substr(0, header.size()) == header);
  const unsigned char expected[] = {
      0, 0, 0, 0, 0, 0, 0xf0, 0x3f,  // 1.0
      0, 0, 0, 0x3f,                 // 0.5f
      0,                             //
      0, 0, 0, 0, 0, 0, 0, 0xc0,     // -2.0
      0, 0, 0x80, 0x3f,              // 1.0f
      255};
  for (std::size_t k = 0; k < sizeof expected; ++k) {
    CAPTURE(k);
    CHECK(static_cast<unsigned char>(text[header.size() + k]) == expected[k]);
  }
}

TEST_CASE("ply writer: an empty cloud has a header and no record") {
  const std::string text = ply_vertex_text({{"x", PlyScalar::float64, {}}});
  CHECK(text == "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty double x\nend_header\n");
}

TEST_CASE("ply writer: columns of other lengths, non-finite values and values outside their type are refused") {
  CHECK_THROWS_AS(ply_vertex_text({}), std::invalid_argument);
  CHECK_THROWS_AS(ply_vertex_text({{"x", PlyScalar::float64, {1, 2}}, {"y", PlyScalar::float64, {1}}}),
                  std::invalid_argument);
  CHECK_THROWS_AS(ply_vertex_text({{"x", PlyScalar::float64, {std::nan("")}}}), std::invalid_argument);
  CHECK_THROWS_AS(ply_vertex_text({{"x", PlyScalar::float32, {1e300}}}), std::invalid_argument);
  CHECK_THROWS_AS(ply_vertex_text({{"flag", PlyScalar::uchar, {256}}}), std::invalid_argument);
  CHECK_THROWS_AS(ply_vertex_text({{"flag", PlyScalar::uchar, {0.5}}}), std::invalid_argument);
  CHECK_THROWS_AS(ply_vertex_text({{"x", PlyScalar::float64, {1}}}, {"two\nlines"}), std::invalid_argument);
}
