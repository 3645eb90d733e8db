#pragma once
// Private to the mesh readers: a reader run in a child process, its mesh sent back
// through a pipe. gmsh 4.8 dies with SIGSEGV on some damaged files (an element naming
// a node tag it never read: GModel::getMeshVertexByTag, found by fuzz_readers); in a
// child that is an InputError naming the file, not the end of the run.
#include <functional>
#include <string>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh::detail {

/// Runs read() in a child process and returns its mesh. An InputError or Error thrown
/// there is thrown here with the same message; a child killed by a signal is an
/// InputError naming `path` and the signal.
Mesh readInChildProcess(const std::string& path, const std::function<Mesh()>& read);

}  // namespace cyclone::mesh::detail
