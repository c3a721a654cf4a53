#include <doctest/doctest.h>

#include <cmath>

#include "report/colour_scale.hpp"
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
