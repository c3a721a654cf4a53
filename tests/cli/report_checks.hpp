#pragma once
// Independent checks of a QA report folder for the end-to-end tests:
//  - report.json against docs/report.schema.json with python3-jsonschema
//    (another implementation than ours, in another language);
//  - report.html rendered by headless Chromium: the DOM after load (with
//    the page's data-images-loaded="n/m" marker) and a screenshot.
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "support/run_cli.hpp"

namespace furrow::test {

struct ShellResult {
  int status = -1;
  std::string out;
};

inline ShellResult run_shell(const std::string& command, const std::string& capture) {
  const int raw = std::system((command + " > " + shell_quote(capture) + " 2>&1").c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(capture)};
}

// Exit status 0 and "valid" when the document validates; 3 when python3 or
// jsonschema is missing (scripts/install-deps.sh installs python3-jsonschema).
inline ShellResult validate_with_jsonschema(const std::string& schema, const std::string& document,
                                            const std::string& scratch) {
  const std::string script =
      "import json, sys\n"
      "try:\n"
      "    import jsonschema\n"
      "except ImportError:\n"
      "    print('python3-jsonschema is not installed (scripts/install-deps.sh)'); sys.exit(3)\n"
      "schema = json.load(open(sys.argv[1]))\n"
      "jsonschema.Draft202012Validator.check_schema(schema)\n"
      "errors = list(jsonschema.Draft202012Validator(schema).iter_errors(json.load(open(sys.argv[2]))))\n"
      "for e in errors[:5]: print('/'.join(map(str, e.absolute_path)), e.message[:200])\n"
      "print('valid' if not errors else 'invalid'); sys.exit(1 if errors else 0)\n";
  write_text(scratch + "/validate.py", script);
  return run_shell("python3 " + shell_quote(scratch + "/validate.py") + " " + shell_quote(schema) + " " +
                       shell_quote(document),
                   scratch + "/validate.out");
}

constexpr const char* kChromium = "/usr/bin/chromium";

struct BrowserRender {
  bool available = false;  // /usr/bin/chromium exists
  int dom_status = -1, screenshot_status = -1;
  std::string dom;
  cv::Mat screenshot;
};

// Two headless runs (DOM dump, then a 1280 x 1600 screenshot), each with a
// fresh profile folder, no network services, and a time limit.
inline BrowserRender render_in_chromium(const std::string& html, const std::string& scratch) {
  BrowserRender r;
  r.available = std::filesystem::exists(kChromium);
  if (!r.available) return r;
  const std::string url = "file://" + std::filesystem::absolute(html).string();
  auto command = [&](const std::string& profile, const std::string& action) {
    std::filesystem::remove_all(profile);
    std::filesystem::create_directories(profile);
    return std::string("timeout 120 ") + kChromium +
           " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking"
           " --disable-component-update --disable-sync --user-data-dir=" +
           shell_quote(profile) + " " + action + " " + shell_quote(url);
  };
  r.dom_status = std::system((command(scratch + "/profile-dom", "--dump-dom") + " > " +
                              shell_quote(scratch + "/dom.html") + " 2> " + shell_quote(scratch + "/dom.log"))
                                 .c_str());
  r.dom = slurp(scratch + "/dom.html");
  const std::string shot = scratch + "/screenshot.png";
  r.screenshot_status = std::system((command(scratch + "/profile-shot", "--window-size=1280,1600 --screenshot=" +
                                                                             shell_quote(shot)) +
                                     " > " + shell_quote(scratch + "/shot.log") + " 2>&1")
                                        .c_str());
  r.screenshot = cv::imread(shot, cv::IMREAD_COLOR);
  return r;
}

// Pixels within `tolerance` of an sRGB colour inside `area`.
inline int pixels_near(const cv::Mat& img, cv::Rect area, int r, int g, int b, int tolerance = 8) {
  area &= cv::Rect(0, 0, img.cols, img.rows);
  int n = 0;
  for (int y = area.y; y < area.y + area.height; ++y)
    for (int x = area.x; x < area.x + area.width; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      n += std::abs(p[2] - r) <= tolerance && std::abs(p[1] - g) <= tolerance && std::abs(p[0] - b) <= tolerance;
    }
  return n;
}

}  // namespace furrow::test
