// Deterministic mutation fuzzing of Cyclone's readers (issue 20): the mesh readers
// (.inp, .msh ASCII and binary, .exo with results), the scene's YAML reading, and the
// files a run reuses (issue 49): a reduced model's HDF5 cache file and a trace
// checkpoint, each fed mutations of valid seed files for a bounded time. A reused file
// must be refused (or, for a checkpoint, not loaded) or read back as it was written: a
// mutated byte that changes what is read is a failure (a silently changed answer). Every input runs in a
// child process under a time limit (a hang) and an address-space limit (a memory
// blow-up); the reader must return or throw cyclone's Error. A crash, a hang, a
// blow-up or another exception fails the run, and the input is kept under
// fuzz_findings/ to reproduce it. Same seed, same inputs: a failure reproduces.
//
//   fuzz_readers <inp|msh|exo|yaml|rom|checkpoint> [seconds] [seed]
#include <gmsh.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/io/ReducedModelFile.hpp"
#include "cyclone/io/TraceCheckpointDirectory.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/GmshIO.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/scenes/SceneRunner.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace fs = std::filesystem;
using namespace cyclone;

namespace {

constexpr int kSecondsPerInput = 10;                  // longer: a hang
constexpr rlim_t kAddressSpace = rlim_t(4) << 30;     // more: a memory blow-up (the files are kB)

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeFile(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

mesh::Mesh coarseSector() {
  mesh::ShroudedSectorParameters p;
  p.sectors = 8, p.meshSize = 16.0, p.boreRadius = 70.0;
  auto m = mesh::generateShroudedSector(p);
  m.assignDefaultIds();
  return m;
}

void gmshBox(const fs::path& path, bool binary) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
  gmsh::model::add("box");
  const int box = gmsh::model::occ::addBox(0, 0, 0, 2, 1, 0.5);
  gmsh::model::occ::synchronize();
  gmsh::model::addPhysicalGroup(3, {box}, 11);
  gmsh::model::setPhysicalName(3, 11, "solid");
  gmsh::option::setNumber("Mesh.CharacteristicLengthMax", 0.6);
  gmsh::option::setNumber("Mesh.ElementOrder", 2);
  gmsh::model::mesh::generate(3);
  gmsh::write(path.string());
  gmsh::finalize();
}

// A small hybrid model's record (6 retained DOFs, 3 modes, a load pattern): what the
// disc chain caches per nodal diameter.
io::ReducedModelRecord smallModelRecord() {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  rom::RetainedModes modes;
  modes.eigenvalues = {1.0e6, 4.0e6, 9.0e6};
  modes.shapes = Eigen::MatrixXd::NullaryExpr(6, 3, [&] { return u(rng); });
  modes.loads = Eigen::MatrixXd::NullaryExpr(3, 1, [&] { return u(rng); });
  rom::StaticCompliance compliance;
  const Eigen::MatrixXd A = Eigen::MatrixXd::NullaryExpr(6, 6, [&] { return u(rng); });
  compliance.matrix = A * A.transpose() + Eigen::MatrixXd::Identity(6, 6);
  compliance.loadResponse = Eigen::MatrixXd::NullaryExpr(6, 1, [&] { return u(rng); });
  const rom::HybridFrfModel model(modes, compliance, 0.006);
  return io::makeReducedModelRecord(model, 2, 8, 10000, {0, 0, 0, 1, 1, 1}, {0, 1, 2, 0, 1, 2}, {0, 0, 0, 0, 0, 0});
}

// A trace's state part way (3 points of 4 unknowns, tangents, the step's scales).
continuation::TraceState smallTraceState() {
  continuation::TraceState s;
  for (int i = 0; i < 3; ++i) {
    s.branch.points.push_back({1.0 + 0.1 * i, Eigen::VectorXd::LinSpaced(4, i, i + 1.5)});
    s.tangentX.push_back(Eigen::VectorXd::Constant(4, 0.5 * i));
    s.tangentP.push_back(0.25 * i), s.measures.push_back(1.0 + i);
  }
  s.directionX = Eigen::VectorXd::Constant(4, 0.5), s.directionP = 0.5, s.step = 0.01, s.scaleP = 2;
  s.scaleX = {1.5, 2.5}, s.largestNorm = {3.0, 4.0}, s.scaleFloor = {1e-3, 1e-2};
  s.retractions = 1, s.anchor = 2, s.secant = 1, s.heldSteps = {1, 0, 1};
  return s;
}

// What a checkpoint's reader must give back: the state as saved, value for value.
bool sameState(const continuation::TraceState& a, const continuation::TraceState& b) {
  if (a.branch.points.size() != b.branch.points.size() || a.complete != b.complete || a.tangentX.size() != b.tangentX.size())
    return false;
  for (std::size_t i = 0; i < a.branch.points.size(); ++i)
    if (a.branch.points[i].parameter != b.branch.points[i].parameter || a.branch.points[i].x != b.branch.points[i].x ||
        a.tangentX[i] != b.tangentX[i])
      return false;
  return a.tangentP == b.tangentP && a.measures == b.measures && a.directionX == b.directionX &&
         a.directionP == b.directionP && a.step == b.step && a.scaleP == b.scaleP && a.scaleX == b.scaleX &&
         a.largestNorm == b.largestNorm && a.scaleFloor == b.scaleFloor && a.retractions == b.retractions &&
         a.anchor == b.anchor && a.creepChecked == b.creepChecked && a.secant == b.secant &&
         a.smoothRun == b.smoothRun && a.heldSteps == b.heldSteps && a.branch.end == b.branch.end &&
         a.branch.stopReason == b.branch.stopReason;
}

// Valid files of the reader's kind.
std::vector<std::string> seeds(const std::string& reader, const fs::path& work) {
  std::vector<std::string> out;
  if (reader == "inp") {
    mesh::writeAbaqusInp((work / "seed.inp").string(), coarseSector());
    out.push_back(readFile(work / "seed.inp"));
    out.push_back("*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n5, 1, 1, 1\n"
                  "*ELEMENT, TYPE=C3D4, ELSET=EALL\n1, 1, 2, 3, 4\n2, 2, 3, 4, 5\n*NSET, NSET=FIX\n1, 2\n"
                  "*NSET, NSET=GEN, GENERATE\n1, 5, 2\n*ELSET, ELSET=ONE\n1\n");
  } else if (reader == "msh") {
    gmshBox(work / "ascii.msh", false);
    gmshBox(work / "binary.msh", true);
    out.push_back(readFile(work / "ascii.msh"));
    out.push_back(readFile(work / "binary.msh"));
  } else if (reader == "exo") {
    const auto m = coarseSector();
    mesh::ExodusResults r;
    r.nodalNames = {"ux", "uy"};
    r.elementNames = {"s"};
    r.globalNames = {"f"};
    for (int s = 0; s < 2; ++s) {
      mesh::ExodusResults::Step step;
      step.time = s;
      step.nodal.assign(2, std::vector<double>(std::size_t(m.numNodes()), 0.5 * s));
      step.element.assign(1, std::vector<double>(std::size_t(m.numElements()), 1.0 + s));
      step.global = {double(s)};
      r.steps.push_back(step);
    }
    mesh::writeExodus((work / "seed.exo").string(), m, r);
    out.push_back(readFile(work / "seed.exo"));
  } else if (reader == "rom") {
    io::writeReducedModelHdf5((work / "seed.rom").string(), smallModelRecord());
    out.push_back(readFile(work / "seed.rom"));
  } else if (reader == "checkpoint") {
    io::TraceCheckpointDirectory dir((work / "seed_checkpoints").string());
    fs::create_directories(work / "seed_checkpoints");
    dir.save("k", smallTraceState());
    out.push_back(readFile(work / "seed_checkpoints" / "trace_k.h5"));
  } else if (reader == "yaml") {
    out.push_back(scenes::demoScene());
    for (const auto& e : fs::directory_iterator(CYCLONE_SCENE_DIR))
      if (e.path().extension() == ".yaml") out.push_back(readFile(e.path()));
  }
  return out;
}

// One to four of: a byte changed, bytes inserted, a range deleted or repeated, the
// end cut, a number replaced by an extreme one, two lines swapped.
std::string mutate(std::string s, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) { return n == 0 ? std::size_t(0) : std::size_t(rng() % n); };
  static const char* extremes[] = {"0", "-1", "-0", "1e308", "-1e308", "nan", "inf", "2147483648", "9223372036854775808",
                                   "-2147483649", "1e-320", "99999999999999999999", "", "0x7fffffff", "1.5"};
  const int count = 1 + int(rng() % 4);
  for (int k = 0; k < count && !s.empty(); ++k) {
    switch (rng() % 7) {
      case 0: s[pick(s.size())] = char(rng()); break;
      case 1: s.insert(pick(s.size() + 1), std::string(1 + pick(8), char(rng()))); break;
      case 2: {
        const auto a = pick(s.size());
        s.erase(a, 1 + pick(std::min<std::size_t>(64, s.size() - a)));
        break;
      }
      case 3: {
        const auto a = pick(s.size());
        const auto n = 1 + pick(std::min<std::size_t>(256, s.size() - a));
        s.insert(pick(s.size() + 1), s.substr(a, n));
        break;
      }
      case 4: s.resize(pick(s.size())); break;
      case 5: {  // a number token
        for (int tries = 0; tries < 20; ++tries) {
          const auto a = pick(s.size());
          if (!std::isdigit(static_cast<unsigned char>(s[a]))) continue;
          auto b = a;
          while (b < s.size() && (std::isdigit(static_cast<unsigned char>(s[b])) || s[b] == '.' || s[b] == 'e' || s[b] == '-')) ++b;
          s.replace(a, b - a, extremes[pick(std::size(extremes))]);
          break;
        }
        break;
      }
      default: {  // two lines swapped
        const auto a = s.rfind('\n', pick(s.size())), b = s.rfind('\n', pick(s.size()));
        if (a == std::string::npos || b == std::string::npos || a == b) break;
        const auto ea = s.find('\n', a + 1), eb = s.find('\n', b + 1);
        if (ea == std::string::npos || eb == std::string::npos) break;
        const std::string la = s.substr(a, ea - a), lb = s.substr(b, eb - b);
        if (a < b) s = s.substr(0, a) + lb + s.substr(ea, b - ea) + la + s.substr(eb);
        break;
      }
    }
  }
  return s;
}

