#include "coupling/mesh/isolated_read.h"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <vector>

#include "coupling/mesh/mesh_error.h"
#include "framework/core/errors.h"
#include "framework/core/state_stream.h"

namespace upf {

namespace {

enum class Outcome : std::uint8_t { Mesh = 0, BadInput = 1, Failure = 2 };

void write_all(int fd, const std::vector<char>& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += std::size_t(n);
  }
}

// Everything the child sends until it closes the pipe, or nothing once `seconds` have passed
// (then `timed_out`).
std::vector<char> read_all(int fd, double seconds, bool& timed_out) {
  std::vector<char> bytes;
  char buffer[65536];
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd ready{fd, POLLIN, 0};
    const int polled = left.count() > 0 ? ::poll(&ready, 1, int(left.count())) : 0;
    if (polled < 0 && errno == EINTR) continue;
    if (polled == 0) {
      timed_out = true;
      return {};
    }
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.insert(bytes.end(), buffer, buffer + n);
  }
  return bytes;
}

// How long the reader may take on `file`: assimp reads a well-formed mesh in far less, but loops
// for ever on some broken headers (fuzz_mesh found a 308-byte PLY that never finished).
double time_limit(const std::string& file) {
  std::error_code error;
  const auto bytes = std::filesystem::file_size(file, error);
  return 5.0 + (error ? 0.0 : 2.0 * double(bytes) / 1e6);
}

[[noreturn]] void child(int fd, const std::function<TriangleMesh()>& read) {
  // A crash in the child is the parent's to report: no handler (a sanitizer's, a fuzzer's) of
  // the parent's may turn it into a report of its own.
  for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(s, SIG_DFL);
  // The reader dies with the process that waits for it: a parent killed mid-read (a timeout, a
  // kill -9) must not leave assimp running with the parent's output streams open (ctest waited
  // for such an orphan, which held the fuzz test's pipe).
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  StateWriter out;
  try {
    const TriangleMesh mesh = read();
    out.put(Outcome::Mesh);
    std::vector<double> xyz;
    xyz.reserve(mesh.vertices.size() * 3);
    for (const auto& v : mesh.vertices) xyz.insert(xyz.end(), {v.x(), v.y(), v.z()});
    out.put_vector(xyz);
    out.put_vector(mesh.triangles);
  } catch (const InputError& e) {
    out.put(Outcome::BadInput);
    const InputProblem first =
        e.problems().empty() ? InputProblem{"", e.what()} : e.problems().front();
    out.put_string(first.where);
    out.put_string(first.message);
  } catch (const std::exception& e) {
    out.put(Outcome::Failure);
    out.put_string(e.what());
  }
  write_all(fd, out.bytes());
  ::close(fd);
  ::_exit(0);  // no atexit handlers, no destructors of the parent's objects
}

}  // namespace

TriangleMesh read_isolated(const std::function<TriangleMesh()>& read, const std::string& file,
                           const std::string& where) {
  int fds[2];
  if (::pipe(fds) != 0) return read();  // no pipe: read in this process, as before
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return read();
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], read);
  }
  ::close(fds[1]);
  bool timed_out = false;
  const double limit = time_limit(file);
  std::vector<char> bytes = read_all(fds[0], limit, timed_out);
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.0f", limit);
    throw mesh_error(file, where,
                     std::string("the mesh reader (assimp) did not finish within ") + seconds +
                         " s (5 s and 2 s per MB): the file is malformed");
  }
  if (WIFSIGNALED(status))
    throw mesh_error(file, where,
                     "the mesh reader (assimp) crashed on it (signal " +
                         std::to_string(WTERMSIG(status)) + ", " + strsignal(WTERMSIG(status)) +
                         "): the file is malformed");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty())
    throw mesh_error(file, where, "the mesh reader stopped without an answer");
  StateReader in(std::move(bytes), file);
  {
    const auto outcome = in.get<Outcome>();
    if (outcome == Outcome::BadInput) {
      std::string at = in.get_string();
      throw InputError(std::move(at), in.get_string());
    }
    if (outcome == Outcome::Failure) throw mesh_error(file, where, in.get_string());
    TriangleMesh mesh;
    std::vector<double> xyz;
    in.get_vector(xyz);
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
      mesh.vertices.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
    in.get_vector(mesh.triangles);
    return mesh;
  }
}

}  // namespace upf
