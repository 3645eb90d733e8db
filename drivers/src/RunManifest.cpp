#include "RunManifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::scenes {

namespace {

std::string utcNow() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return text;
}

// key -> value of the manifest's "key: value" lines (the first of each key).
std::string manifestValue(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ": ", 0) == 0) return line.substr(key.size() + 2);
  return "";
}

}  // namespace

RunManifest::RunManifest(const std::string& outDir, const std::string& scene, std::string& previousUnfinished)
    : dir_(outDir), scene_(scene), started_(utcNow()) {
  const std::string lockPath = dir_ + "/.cyclone_run.lock", manifest = dir_ + "/run_manifest.txt";
  lock_ = ::open(lockPath.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (lock_ < 0) throw InputError(outDir, "cannot create the run's lock file " + lockPath);
  if (::flock(lock_, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock_);
    lock_ = -1;
    throw InputError(outDir, "another cyclone run is writing into this output directory (process " +
                                 manifestValue(manifest, "pid") + ", scene " + manifestValue(manifest, "scene") +
                                 ", started " + manifestValue(manifest, "started") +
                                 "): wait for it, or give this run another output_directory");
  }
  if (std::filesystem::exists(manifest) && manifestValue(manifest, "status") == "running")
    previousUnfinished = "the previous run into " + outDir + " (scene " + manifestValue(manifest, "scene") +
                         ", started " + manifestValue(manifest, "started") +
                         ") stopped without finishing: files this run does not write again are that run's";
  write("running", "");
}

RunManifest::~RunManifest() {
  if (!finished_) {
    try {
      write("failed", "error: stopped before the end\n");
    } catch (...) {
    }
  }
  if (lock_ >= 0) ::close(lock_);  // releases the lock
}

void RunManifest::complete(const std::vector<std::string>& written) {
  std::ostringstream files;
  files << "finished: " << utcNow() << "\nfiles:\n";
  // Paths relative to the output directory (the reduced models live in a subdirectory).
  for (const auto& f : written)
    files << "  - " << std::filesystem::path(f).lexically_relative(dir_).generic_string() << "\n";
  write("complete", files.str());
  finished_ = true;
}

void RunManifest::fail(const std::string& reason) {
  std::string oneLine = reason;
  for (char& c : oneLine)
    if (c == '\n') c = ' ';
  write("failed", "finished: " + utcNow() + "\nerror: " + oneLine + "\n");
  finished_ = true;
}

void RunManifest::write(const std::string& status, const std::string& extra) {
  AtomicFile file(dir_ + "/run_manifest.txt");
  std::ofstream out(file.tempPath());
  out << "status: " << status << "\nscene: " << scene_ << "\npid: " << ::getpid() << "\nstarted: " << started_ << "\n"
      << extra;
  out.close();
  if (!out) throw Error("cannot write " + dir_ + "/run_manifest.txt");
  file.commit();
}

}  // namespace cyclone::scenes
