// The I++ DME point items' fast reader (io/cmm/ippdme_command.hpp,
// ippdme_point_items_fast) against the general one it stands in for
// (parse_ippdme_items + ippdme_point_items), the second implementation and
// the oracle: on texts made of well-formed items and on the same texts
// mutated character by character, whatever the fast reader accepts the
// general one accepts with the same values bit for bit; and the answers a
// CMM writes are taken by the fast reader, not left to the slow one.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "io/cmm/ippdme_command.hpp"

using namespace furrow;

namespace {

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

bool same(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || bits(*a) == bits(*b));
}

// A number as a CMM may write it: fixed, exponent, signs, leading dot,
// many digits.
std::string number(std::mt19937& rng) {
  std::uniform_real_distribution<double> v(-1000, 1000);
  char text[64];
  switch (rng() % 6) {
    case 0: std::snprintf(text, sizeof text, "%.5f", v(rng)); break;
    case 1: std::snprintf(text, sizeof text, "%.6E", v(rng)); break;
    case 2: std::snprintf(text, sizeof text, "%+.3f", v(rng)); break;
    case 3: std::snprintf(text, sizeof text, "%.17g", v(rng) * 1e-3); break;
    case 4: std::snprintf(text, sizeof text, ".%u", static_cast<unsigned>(rng() % 100000)); break;
    default: std::snprintf(text, sizeof text, "%d", static_cast<int>(rng() % 2000) - 1000); break;
  }
  return text;
}

std::string point_items(std::mt19937& rng) {
  static const char* const keys[] = {"X", "Y", "Z", "ER", "Tool.A", "Tool.B", "Tool.C"};
  std::string out;
  std::vector<int> order = {0, 1, 2, 7, 3};
  if (rng() % 3 == 0) order.push_back(4 + static_cast<int>(rng() % 3));
  std::shuffle(order.begin(), order.end(), rng);
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k) out += rng() % 2 ? ", " : ",";
    if (order[k] == 7) {
      out += "IJK(" + number(rng) + ", " + number(rng) + (rng() % 2 ? "," : ", ") + number(rng) + ")";
    } else {
      out += std::string(keys[order[k]]) + "(" + number(rng) + ")";
    }
  }
  return out;
}

std::string mutated(std::string text, std::mt19937& rng) {
  static const std::string alphabet = "0123456789+-.eE, ()XYZIJKER\"a";
  const int edits = 1 + static_cast<int>(rng() % 3);
  for (int e = 0; e < edits && !text.empty(); ++e) {
    const std::size_t at = rng() % text.size();
    const char c = alphabet[rng() % alphabet.size()];
    switch (rng() % 3) {
      case 0: text[at] = c; break;
      case 1: text.insert(text.begin() + static_cast<long>(at), c); break;
      default: text.erase(at, 1); break;
    }
  }
  return text;
}

// The general reader's items of an answer's data; false when it refuses.
bool general(const std::string& text, IppdmePointItems& out) {
  std::vector<IppdmeItem> items;
  if (!parse_ippdme_items(text, items).empty()) return false;
  return ippdme_point_items(items, out).empty() && out.only_point_items;
}

}  // namespace

TEST_CASE("I++ DME point items: the fast reader accepts only what the general reader accepts, with the same values") {
  std::mt19937 rng(20261129);
  int fast_accepted = 0, fast_refused_general_accepted = 0, mutants = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::string clean = point_items(rng);
    const std::string text = trial % 2 ? mutated(clean, rng) : clean;
    mutants += trial % 2;
    IppdmePointItems fast, slow;
    const bool f = ippdme_point_items_fast(text, kIppdmeAnswerDigits, fast);
    const bool g = general(text, slow);
    if (!f) {
      fast_refused_general_accepted += g;
      continue;
    }
    ++fast_accepted;
    REQUIRE_MESSAGE(g, text);
    CHECK_MESSAGE(same(fast.x, slow.x), text);
    CHECK_MESSAGE(same(fast.y, slow.y), text);
    CHECK_MESSAGE(same(fast.z, slow.z), text);
    CHECK_MESSAGE(same(fast.er, slow.er), text);
    CHECK_MESSAGE(same(fast.tool_a, slow.tool_a), text);
    CHECK_MESSAGE(same(fast.tool_b, slow.tool_b), text);
    CHECK_MESSAGE(same(fast.tool_c, slow.tool_c), text);
    REQUIRE_MESSAGE(fast.ijk.has_value() == slow.ijk.has_value(), text);
    if (fast.ijk)
      for (int a = 0; a < 3; ++a) CHECK_MESSAGE(bits((*fast.ijk)[a]) == bits((*slow.ijk)[a]), text);
  }
  // Every clean answer goes the fast way; the mutants test the refusals.
  CHECK(fast_accepted >= 10000);
  CHECK(mutants == 10000);
  MESSAGE("fast accepted " << fast_accepted << ", left to the general reader although it accepts: "
                           << fast_refused_general_accepted);
}

TEST_CASE("I++ DME point items: numbers the grammar refuses are refused by the fast reader too") {
  IppdmePointItems out;
  for (const char* bad : {"X(1.2.3)", "X(+)", "X(-)", "X(1e)", "X(1e1234)", "X(1-2)", "X(1e5.3)", "X(.)",
                          "X(123456789012345678)", "X(1,2)", "IJK(1,2)", "X(1), X(2)", "X(1),", "Q(1)",
                          "X(1)Y(2)", "X(1e+)", "X(--1)", "X(+-1)", "X(1E3e2)"}) {
    CHECK_MESSAGE(!ippdme_point_items_fast(bad, kIppdmeAnswerDigits, out), bad);
  }
  // Seventeen significant digits after leading zeros are an answer's most.
  CHECK(ippdme_point_items_fast("X(0.00012345678901234567)", kIppdmeAnswerDigits, out));
  CHECK(!ippdme_point_items_fast("X(0.000123456789012345678)", kIppdmeAnswerDigits, out));
  CHECK(!ippdme_point_items_fast("X(12345678901234567)", kIppdmeDigits, out));
  CHECK(ippdme_point_items_fast("X(+.5), Y(-0), Z(1E-3)", kIppdmeAnswerDigits, out));
  CHECK(*out.x == 0.5);
  CHECK(*out.z == 0.001);
}
