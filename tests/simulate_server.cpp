// build/simulate_server SOCKET_FD — the robustness suite's ./simulate, forked (tests/robustness/
// forked_runs.py). Started once per worker, after the libraries' start-up that every ./simulate
// process pays (about 85 ms of a refusal's 120 ms of CPU on the suite's machine, most of it
// the dynamic loader binding SimGrid's and ns-3's libraries), it forks one child per case, and
// the child runs ./simulate's own main (ncube::simulate_main) from the case's arguments, as a
// new process of ./simulate would from its first line on: in a session of its own, in the
// case's folder, with the case's environment, stdin, stdout and stderr (passed as descriptors),
// address-space, core and file-size limits, and the default signal dispositions the exec'd
// program would have. Linked as build/simulate is (its allocator too). It ends as a returning
// main does, but for the libraries' static destructors where SimGrid never started (run_case).
// The binary's own start and exit are tried by the other tests (tests/cli_test.sh and every
// script test that runs build/simulate).
//
// Protocol, one request at a time over a SOCK_SEQPACKET socket: a request is one packet of JSON
// {"args": [...] (argv[1:]), "cwd": DIR, "env": {NAME: VALUE} (the whole environment),
// "as_bytes": N, "fsize_bytes": N or 0, "ignore_xfsz": BOOL} carrying three descriptors
// (stdin, stdout, stderr); the answers are the packets "pid N" (at once) and "status S
// maxrss KB" (S as wait(2) gives it, when the child has ended). A closed socket ends the server.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <simgrid/s4u/Engine.hpp>

#include "tools/simulate_command.h"

namespace {

constexpr int kDescriptors = 3;

// One request: its JSON text and its descriptors; false when the socket is closed.
bool receive(int socket_fd, std::vector<char>& buffer, std::string& text,
             int (&fds)[kDescriptors]) {
  iovec io{buffer.data(), buffer.size()};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int) * kDescriptors)];
  msghdr message{};
  message.msg_iov = &io;
  message.msg_iovlen = 1;
  message.msg_control = control;
  message.msg_controllen = sizeof control;
  const ssize_t n = recvmsg(socket_fd, &message, MSG_CMSG_CLOEXEC);
  if (n <= 0) return false;
  if (message.msg_flags & (MSG_TRUNC | MSG_CTRUNC)) {
    std::fprintf(stderr, "simulate_server: a request over %zu bytes or 3 descriptors\n",
                 buffer.size());
    std::exit(7);
  }
  const cmsghdr* header = CMSG_FIRSTHDR(&message);
  if (!header || header->cmsg_type != SCM_RIGHTS ||
      header->cmsg_len != CMSG_LEN(sizeof(int) * kDescriptors)) {
    std::fprintf(stderr, "simulate_server: a request without its 3 descriptors\n");
    std::exit(7);
  }
  std::memcpy(fds, CMSG_DATA(header), sizeof(int) * kDescriptors);
  text.assign(buffer.data(), std::size_t(n));
  return true;
}

void answer(int socket_fd, const std::string& text) {
  if (send(socket_fd, text.data(), text.size(), MSG_NOSIGNAL) < 0) std::exit(0);  // client gone
}

// In the child: the process a fresh exec of ./simulate would be, then its main.
[[noreturn]] void run_case(const nlohmann::json& request, const int (&fds)[kDescriptors],
                          int socket_fd) {
  setsid();
  for (int target = 0; target < kDescriptors; ++target) dup2(fds[target], target);
  for (int fd : fds)
    if (fd > 2) close(fd);
  close(socket_fd);
  for (int s : {SIGPIPE, SIGXFSZ, SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGCHLD}) signal(s, SIG_DFL);
  if (request.value("ignore_xfsz", false)) signal(SIGXFSZ, SIG_IGN);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  const std::string cwd = request.at("cwd");
  if (chdir(cwd.c_str()) != 0) {
    std::fprintf(stderr, "simulate_server: cannot enter %s\n", cwd.c_str());
    _exit(127);
  }
  clearenv();
  for (const auto& [name, value] : request.at("env").items())
    setenv(name.c_str(), value.get<std::string>().c_str(), 1);
  const auto limit = [](int resource, rlim_t bytes) {
    const rlimit r{bytes, bytes};
    setrlimit(resource, &r);
  };
  limit(RLIMIT_AS, request.at("as_bytes").get<rlim_t>());
  limit(RLIMIT_CORE, 0);
  if (const rlim_t fsize = request.value("fsize_bytes", rlim_t(0))) limit(RLIMIT_FSIZE, fsize);
  std::vector<std::string> words{"simulate"};
  for (const auto& arg : request.at("args")) words.push_back(arg.get<std::string>());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const int code = ncube::simulate_main(int(words.size()), argv.data());
  // A run that started SimGrid ends as a returning main does (std::exit): SimGrid's at-exit
  // work (its log appenders' files closed, --cfg=debug/clean-atexit) is part of what the
  // case tries. One that ended before SimGrid started (most cases: refusals of options and
  // inputs) has nothing left at exit but its streams, flushed here, and the libraries' static
  // destructors, freeing ns-3's and SimGrid's start-up objects: in a forked child each page
  // they write is first copied from the server (about 740 page faults, 30 ms of CPU of a
  // refusal's 39 ms on the suite's machine), and nothing they do shows outside the process.
  // Those destructors are run by every test that starts build/simulate itself.
  if (simgrid::s4u::Engine::is_initialized()) std::exit(code);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  _exit(code);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: simulate_server SOCKET_FD (tests/robustness/forked_runs.py)\n");
    return 2;
  }
  const int socket_fd = std::atoi(argv[1]);
  std::vector<char> buffer(std::size_t(4) << 20);
  std::string text;
  int fds[kDescriptors];
  while (receive(socket_fd, buffer, text, fds)) {
    const nlohmann::json request = nlohmann::json::parse(text);
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) run_case(request, fds, socket_fd);
    for (int fd : fds) close(fd);
    if (pid < 0) {
      answer(socket_fd, "pid -1");
      continue;
    }
    answer(socket_fd, "pid " + std::to_string(pid));
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    answer(socket_fd,
           "status " + std::to_string(status) + " maxrss " + std::to_string(usage.ru_maxrss));
  }
  return 0;
}