enum Outcome { Ok = 0, MemoryBlowUp = 4, OtherException = 5, UnknownThrow = 6, SilentChange = 7 };

void read(const std::string& reader, const std::string& path) {
  if (reader == "rom") {
    // Refused (an Error, or read without a digest to verify it by, which the disc cache
    // refuses: "it carries no content digest"), or what was written.
    const auto record = io::readReducedModelHdf5(path);
    if (record.contentVerified && io::contentDigest(record) != io::contentDigest(smallModelRecord()))
      _exit(SilentChange);
  } else if (reader == "checkpoint") {
    // Not loaded (computed again), or the state as saved.
    const fs::path dir = fs::path(path).parent_path() / ("checkpoints_" + std::to_string(getpid()));
    fs::create_directories(dir);
    fs::copy_file(path, dir / "trace_k.h5", fs::copy_options::overwrite_existing);
    const auto state = io::TraceCheckpointDirectory(dir.string(), true).load("k");
    fs::remove_all(dir);
    if (state && !sameState(*state, smallTraceState())) _exit(SilentChange);
  } else if (reader == "inp") mesh::readAbaqusInp(path);
  else if (reader == "msh") mesh::readGmsh(path);
  else if (reader == "exo") {
    mesh::readExodus(path);
    mesh::readExodusResults(path);
  } else {
    const std::string text = readFile(path);
    const auto list = scenes::parseSceneYaml(text, path);
    // What a run reads first: the analyses and every section as a section.
    const Teuchos::ParameterList& top = list->isSublist("cyclone") ? list->sublist("cyclone") : *list;
    scenes::SceneSection scene(top, path, "cyclone");
    scene.getStringList("analysis", {"static"});
    for (const auto& name : scene.sectionNames()) {
      auto sec = scene.section(name);
      (void)sec.sectionNames();
    }
  }
}

