#include "framework/compare/python_runner.h"

#include <unistd.h>

#include <cstdlib>

#include "framework/core/child_process.h"

namespace upf {

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
  run.missing_module = true;
  return run;
}

}  // namespace upf
