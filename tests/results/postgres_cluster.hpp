#pragma once
// A real, throwaway PostgreSQL cluster for the results-database tests
// (docs/results_database.md "PostgreSQL"): initdb and pg_ctl of Debian's
// postgresql package (/usr/lib/postgresql/*/bin) in a fresh temporary
// folder, a free local port, the unix socket in that folder, trust
// authentication for its one superuser. PostgreSQL refuses to run as root:
// as root the folder is given to the `postgres` user and the server runs as
// it (runuser). A watchdog process stops the server and removes the folder
// when the test process ends, however it ends (even killed or crashed).
// Without initdb the cluster cannot start: the constructor throws, and
// every test that needs it fails saying so (never skips).
#include <arpa/inet.h>
#include <fcntl.h>
#include <glob.h>
#include <libpq-fe.h>
#include <netinet/in.h>
#include <pwd.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/run_cli.hpp"

namespace furrow::test {

class PostgresCluster {
 public:
  static constexpr const char* kSuperuser = "furrow_admin";

  // `durable`: fsync as a production server does (benchmarks); the tests'
  // cluster skips it, a crash of the machine is not what they test.
  explicit PostgresCluster(bool durable = false) {
    bin_ = find_bin();
    char pattern[] = "/tmp/furrow-pg-XXXXXX";
    if (!::mkdtemp(pattern)) throw std::runtime_error("PostgreSQL test cluster: cannot make a temporary folder");
    dir_ = pattern;
    start_watchdog();
    as_root_ = ::geteuid() == 0;
    if (as_root_) {
      const passwd* pg = ::getpwnam("postgres");
      if (!pg) throw std::runtime_error("PostgreSQL test cluster: running as root, and there is no user postgres "
                                        "to run the server as (install the Debian package postgresql)");
      if (::chown(dir_.c_str(), pg->pw_uid, pg->pw_gid) != 0)
        throw std::runtime_error("PostgreSQL test cluster: cannot give " + dir_ + " to the user postgres");
    }
    run(shell_quote(bin_ + "/initdb") + " -D " + shell_quote(dir_ + "/data") + " -U " + kSuperuser +
            " --auth=trust -E UTF8 --locale=C -N > " + shell_quote(dir_ + "/initdb.log") + " 2>&1",
        "initdb");
    // A port bound by nobody a moment ago; retried if taken in between.
    for (int attempt = 0;; ++attempt) {
      port_ = free_port();
      const std::string options = "-p " + std::to_string(port_) + " -k " + dir_ +
                                  " -c listen_addresses=127.0.0.1 -c max_connections=40" +
                                  (durable ? "" : " -c fsync=off");
      const std::string command = shell_quote(bin_ + "/pg_ctl") + " -D " + shell_quote(dir_ + "/data") + " -l " +
                                  shell_quote(dir_ + "/server.log") + " -w -t 60 -o " + shell_quote(options) +
                                  " start > " + shell_quote(dir_ + "/pg_ctl.log") + " 2>&1";
      if (system_as_server_user(command) == 0) break;
      if (attempt == 2)
        throw std::runtime_error("PostgreSQL test cluster: pg_ctl start failed; server log: " +
                                 slurp(dir_ + "/server.log"));
    }
  }

  ~PostgresCluster() {
    // Closing the pipe tells the watchdog to stop the server and clean up.
    if (watchdog_fd_ >= 0) ::close(watchdog_fd_);
    if (watchdog_ > 0) ::waitpid(watchdog_, nullptr, 0);
  }

  PostgresCluster(const PostgresCluster&) = delete;
  PostgresCluster& operator=(const PostgresCluster&) = delete;

  const std::string& socket_dir() const { return dir_; }
  int port() const { return port_; }

  // A new, empty database; its location as a URI (socket folder and port
  // as query parameters).
  std::string new_database(const std::string& hint) {
    const std::string name = hint + "_" + std::to_string(++databases_) + "_" + std::to_string(::getpid());
    exec("postgres", "CREATE DATABASE " + name);
    return uri(name);
  }

  std::string uri(const std::string& database, const std::string& user = kSuperuser) const {
    return "postgresql://" + user + "@/" + database + "?host=" + dir_ + "&port=" + std::to_string(port_);
  }

  // The same database as key=value pairs.
  std::string key_value(const std::string& database, const std::string& user = kSuperuser) const {
    return "host=" + dir_ + " port=" + std::to_string(port_) + " dbname=" + database + " user=" + user;
  }

  static std::string database_of(const std::string& uri) {
    const std::size_t slash = uri.find("@/") + 2;
    return uri.substr(slash, uri.find('?') - slash);
  }

  // The first value of a query's first row by libpq on a fresh connection
  // (the tests' own reader); "" for no row, "error: ..." when it fails.
  std::string query(const std::string& database, const std::string& sql) const {
    PGconn* c = connect(database);
    PGresult* r = PQexec(c, sql.c_str());
    std::string out;
    if (PQresultStatus(r) == PGRES_TUPLES_OK) {
      if (PQntuples(r) > 0 && !PQgetisnull(r, 0, 0)) out = PQgetvalue(r, 0, 0);
    } else if (PQresultStatus(r) != PGRES_COMMAND_OK) {
      out = std::string("error: ") + PQerrorMessage(c);
    }
    PQclear(r);
    PQfinish(c);
    return out;
  }

  // True when the statements ran.
  bool exec(const std::string& database, const std::string& sql) const {
    PGconn* c = connect(database);
    PGresult* r = PQexec(c, sql.c_str());
    const bool ok = PQresultStatus(r) == PGRES_COMMAND_OK || PQresultStatus(r) == PGRES_TUPLES_OK;
    PQclear(r);
    PQfinish(c);
    return ok;
  }

