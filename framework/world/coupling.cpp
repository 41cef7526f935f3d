#include "framework/world/coupling.h"

#include <algorithm>

#include "framework/core/errors.h"

namespace upf {

void CouplingArrays::reset(std::size_t particles) {
  for (std::size_t a = 0; a < arrays_.size(); ++a)
    if (active_[a]) arrays_[a].assign(particles, Vec3{});
}

namespace {

bool contains(const std::vector<CouplingArray>& list, CouplingArray a) {
  return std::find(list.begin(), list.end(), a) != list.end();
}

// Does `reader` read what `writer` writes (a solver reading its own array orders nothing)?
bool must_follow(const DeclaredSolver& reader, const DeclaredSolver& writer) {
  for (CouplingArray a : writer.use.writes)
    if (contains(reader.use.reads, a) || contains(reader.use.reads_if_written, a)) return true;
  return false;
}

}  // namespace

std::vector<std::size_t> coupling_order(const std::vector<DeclaredSolver>& solvers) {
  const std::size_t n = solvers.size();
  std::vector<InputProblem> problems;
  for (const DeclaredSolver& s : solvers)
    for (CouplingArray a : s.use.reads) {
      const bool written = std::any_of(solvers.begin(), solvers.end(), [&](const DeclaredSolver& w) {
        return contains(w.use.writes, a);
      });
      if (!written)
        problems.push_back({"/materials",
                            "solver '" + s.name + "' reads the coupling array '" +
                                std::string(coupling_array_name(a)) +
                                "', which no solver of this scene writes"});
    }
  if (!problems.empty()) throw InputError(problems);

  // Kahn's algorithm, always taking the earliest ready solver: the given order where free.
  std::vector<std::size_t> order;
  std::vector<bool> placed(n, false);
  while (order.size() < n) {
    std::size_t next = n;
    for (std::size_t r = 0; r < n && next == n; ++r) {
      if (placed[r]) continue;
      bool ready = true;
      for (std::size_t w = 0; w < n && ready; ++w)
        if (w != r && !placed[w] && must_follow(solvers[r], solvers[w])) ready = false;
      if (ready) next = r;
    }
    if (next == n) {
      std::string names;
      for (std::size_t s = 0; s < n; ++s)
        if (!placed[s]) names += (names.empty() ? "'" : ", '") + solvers[s].name + "'";
      throw InputError("/materials", "the solvers " + names +
                                         " read each other's coupling arrays in a cycle: no "
                                         "order steps every writer before its readers");
    }
    placed[next] = true;
    order.push_back(next);
  }
  return order;
}

}  // namespace upf
