// The cyclone program: runs scenes (YAML) and the embedded demo.
#include <Tpetra_Core.hpp>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/PeakMemory.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/scenes/SceneRunner.hpp"

#include "StackLimit.hpp"

namespace {

const char* kUsage = R"(cyclone - vibration of bladed discs with friction at the shrouds

usage:
  cyclone demo [--output DIR] [--mesh-size H] [--resume]   the main job on the built-in default disc
  cyclone run SCENE.yaml [--output DIR] [--mesh-size H] [--resume] [--checkpoint-seconds S]
  cyclone print-demo-scene                      the demo scene, to copy and edit
  cyclone --help | --version

A scene is a YAML file with a top-level key 'cyclone'; docs/scenes.md lists
every key. Products go to the scene's output_directory (or --output); nothing is
half-written. Run on several MPI ranks with mpirun -np N cyclone ...

Forced-response curves save their traces in <output>/checkpoints every S seconds
of work (default 5); --resume continues a killed run into the same directory from
them (finished curves are read back, the interrupted one goes on from its last
save). The directory is removed when a run completes.
)";

int usageError(const std::string& message) {
  std::fprintf(stderr, "cyclone: %s\n\n%s", message.c_str(), kUsage);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  // Progress goes to stdout; a reader that closes it (`cyclone run s.yaml | head`) must not
  // end the run by SIGPIPE with its manifest left "running": the writes fail, the run goes on.
  std::signal(SIGPIPE, SIG_IGN);
  // Commands that need no MPI/Kokkos are answered first: Kokkos would take --help for itself.
  if (argc < 2) return usageError("no command given");
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::printf("%s", kUsage);
    return 0;
  }
  if (command == "--version") {
    std::printf("cyclone 0.1.0\n");
    return 0;
  }
  if (command == "print-demo-scene") {
    std::printf("%s", cyclone::scenes::demoScene());
    return 0;
  }
  if (!cyclone::scenes::ensureStack(argv)) return 1;
  cyclone::returnLargeBlocksOnFree();
  Tpetra::ScopeGuard mpi(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  cyclone::log::setRank(comm->getRank());

  cyclone::scenes::SceneOverrides overrides;
  std::string scenePath;
  int i = 2;
  if (command == "run") {
    if (argc < 3) return usageError("'run' needs a scene file");
    scenePath = argv[2];
    i = 3;
  } else if (command != "demo") {
    return usageError("unknown command '" + command + "'");
  }
  for (; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--output" || arg == "-o") && i + 1 < argc) {
      overrides.outputDirectory = argv[++i];
    } else if (arg == "--mesh-size" && i + 1 < argc) {
      char* end = nullptr;
      const double h = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(h > 0)) return usageError("--mesh-size needs a positive number, got '" + std::string(argv[i]) + "'");
      overrides.meshSize = h;
    } else if (arg == "--resume") {
      overrides.resume = true;
    } else if (arg == "--checkpoint-seconds" && i + 1 < argc) {
      char* end = nullptr;
      const double seconds = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(seconds >= 0) || !std::isfinite(seconds))
        return usageError("--checkpoint-seconds needs a number of seconds >= 0, got '" + std::string(argv[i]) + "'");
      overrides.checkpointSeconds = seconds;
    } else {
      return usageError("unknown or incomplete option '" + arg + "'");
    }
  }

  try {
    cyclone::Timer timer;
    const auto summary = command == "demo"
                             ? cyclone::scenes::runSceneText(cyclone::scenes::demoScene(), "embedded demo scene",
                                                             overrides, comm)
                             : cyclone::scenes::runSceneFile(scenePath, overrides, comm);
    if (comm->getRank() == 0) {
      const double seconds = timer.seconds();
      auto print = [&](std::FILE* to) {
        std::fprintf(to, "\nsummary (%.1f s on %d rank%s)\n", seconds, comm->getSize(), comm->getSize() > 1 ? "s" : "");
        for (const auto& line : summary.computed) std::fprintf(to, "  %s\n", line.c_str());
        std::fprintf(to, "written:\n");
        for (const auto& path : summary.written) std::fprintf(to, "  %s\n", path.c_str());
        return std::fflush(to) == 0 && !std::ferror(to);
      };
      // Standard output closed or full (a reader gone, /dev/full): the products are whole
      // and the run succeeded, but its summary must not vanish: it goes to stderr then.
      errno = 0;
      if (!print(stdout)) {
        const int why = errno;
        std::fprintf(stderr, "cyclone: standard output could not be written (%s): the summary follows here\n",
                     why != 0 ? std::strerror(why) : "write error");
        print(stderr);
      }
    }
    return 0;
  } catch (const cyclone::InputError& e) {
    std::fprintf(stderr, "cyclone: input error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    // std::bad_alloc's own text is "std::bad_alloc".
    std::fprintf(stderr, "cyclone: error: out of memory: the run needed more than this machine, or the process's "
                         "limit (ulimit -v), allows; use a coarser mesh, fewer modes or fewer harmonics\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclone: error: %s\n", e.what());
    return 1;
  }
}