  // The role furrow_writer with exactly the grants docs/results_database.md
  // "Grants" gives a writer on `database` (the tables must exist); its URI.
  std::string documented_writer(const std::string& database) const {
    if (!exec("postgres", "DO $$ BEGIN IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname = 'furrow_writer') "
                          "THEN CREATE ROLE furrow_writer LOGIN; END IF; END $$") ||
        !exec(database, "GRANT CONNECT ON DATABASE " + database + " TO furrow_writer;"
                        "GRANT USAGE ON SCHEMA public TO furrow_writer;"
                        "GRANT SELECT, INSERT ON meta, parts, points, regions, inputs TO furrow_writer;"))
      throw std::runtime_error("PostgreSQL test cluster: cannot grant furrow_writer on " + database);
    return uri(database, "furrow_writer");
  }

  // Runs an SQL script with PostgreSQL's own psql (which reads what
  // pg_dump writes, meta-commands included), stopping at the first error.
  void psql_file(const std::string& database, const std::string& script) const {
    const std::string log = dir_ + "/psql.log";
    const std::string command = shell_quote(bin_ + "/psql") + " -X -q -v ON_ERROR_STOP=1 -h " + shell_quote(dir_) +
                                " -p " + std::to_string(port_) + " -U " + kSuperuser + " -d " + database + " -f " +
                                shell_quote(script) + " > " + shell_quote(log) + " 2>&1";
    const int raw = std::system(command.c_str());
    if (!WIFEXITED(raw) || WEXITSTATUS(raw) != 0)
      throw std::runtime_error("PostgreSQL test cluster: psql -f " + script + " failed: " + slurp(log));
  }

 private:
  static std::string find_bin() {
    glob_t g{};
    std::vector<std::string> found;
    if (::glob("/usr/lib/postgresql/*/bin/initdb", 0, nullptr, &g) == 0)
      for (std::size_t k = 0; k < g.gl_pathc; ++k) found.push_back(g.gl_pathv[k]);
    ::globfree(&g);
    if (found.empty())
      throw std::runtime_error("PostgreSQL test cluster: no initdb in /usr/lib/postgresql/*/bin; install the "
                               "Debian package postgresql (scripts/install-deps.sh) - these tests do not skip");
    // The newest major version.
    std::sort(found.begin(), found.end(), [](const std::string& a, const std::string& b) {
      return std::atoi(a.c_str() + 20) < std::atoi(b.c_str() + 20);
    });
    return std::filesystem::path(found.back()).parent_path().string();
  }

  static int free_port() {
    const int s = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof a;
    if (s < 0 || ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
        ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &len) != 0)
      throw std::runtime_error("PostgreSQL test cluster: cannot find a free local port");
    ::close(s);
    return ntohs(a.sin_port);
  }

  int system_as_server_user(const std::string& command) const {
    const std::string full = "cd " + shell_quote(dir_) + " && " +
                             (as_root_ ? "runuser -u postgres -- sh -c " + shell_quote(command) : command);
    const int raw = std::system(full.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  }

  void run(const std::string& command, const std::string& what) const {
    if (system_as_server_user(command) != 0)
      throw std::runtime_error("PostgreSQL test cluster: " + what + " failed: " + slurp(dir_ + "/" + what + ".log"));
  }

  // A child that waits until every copy of the pipe's write end is closed
  // (this process ended, or the destructor ran), then stops the server and
  // removes the folder.
  void start_watchdog() {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("PostgreSQL test cluster: no pipe for the watchdog");
    watchdog_ = ::fork();
    if (watchdog_ < 0) throw std::runtime_error("PostgreSQL test cluster: cannot fork the watchdog");
    if (watchdog_ == 0) {
      ::close(fds[1]);
      // Leave the test's own standard streams to the test.
      char c;
      while (::read(fds[0], &c, 1) != 0) {
      }
      const std::string data = dir_ + "/data";
      if (std::filesystem::exists(data + "/postmaster.pid")) {
        const std::string bin = bin_;
        const std::string command = shell_quote(bin + "/pg_ctl") + " -D " + shell_quote(data) +
                                    " -m immediate -w stop > /dev/null 2>&1";
        const std::string full = "cd / && " + std::string(::geteuid() == 0 ? "runuser -u postgres -- sh -c " +
                                                                               shell_quote(command)
                                                                         : command);
        [[maybe_unused]] const int ignored = std::system(full.c_str());
      }
      std::error_code ec;
      std::filesystem::remove_all(dir_, ec);
      ::_exit(0);
    }
    ::close(fds[0]);
    // Programs the tests start (furrow, initdb, pg_ctl) do not keep it open.
    ::fcntl(fds[1], F_SETFD, FD_CLOEXEC);
    watchdog_fd_ = fds[1];
  }

  PGconn* connect(const std::string& database) const {
    const std::string info = key_value(database);
    PGconn* c = PQconnectdb(info.c_str());
    if (PQstatus(c) != CONNECTION_OK) {
      const std::string message = PQerrorMessage(c);
      PQfinish(c);
      throw std::runtime_error("PostgreSQL test cluster: cannot connect to " + database + ": " + message);
    }
    PQsetNoticeProcessor(c, [](void*, const char*) {}, nullptr);
    return c;
  }

  std::string bin_, dir_;
  bool as_root_ = false;
  int port_ = 0;
  int databases_ = 0;
  pid_t watchdog_ = -1;
  int watchdog_fd_ = -1;
};

// The one cluster of this test process, started on first use.
inline PostgresCluster& postgres_cluster() {
  static PostgresCluster cluster;
  return cluster;
}

}  // namespace furrow::test
