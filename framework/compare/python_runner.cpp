#include "framework/compare/python_runner.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

extern char** environ;  // the environment the child inherits (POSIX)

namespace upf {

namespace {

struct ChildExit {
  bool started = false;
  int code = -1;  // exit status, or -1 when killed by a signal
  std::string error;
};

ChildExit spawn_and_wait(const std::vector<std::string>& argv, const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ChildExit out;
  if (rc != 0) {
    out.error = "cannot start " + argv[0] + ": " + std::strerror(rc);
    return out;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      out.error = std::string("waiting for ") + argv[0] + " failed: " + std::strerror(errno);
      return out;
    }
  }
  out.started = true;
  out.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

// The last non-empty line the script wrote: its error message or the exception's last line.
std::string last_line(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

}  // namespace

std::vector<std::string> python_candidates() {
  if (const char* chosen = std::getenv("UPF_PYTHON"); chosen && *chosen) return {chosen};
  std::vector<std::string> out = {"python3"};
  if (access("/usr/bin/python3", X_OK) == 0) out.push_back("/usr/bin/python3");
  return out;
}

PythonRun run_python_script(const std::filesystem::path& script,
                            const std::vector<std::string>& args,
                            const std::filesystem::path& log) {
  PythonRun run;
  std::string failures;
  for (const auto& interpreter : python_candidates()) {
    run.interpreter = interpreter;
    std::vector<std::string> argv = {interpreter, script.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    const ChildExit child = spawn_and_wait(argv, log);
    std::string why;
    if (!child.started) {
      why = child.error;
    } else if (child.code == 0) {
      run.ok = true;
      return run;
    } else if (child.code == kPythonMissingModuleExit) {
      why = interpreter + ": " + last_line(log);
    } else {
      // The script itself failed: another interpreter would fail the same way.
      run.error = interpreter + " " + script.string() + " exited with " +
                  (child.code < 0 ? std::string("a signal") : std::to_string(child.code)) + ": " +
                  last_line(log) + " (full output in " + log.string() + ")";
      return run;
    }
    failures += (failures.empty() ? "" : "; ") + why;
  }
  run.error = failures;
  return run;
}

}  // namespace upf
