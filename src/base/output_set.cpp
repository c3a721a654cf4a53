#include "base/output_set.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/error.hpp"

namespace furrow {

namespace fs = std::filesystem;

namespace {

// ---- temporaries of live sets, for the signal handler -----------------------
// A fixed table of C strings: the handler reads it without locking or
// allocating, and registration never moves an entry the handler may read.
constexpr std::size_t kSlots = 256;
std::array<std::atomic<char*>, kSlots> g_live{};

void register_temporary(const std::string& path) {
  char* copy = ::strdup(path.c_str());
  if (!copy) return;
  for (auto& slot : g_live) {
    char* expected = nullptr;
    if (slot.compare_exchange_strong(expected, copy)) return;
  }
  std::free(copy);  // table full: the next run's stale sweep removes it
}

void unregister_temporary(const std::string& path) {
  for (auto& slot : g_live) {
    char* p = slot.load();
    if (p && path == p && slot.compare_exchange_strong(p, nullptr)) {
      std::free(p);
      return;
    }
  }
}

// What was installed before ours, per signal, so that it still runs.
struct sigaction g_previous[NSIG];

extern "C" void remove_temporaries_and_die(int sig) {
  for (auto& slot : g_live) {
    char* p = slot.exchange(nullptr);
    if (!p) continue;
    // A staged file is one unlink; a staged folder needs a recursive removal,
    // which allocates: acceptable here, as the process ends right after.
    if (::unlink(p) != 0) {
      std::error_code ec;
      fs::remove_all(p, ec);
    }
  }
  // Then whatever handled the signal before us (a test runner, an
  // embedding program), and finally the default action: the process ends as
  // the signal says.
  const struct sigaction& previous = g_previous[sig];
  if (!(previous.sa_flags & SA_SIGINFO) && previous.sa_handler != SIG_DFL && previous.sa_handler != SIG_IGN &&
      previous.sa_handler != remove_temporaries_and_die)
    previous.sa_handler(sig);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// Installed whenever a set is made, not once: a program that installs its
// own handler later (doctest does, per test case) would otherwise silently
// switch the clean-up off.
void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_die;
  sigemptyset(&action.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    ::sigaction(sig, nullptr, &current);
    if (current.sa_handler == remove_temporaries_and_die) continue;
    g_previous[sig] = current;
    ::sigaction(sig, &action, nullptr);
  }
}

// ---- names -----------------------------------------------------------------

std::string temporary_prefix(const fs::path& target) { return "." + target.filename().string() + ".tmp-"; }

fs::path temporary_sibling(const fs::path& target) {
  // pid + counter: unique within a process and across concurrent runs.
  static std::atomic<long> counter{0};
  return target.parent_path() /
         (temporary_prefix(target) + std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

// Removes `.NAME.tmp-PID-N` siblings of `target` whose process is gone (a
// killed run). A temporary of a live process, this one included, is kept.
void remove_stale_temporaries(const fs::path& target) {
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const std::string prefix = temporary_prefix(target);
  std::error_code ec;
  fs::directory_iterator it(parent, ec), end;
  if (ec) return;
  std::vector<fs::path> stale;
  for (; it != end; it.increment(ec)) {
    if (ec) return;
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    const std::size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos) continue;
    char* stop = nullptr;
    const long pid = std::strtol(rest.c_str(), &stop, 10);
    if (stop != rest.c_str() + dash || pid <= 0) continue;
    if (pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    stale.push_back(it->path());
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);
}

void ensure_parent(const fs::path& target) {
  const fs::path parent = target.parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec)
    throw InputError(target.string() + ": cannot create folder " + parent.string() + ": " + ec.message());
}

// The path with links and `..` resolved as far as it exists.
fs::path resolved(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) p = fs::absolute(path, ec).lexically_normal();
  // "reports/demo/" and "reports/demo" are the same folder.
  if (p.filename().empty()) p = p.parent_path();
  return p;
}

bool is_within(const fs::path& inner, const fs::path& outer) {
  const fs::path rel = inner.lexically_relative(outer);
  return !rel.empty() && rel.is_relative() && *rel.begin() != "..";
}

}  // namespace

void check_output_spares_input(const std::string& output, const std::string& input, const std::string& role) {
  const fs::path out = resolved(output), in = resolved(input);
  if (out == in)
    throw InputError(output + ": the output would overwrite the input " + input + " (" + role +
                     "); choose another output path");
  if (is_within(in, out))
    throw InputError(output + ": the output folder holds the input " + input + " (" + role +
                     "): it would be deleted when the folder is replaced; choose another output path");
}

OutputSet::OutputSet() { install_signal_handlers(); }

OutputSet::~OutputSet() {
  if (!published_) discard();
}

void OutputSet::add_input(const std::string& path, const std::string& role) {
  inputs_.push_back({path, role});
  for (const Staged& s : staged_) check_output_spares_input(s.destination, path, role);
}

void OutputSet::check_against_inputs(const std::string& destination) const {
  for (const Input& in : inputs_) check_output_spares_input(destination, in.path, in.role);
  const fs::path mine = resolved(destination);
  for (const Staged& s : staged_)
    if (resolved(s.destination) == mine)
      throw InputError(destination + ": named twice as an output (" + s.destination + ")");
}

void OutputSet::will_write(const std::string& path) {
  check_against_inputs(path);
  for (const std::string& other : intended_)
    if (resolved(other) == resolved(path))
      throw InputError(path + ": names the same file as the output " + other);
  intended_.push_back(path);
}

void OutputSet::file(const std::string& path, const std::string& content) {
  const fs::path target(path);
  if (target.filename().empty() || target.filename() == "." || target.filename() == "..")
    throw InputError(path + ": not a file name");
  check_against_inputs(path);
  ensure_parent(target);
  remove_stale_temporaries(target);
  const fs::path tmp = temporary_sibling(target);
  register_temporary(tmp.string());
  staged_.push_back({path, tmp.string(), false});
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path + ": cannot write the file");
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.flush();
  if (!out) throw InputError(path + ": writing failed (disk full?)");
}

