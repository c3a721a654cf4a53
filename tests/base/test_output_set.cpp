// OutputSet: outputs appear together or not at all, never over an input, and
// temporaries of interrupted runs do not survive.
#include <doctest/doctest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "base/error.hpp"
#include "base/output_set.hpp"

using namespace furrow;
namespace fs = std::filesystem;

namespace {

std::string scratch(const std::string& name) {
  const fs::path dir = fs::path(FURROW_BINARY_DIR) / "test-scratch" / ("output-set-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Every entry of a folder, recursively, hidden ones included.
std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) out.push_back(fs::relative(e.path(), dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("output set: nothing is visible before publish, everything after") {
  const std::string dir = scratch("publish");
  OutputSet out;
  out.file(dir + "/a.json", "{}");
  out.file(dir + "/maps/b.png", "png");
  const std::string staging = out.folder(dir + "/plan");
  write(staging + "/plan.json", "plan");
  CHECK_FALSE(fs::exists(dir + "/a.json"));
  CHECK_FALSE(fs::exists(dir + "/maps/b.png"));
  CHECK_FALSE(fs::exists(dir + "/plan"));
  out.publish(dir + "/a.json");
  CHECK(read(dir + "/a.json") == "{}");
  CHECK(read(dir + "/maps/b.png") == "png");
  CHECK(read(dir + "/plan/plan.json") == "plan");
  CHECK(entries(dir) == std::vector<std::string>{"a.json", "maps", "maps/b.png", "plan", "plan/plan.json"});
}

TEST_CASE("output set: a failure before publish leaves nothing, and an older output stays as it was") {
  const std::string dir = scratch("failure");
  write(dir + "/a.json", "old");
  write(dir + "/blocker", "a file where a folder is needed");
  try {
    OutputSet out;
    out.file(dir + "/a.json", "new");
    out.file(dir + "/blocker/b.png", "png");  // its folder cannot be made
    FAIL("staging under a file must fail");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find(dir + "/blocker/b.png") == 0);
  }
  CHECK(read(dir + "/a.json") == "old");
  CHECK(entries(dir) == std::vector<std::string>{"a.json", "blocker"});
}

TEST_CASE("output set: a folder output replaces the older folder whole") {
  const std::string dir = scratch("replace");
  fs::create_directories(dir + "/out");
  write(dir + "/out/stale.txt", "from an older run");
  OutputSet out;
  write(out.folder(dir + "/out/") + "/new.txt", "new");
  out.publish();
  CHECK(entries(dir) == std::vector<std::string>{"out", "out/new.txt"});
}

TEST_CASE("output set: an output that is, or holds, an input is refused before anything is written") {
  const std::string dir = scratch("inputs");
  fs::create_directories(dir + "/parts/sub");
  write(dir + "/parts/sub/part.json", "part");
  fs::create_directory_symlink(dir + "/parts", dir + "/link");
  const std::string part = dir + "/parts/sub/part.json";
  struct Case {
    std::string output;
    bool folder;
  };
  const Case cases[] = {
      {part, false},                                    // the input itself
      {dir + "/link/sub/part.json", false},             // through a symbolic link
      {dir + "/parts/sub/../sub/part.json", false},     // through ..
      {dir + "/parts", true},                           // a parent folder
      {dir + "/parts/sub/", true},                      // its folder, trailing slash
      {dir + "/link", true},                            // a link to a parent
      {dir, true},                                      // further up
  };
  for (const Case& c : cases) {
    CAPTURE(c.output);
    OutputSet out;
    out.add_input(part, "part");
    CHECK_THROWS_AS(out.will_write(c.output), InputError);
    try {
      if (c.folder)
        out.folder(c.output);
      else
        out.file(c.output, "x");
      FAIL("must be refused");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("input " + part + " (part)") != std::string::npos);
    }
  }
  CHECK(read(part) == "part");
  // A sibling file and a sibling folder are fine.
  OutputSet ok;
  ok.add_input(part, "part");
  ok.file(dir + "/parts/sub/regions.json", "r");
  ok.folder(dir + "/parts/plan");
  ok.publish();
  CHECK(fs::exists(dir + "/parts/sub/regions.json"));
  // The same destination named twice.
  OutputSet twice;
  twice.will_write(dir + "/x.json");
  CHECK_THROWS_AS(twice.will_write(dir + "/./x.json"), InputError);
}

TEST_CASE("output set: temporaries of a dead process are removed, a live one's are kept") {
  const std::string dir = scratch("stale");
  // A process that has ended: its pid is free (we waited for it).
  const pid_t dead = fork();
  if (dead == 0) _exit(0);
  waitpid(dead, nullptr, 0);
  const std::string stale_file = dir + "/.a.json.tmp-" + std::to_string(dead) + "-0";
  const std::string stale_folder = dir + "/.out.tmp-" + std::to_string(dead) + "-3";
  write(stale_file, "half");
  fs::create_directories(stale_folder + "/x");
  const std::string live = dir + "/.a.json.tmp-1-0";  // pid 1 always runs
  write(live, "someone else's");
  const std::string other = dir + "/.b.json.tmp-" + std::to_string(dead) + "-0";  // another destination
  write(other, "not ours to judge");
  OutputSet out;
  out.file(dir + "/a.json", "{}");
  out.folder(dir + "/out");
  out.publish();
  CHECK_FALSE(fs::exists(stale_file));
  CHECK_FALSE(fs::exists(stale_folder));
  CHECK(fs::exists(live));
  CHECK(fs::exists(other));
}

TEST_CASE("output set: SIGTERM during the work removes the staged temporaries") {
  const std::string dir = scratch("signal");
  int ready[2];
  REQUIRE(pipe(ready) == 0);
  const pid_t child = fork();
  if (child == 0) {
    OutputSet out;
    out.file(dir + "/a.json", "{}");
    write(out.folder(dir + "/plan") + "/plan.json", "plan");
    (void)!::write(ready[1], "x", 1);
    for (;;) pause();
  }
  char c = 0;
  REQUIRE(::read(ready[0], &c, 1) == 1);
  CHECK(entries(dir).size() == 3);  // the staged file, folder and its file
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(entries(dir).empty());
  close(ready[0]);
  close(ready[1]);
}
