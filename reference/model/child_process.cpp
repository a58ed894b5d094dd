#include "child_process.hpp"
#include "interruption_flag.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rsi {

std::string command_text(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& a : argv) {
    if (!text.empty()) text += ' ';
    text += a;
  }
  return text;
}

bool executable_on_path(const std::string& program) {
  if (program.empty()) return false;
  if (program.find('/') != std::string::npos) return access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::istringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + program;
    struct stat st {};
    if (stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        access(candidate.c_str(), X_OK) == 0)
      return true;
  }
  return false;
}

ChildResult run_child(const std::vector<std::string>& argv, const std::string& working_dir,
                      const std::string& log_path) {
  if (argv.empty()) throw std::invalid_argument("run_child: empty argument list");
  ChildResult result;
  std::vector<std::string> args = argv;
  std::vector<char*> pointers;
  for (std::string& a : args)
    pointers.push_back(a.data());
  pointers.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  int rc = 0;
  if (!working_dir.empty())
    rc = posix_spawn_file_actions_addchdir_np(&actions, working_dir.c_str());
  // The log path is opened by the child after the chdir: make it absolute
  // relative to the parent's directory first.
  std::string log = log_path;
  if (!log.empty() && log.front() != '/') {
    char cwd[4096];
    if (getcwd(cwd, sizeof cwd) != nullptr) log = std::string(cwd) + "/" + log;
  }
  if (rc == 0)
    rc = posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                          O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (rc == 0) rc = posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  if (rc == 0)
    rc = posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  // Its own process group (see the header), and SIGINT/SIGTERM at their
  // default action whatever rsi's disposition.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  if (rc == 0) rc = posix_spawnattr_setpgroup(&attributes, 0);
  if (rc == 0) rc = posix_spawnattr_setsigdefault(&attributes, &defaults);
  if (rc == 0)
    rc = posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF);
  pid_t pid = 0;
  if (rc == 0) rc = posix_spawnp(&pid, pointers[0], &actions, &attributes, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (rc != 0) {
    result.error = std::string("cannot start '") + argv[0] + "': " + std::strerror(rc);
    return result;
  }
  result.started = true;
  int status = 0;
  pid_t waited = 0;
  int forwarded = 0; // the signal sent to the child's group, 0 if none
  std::chrono::steady_clock::time_point sent;
  for (;;) {
    waited = waitpid(pid, &status, WNOHANG);
    if (waited < 0 && errno == EINTR) continue;
    if (waited != 0) break;
    const int signal = pending_interruption();
    if (signal != 0 && forwarded == 0) {
      forwarded = signal;
      sent = std::chrono::steady_clock::now();
      kill(-pid, signal);
    } else if (forwarded != 0 && forwarded != SIGKILL &&
               std::chrono::steady_clock::now() - sent > std::chrono::seconds(5)) {
      forwarded = SIGKILL; // the child ignores the signal: stopped all the same
      kill(-pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (forwarded != 0 && waited == pid) {
    // What the child's group started may outlive it: the group goes too.
    kill(-pid, SIGKILL);
    throw_if_interrupted();
  }
  if (waited != pid) {
    result.error = std::string("waitpid failed: ") + std::strerror(errno);
  } else if (WIFEXITED(status)) {
    result.exit_status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
  std::ifstream in(log);
  std::ostringstream text;
  text << in.rdbuf();
  result.output = text.str();
  return result;
}

} // namespace rsi
