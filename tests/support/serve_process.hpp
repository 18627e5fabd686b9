// `towdb serve` as a child process for the tests that talk to it over HTTP
// (tests/cli/cli_serve_test.cpp, tests/fuzz/fuzz_http_api_test.cpp).
#ifndef TOWDB_TESTS_SUPPORT_SERVE_PROCESS_HPP
#define TOWDB_TESTS_SUPPORT_SERVE_PROCESS_HPP

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <httplib.h>

#include "test_support.hpp"

extern char** environ;

namespace towdb::test {

// `towdb serve --port 0 ...` as a child process: the port is read from its
// first line; SIGTERM stops it (exit 0).
class ServerProcess {
 public:
  explicit ServerProcess(const std::vector<std::string>& extra_args) {
    std::vector<std::string> args = {towdb_exe().string(), "serve", "--port", "0"};
    args.insert(args.end(), extra_args.begin(), extra_args.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) throw std::runtime_error("spawn");
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    stdout_ = fdopen(out[0], "r");
    char line[512] = {};
    if (!std::fgets(line, sizeof line, stdout_)) throw std::runtime_error("towdb serve printed nothing");
    first_line_ = line;
    const auto at = first_line_.find("http://127.0.0.1:");
    if (at == std::string::npos) throw std::runtime_error("unexpected first line: " + first_line_);
    port_ = std::stoi(first_line_.substr(at + 17));
  }
  ~ServerProcess() {
    if (pid_ > 0) stop();
    if (stdout_) std::fclose(stdout_);
  }
  int stop() {
    kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = 0;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  int port() const { return port_; }
  const std::string& first_line() const { return first_line_; }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(30, 0);
    return c;
  }

 private:
  pid_t pid_ = 0;
  FILE* stdout_ = nullptr;
  std::string first_line_;
  int port_ = 0;
};

}  // namespace towdb::test

#endif  // TOWDB_TESTS_SUPPORT_SERVE_PROCESS_HPP
