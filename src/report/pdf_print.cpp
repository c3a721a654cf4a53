#include "report/pdf_print.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "base/error.hpp"
#include "report/print_style.hpp"

namespace furrow {

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A temporary folder removed when the printer returns or throws.
struct TemporaryFolder {
  fs::path path;
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "furrow-pdf-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("report.pdf: cannot create a temporary folder");
    path = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
};

// Runs argv[0] with the arguments, stdout and stderr to `log`; the exit
// status, or -1 when it had to be killed after `timeout_seconds`.
int run_process(const std::vector<std::string>& args, const fs::path& log, int timeout_seconds) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("report.pdf: cannot start " + args[0]);
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = ::open("/dev/null", O_RDONLY);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
    }
    if (null >= 0) ::dup2(null, 0);
    ::setpgid(0, 0);  // its own process group: a timeout ends Chromium's helpers too
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_seconds);
  for (;;) {
    int status = 0;
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    if (done < 0) throw std::runtime_error("report.pdf: lost track of " + args[0]);
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(-pid, SIGKILL);
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

std::string tail_of(const std::string& text, std::size_t n) {
  return text.size() <= n ? text : "..." + text.substr(text.size() - n);
}

}  // namespace

void print_pdf(const std::string& html_path, const std::string& pdf_path, const PdfOptions& options) {
  const std::string size = paper_size_css(options.paper, "--paper");
  std::error_code ec;
  if (!fs::exists(options.chromium, ec))
    throw InputError("report.pdf: printing to PDF needs Chromium, and " + options.chromium +
                     " does not exist: install the Debian package chromium (scripts/install-deps.sh)");
  const std::string html = slurp(html_path);
  if (html.empty()) throw InputError(html_path + ": cannot read the report to print");
  // A copy with the paper size set last, so it wins over the page's A4 (the
  // page is self-contained: it refers to nothing next to it).
  TemporaryFolder temp;
  const fs::path copy = temp.path / "report.html";
  std::string printed = html;
  const std::size_t head = printed.find("</head>");
  printed.insert(head == std::string::npos ? 0 : head, "<style>@page{size:" + size + "}</style>\n");
  { std::ofstream(copy, std::ios::binary) << printed; }

  const fs::path out = fs::absolute(pdf_path);
  fs::remove(out, ec);
  const std::vector<std::string> args = {
      options.chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
      "--disable-background-networking", "--disable-component-update", "--disable-sync", "--disable-extensions",
      "--no-pdf-header-footer", "--run-all-compositor-stages-before-draw", "--virtual-time-budget=10000",
      "--user-data-dir=" + (temp.path / "profile").string(), "--print-to-pdf=" + out.string(),
      "file://" + fs::absolute(copy).string()};
  const fs::path log = temp.path / "chromium.log";
  const int status = run_process(args, log, options.timeout_seconds);
  if (status == -1)
    throw std::runtime_error("report.pdf: Chromium did not finish within " + std::to_string(options.timeout_seconds) +
                             " s");
  const std::string pdf = slurp(out);
  if (status != 0 || pdf.compare(0, 5, "%PDF-") != 0)
    throw std::runtime_error("report.pdf: Chromium failed (exit status " + std::to_string(status) +
                             "): " + tail_of(slurp(log), 600));
}

}  // namespace furrow
