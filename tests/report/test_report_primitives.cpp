#include <doctest/doctest.h>

#include <cmath>

#include "render/colour_scale.hpp"
#include "report/file_digest.hpp"
#include "report/html.hpp"

using namespace furrow;

TEST_CASE("SHA-256 matches the FIPS 180-2 test vectors") {
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST_CASE("base64 matches RFC 4648 test vectors") {
  auto b64 = [](const std::string& s) { return html::base64(std::vector<unsigned char>(s.begin(), s.end())); };
  CHECK(b64("") == "");
  CHECK(b64("f") == "Zg==");
  CHECK(b64("fo") == "Zm8=");
  CHECK(b64("foo") == "Zm9v");
  CHECK(b64("foob") == "Zm9vYg==");
  CHECK(b64("fooba") == "Zm9vYmE=");
  CHECK(b64("foobar") == "Zm9vYmFy");
}

TEST_CASE("HTML escaping covers the five special characters") {
  CHECK(html::escape("a<b>&\"c'") == "a&lt;b&gt;&amp;&quot;c&#39;");
  CHECK(html::embedded_png({1, 2, 3}, "x\"y").find("alt=\"x&quot;y\" src=\"data:image/png;base64,AQID\"") !=
        std::string::npos);
}

TEST_CASE("the diverging scale is white at zero, blue below, red above, saturated beyond") {
  const Rgb zero = diverging_colour(0.0);
  CHECK(zero == Rgb{247, 247, 247});
  CHECK(diverging_colour(-1.0)[2] > diverging_colour(-1.0)[0]);  // blue
  CHECK(diverging_colour(1.0)[0] > diverging_colour(1.0)[2]);    // red
  CHECK(diverging_colour(5.0) == diverging_colour(1.0));
  CHECK(diverging_colour(std::nan("")) == Rgb{150, 150, 150});
  // Monotone darkening away from zero on each side.
  auto lightness = [](const Rgb& c) { return c[0] + c[1] + c[2]; };
  for (double t = 0.1; t <= 1.0; t += 0.1) {
    CHECK(lightness(diverging_colour(t)) < lightness(diverging_colour(t - 0.1)));
    CHECK(lightness(diverging_colour(-t)) < lightness(diverging_colour(-t + 0.1)));
  }
}

#include <opencv2/imgcodecs.hpp>

#include "render/drawing_raster.hpp"
#include "report/figures.hpp"

namespace {

cv::Mat decode(const std::vector<unsigned char>& png) { return cv::imdecode(png, cv::IMREAD_COLOR); }

// Count pixels close to an sRGB colour.
int count_colour(const cv::Mat& img, const Rgb& c) {
  int n = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      if (std::abs(p[2] - c[0]) <= 2 && std::abs(p[1] - c[1]) <= 2 && std::abs(p[0] - c[2]) <= 2) ++n;
    }
  return n;
}

}  // namespace

TEST_CASE("figures are valid, deterministic PNGs that show their data") {
  std::vector<MapPoint> pts;
  for (int k = 0; k < 50; ++k) pts.push_back({Eigen::Vector2d(k, k % 7), (k - 25) * 0.004, k == 3, "", false});
  const ToleranceLimits tol{-0.05, 0.05};
  const auto map = to_png(deviation_map_drawing("map", pts, {{{0, 0}, {50, 0}, {50, 7}, {0, 7}, {0, 0}}}, tol, "x", "y", true));
  CHECK(map == to_png(deviation_map_drawing("map", pts, {{{0, 0}, {50, 0}, {50, 7}, {0, 7}, {0, 0}}}, tol, "x", "y", true)));
  const cv::Mat img = decode(map);
  REQUIRE_FALSE(img.empty());
  CHECK(img.cols == 900);
  // The most negative point is the saturated dark blue of the scale's end
  // (range = max(tol, max |value|) = 0.1 mm, value -0.1).
  CHECK(count_colour(img, diverging_colour(-1.0)) > 20);
  const std::vector<double> values = {-0.01, 0.0, 0.01, 0.02, 0.02, 0.03};
  const cv::Mat hist = decode(to_png(histogram_drawing("h", values, tol)));
  REQUIRE_FALSE(hist.empty());
  const cv::Mat sc = decode(to_png(scatter_drawing("s", {0.0, 0.01}, {0.001, 0.012}, {0.002, 0.002})));
  REQUIRE_FALSE(sc.empty());
  const cv::Mat st = decode(to_png(status_map_drawing("g", {{Eigen::Vector2d(1, 1), {}, "G1", "CONFIRMED"}}, {}, {}, "x", "y")));
  REQUIRE_FALSE(st.empty());
  CHECK(count_colour(st, status_colour("CONFIRMED")) > 50);
}
