#include "report_script.hpp"
#include "interruption.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
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

bool write_report(const std::string& script, const std::string& stage, const std::string& out) {
  std::fflush(stdout); // the command's table before the script's own lines
  const int status = run_report_script(script, stage);
  if (status == 0) return true;
  std::fprintf(stderr,
               "rsi: error: the report generator %s/%s failed (status %d); nothing was "
               "written to --out %s; fix it or use --no-report\n",
               RSI_REPORTS_DIR, script.c_str(), status, out.c_str());
  return false;
}

} // namespace rsi