// 0: returned or threw cyclone's Error; otherwise what went wrong.
std::string runChild(const std::string& reader, const std::string& path) {
  const pid_t pid = fork();
  if (pid == 0) {
#if !defined(__SANITIZE_ADDRESS__)  // ASan reserves terabytes of shadow; it reports huge allocations itself
    rlimit limit{kAddressSpace, kAddressSpace};
    setrlimit(RLIMIT_AS, &limit);
#endif
    alarm(kSecondsPerInput);
    // HDF5's error stacks and the checkpoint reader's warnings, thousands of them: the
    // outcome is the exit status (the input is kept to reproduce a failure).
    if (reader == "rom" || reader == "checkpoint") std::freopen("/dev/null", "w", stderr);
    try {
      read(reader, path);
    } catch (const Error&) {
      _exit(Ok);
    } catch (const std::bad_alloc&) {
      _exit(MemoryBlowUp);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "  not a cyclone::Error: %s\n", e.what());
      _exit(OtherException);
    } catch (...) {
      _exit(UnknownThrow);
    }
    _exit(Ok);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    return sig == SIGALRM ? "hang (over " + std::to_string(kSecondsPerInput) + " s)" : "crash (signal " + std::to_string(sig) + ")";
  }
  switch (WEXITSTATUS(status)) {
    case Ok: return "";
    case MemoryBlowUp: return "memory blow-up (std::bad_alloc under a 4 GB address space)";
    case OtherException: return "an exception other than cyclone::Error";
    case SilentChange: return "read back with other content than was written (a silently changed answer)";
    default: return "an unknown exception";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: fuzz_readers <inp|msh|exo|yaml|rom|checkpoint> [seconds] [seed]\n");
    return 2;
  }
  const std::string reader = argv[1];
  const double seconds = argc > 2 ? std::stod(argv[2]) : 15.0;
  const unsigned long long seed = argc > 3 ? std::stoull(argv[3]) : 20261125ull;
  log::setQuiet(true);
  const fs::path work = fs::temp_directory_path() / ("cyclone_fuzz_" + reader + "_" + std::to_string(getpid()));
  fs::create_directories(work);
  const auto corpus = seeds(reader, work);
  if (corpus.empty()) {
    std::fprintf(stderr, "no seeds for reader '%s'\n", reader.c_str());
    return 2;
  }
  const std::string ext = reader == "yaml" ? ".yaml" : "." + reader;
  std::mt19937_64 rng(seed);
  const auto start = std::chrono::steady_clock::now();
  long executions = 0, failures = 0;
  // The seeds themselves first: they must read.
  for (std::size_t i = 0; i < corpus.size(); ++i) {
    const auto path = (work / ("seed" + std::to_string(i) + ext)).string();
    writeFile(path, corpus[i]);
    if (const auto bad = runChild(reader, path); !bad.empty()) {
      std::printf("seed %zu: %s\n", i, bad.c_str());
      ++failures;
    }
  }
  fs::create_directories("fuzz_findings");
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds) {
    const std::string input = mutate(corpus[rng() % corpus.size()], rng);
    const auto path = (work / ("input" + ext)).string();
    writeFile(path, input);
    ++executions;
    if (const auto bad = runChild(reader, path); !bad.empty()) {
      const auto kept = fs::path("fuzz_findings") / (reader + "_" + std::to_string(++failures) + ext);
      writeFile(kept, input);
      std::printf("input %ld: %s; kept as %s\n", executions, bad.c_str(), fs::absolute(kept).c_str());
    }
  }
  fs::remove_all(work);
  std::printf("fuzz %s: %ld executions in %.0f s (%zu seeds, seed %llu), %ld failures\n", reader.c_str(), executions,
              seconds, corpus.size(), seed, failures);
  return failures == 0 ? 0 : 1;
}
