// Third-party file parsers in a child process. assimp aborts or crashes on some malformed files
// (the libFuzzer target tests/fuzz/fuzz_mesh.cpp found an abort in its post-processing within
// seconds); "bad input never crashes" means such a file must end in an error that names it, not
// in a dead program. read_isolated forks, runs `read` in the child and sends the mesh (or the
// child's InputError) back through a pipe: a crash takes down only the child.
#pragma once

#include <functional>
#include <string>

#include "coupling/mesh/triangle_mesh.h"

namespace upf {

// `file` and `where` name the input in the error when the child dies.
TriangleMesh read_isolated(const std::function<TriangleMesh()>& read, const std::string& file,
                           const std::string& where);

}  // namespace upf
