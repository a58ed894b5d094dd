#include "report_script.hpp"
#include "interruption.hpp"

#include <cerrno>
#include <csignal>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

namespace rsi {

int run_report_script(const std::string& script, const std::string& dir) {
  const std::string python = "/usr/bin/python3";
  std::vector<std::string> args{python, std::string(RSI_REPORTS_DIR) + "/" + script, dir};
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  // The script's stdout (its "wrote DIR/report.md" line) would name the
  // staging folder it runs in (staged_output.hpp); rsi names the published
  // report itself. Its stderr (tracebacks) stays.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return 127;
  int status = 0;
  pid_t waited = 0;
  do {
    waited = waitpid(pid, &status, 0);
    if (waited < 0 && errno == EINTR && pending_signal() != 0) {
      // Interrupted: the script must not go on writing after rsi has exited.
      kill(pid, SIGTERM);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      throw_if_interrupted();
    }
  } while (waited < 0 && errno == EINTR);
  if (waited != pid) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

} // namespace rsi