std::string OutputSet::folder(const std::string& path) {
  fs::path target(path);
  if (target.filename().empty()) target = target.parent_path();  // "reports/demo/"
  if (target.empty()) throw InputError(path + ": not a folder name");
  check_against_inputs(target.string());
  ensure_parent(target);
  remove_stale_temporaries(target);
  const fs::path staging = temporary_sibling(target);
  register_temporary(staging.string());
  staged_.push_back({target.string(), staging.string(), true});
  std::error_code ec;
  fs::create_directories(staging, ec);
  if (ec) throw InputError(path + ": cannot create a folder: " + ec.message());
  return staging.string();
}

void OutputSet::publish(const std::string& main) {
  if (published_) throw std::logic_error("OutputSet: published twice");
  std::vector<Staged> order;
  for (const Staged& s : staged_)
    if (s.destination != main) order.push_back(s);
  for (const Staged& s : staged_)
    if (s.destination == main) order.push_back(s);
  std::error_code ec;
  for (const Staged& s : order) {
    if (s.folder && fs::exists(s.destination, ec)) {
      // Move the old folder aside first so the destination is never half old,
      // half new; drop it once the new one is in place.
      const fs::path old = temporary_sibling(s.destination);
      register_temporary(old.string());
      fs::rename(s.destination, old, ec);
      if (ec) throw InputError(s.destination + ": cannot replace the existing folder: " + ec.message());
      fs::rename(s.temporary, s.destination, ec);
      if (ec) {
        fs::rename(old, s.destination, ec);
        unregister_temporary(old.string());
        throw InputError(s.destination + ": cannot move the finished folder into place");
      }
      fs::remove_all(old, ec);
      unregister_temporary(old.string());
    } else {
      fs::rename(s.temporary, s.destination, ec);
      if (ec)
        throw InputError(s.destination + ": cannot move the finished " + (s.folder ? "folder" : "file") +
                         " into place: " + ec.message());
    }
    unregister_temporary(s.temporary);
  }
  published_ = true;
}

std::vector<std::string> OutputSet::destinations() const {
  std::vector<std::string> out;
  for (const Staged& s : staged_) out.push_back(s.destination);
  return out;
}

void OutputSet::discard() noexcept {
  for (const Staged& s : staged_) {
    std::error_code ec;
    fs::remove_all(s.temporary, ec);
    unregister_temporary(s.temporary);
  }
  staged_.clear();
}

}  // namespace furrow
