// Runs a Python helper script (the comparison plots) as a child process, never through a shell.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace upf {

// Exit code of our scripts when a module they need (matplotlib) cannot be imported: the runner
// then tries the next interpreter.
inline constexpr int kPythonMissingModuleExit = 3;

struct PythonRun {
  bool ok = false;
  std::string interpreter;  // the last one tried
  std::string error;        // why it did not succeed, for the user
  // No interpreter could import what the script needs (each exited kPythonMissingModuleExit or
  // did not start): the environment lacks a package, the script did not fail.
  bool missing_module = false;
};

// Interpreters in the order they are tried: $UPF_PYTHON alone when set; otherwise python3 on
// PATH, then /usr/bin/python3 (Debian's python3-matplotlib installs for the system interpreter,
// while a pyenv or venv python3 may come first on PATH).
std::vector<std::string> python_candidates();

// Runs `interpreter script args...` for each candidate until one exits with anything but
// kPythonMissingModuleExit. The child's stdout and stderr are appended to `log`.
PythonRun run_python_script(const std::filesystem::path& script,
                            const std::vector<std::string>& args, const std::filesystem::path& log);

}  // namespace upf
