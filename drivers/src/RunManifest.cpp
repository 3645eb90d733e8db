#include "RunManifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <utility>
#include <fstream>
#include <sstream>
#include <vector>

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

// What a stop signal (kStopSignals) writes: the manifest saying "interrupted", composed while the
// run starts, since a signal handler may only make system calls (open, write, rename:
// async-signal-safe). One run per process, so one of each.
char gInterruptedText[4096], gInterruptedTemp[4096], gManifestPath[4096];
std::size_t gInterruptedLength = 0;

// The signals whose default action ends the process and that a run is stopped by from
// outside: a batch system's stop (TERM) and its warnings before a limit (USR1, USR2),
// Ctrl-C (INT), a closed terminal or ssh session (HUP), a CPU-time or file-size limit
// (XCPU, XFSZ), an alarm (ALRM). SIGHUP, SIGXCPU and SIGUSR1 left "running" (fifth probe).
constexpr int kStopSignals[] = {SIGTERM, SIGINT, SIGHUP, SIGXCPU, SIGXFSZ, SIGUSR1, SIGUSR2, SIGALRM};

extern "C" void markInterrupted(int signal) {
  const int fd = ::open(gInterruptedTemp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd >= 0) {
    ssize_t ignored = ::write(fd, gInterruptedText, gInterruptedLength);
    (void)ignored;
    ::close(fd);
    ::rename(gInterruptedTemp, gManifestPath);
  }
  // Then what the signal would have done: the process ends by it (the lock goes with it).
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// Copies `text` into a fixed buffer (truncated to it), for the handler.
void keep(char* buffer, std::size_t size, const std::string& text) {
  const std::size_t n = std::min(size - 1, text.size());
  std::memcpy(buffer, text.data(), n);
  buffer[n] = '\0';
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
  if (lock_ < 0)
    throw InputError(outDir, "cannot create the run's lock file " + lockPath + ": " + std::strerror(errno) +
                                 " (the output directory must be writable)");
  if (::flock(lock_, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock_);
    lock_ = -1;
    throw InputError(outDir, "another cyclone run is writing into this output directory (process " +
                                 manifestValue(manifest, "pid") + ", scene " + manifestValue(manifest, "scene") +
                                 ", started " + manifestValue(manifest, "started") +
                                 "): wait for it, or give this run another output_directory");
  }
  const std::string previous = std::filesystem::exists(manifest) ? manifestValue(manifest, "status") : "";
  {
    std::ifstream in(manifest);
    bool listed = false;
    for (std::string line; std::getline(in, line);) {
      if (line == "files:" || line == "earlier files:") listed = true;
      else if (listed && line.rfind("  - ", 0) == 0) earlierFiles_.push_back(line.substr(4));
      else listed = false;
    }
  }
  if (previous == "running" || previous == "interrupted")
    previousUnfinished = "the previous run into " + outDir + " (scene " + manifestValue(manifest, "scene") +
                         ", started " + manifestValue(manifest, "started") +
                         ") stopped without finishing: files this run does not write again are that run's";
  // A run killed outright (SIGKILL) in the middle of a write leaves its temporary
  // (AtomicFile's ".<name>.tmp<pid>", and the manifest's own ".interrupted.tmp"); with
  // the lock held no run is writing here, so every one is stale.
  // Only the directory and the subdirectories Cyclone writes (not a walk of whatever tree
  // an output_directory of "." would hold, nor another tool's files elsewhere in it).
  std::vector<std::filesystem::path> stale;
  for (const std::string sub : {"", "/reduced_models", "/checkpoints"}) {
    std::error_code walk;
    for (auto it = std::filesystem::directory_iterator(dir_ + sub, walk);
         !walk && it != std::filesystem::directory_iterator(); it.increment(walk)) {
      const std::string name = it->path().filename().string();
      const auto tmp = name.rfind(".tmp");
      const bool digits = tmp != std::string::npos && tmp + 4 < name.size() &&
                          std::all_of(name.begin() + long(tmp + 4), name.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (it->is_regular_file() && name.size() > 1 && name[0] == '.' &&
          (digits || name == "run_manifest.txt.interrupted.tmp"))
        stale.push_back(it->path());
    }
  }
  if (!stale.empty()) {
    std::ostringstream removed;
    removed << "removed " << stale.size() << " temporary file" << (stale.size() > 1 ? "s" : "")
            << " a killed run left (";
    for (std::size_t i = 0; i < stale.size(); ++i) {
      std::error_code ignored;
      std::filesystem::remove(stale[i], ignored);
      if (i < 3) removed << (i ? ", " : "") << std::filesystem::relative(stale[i], dir_).string();
    }
    removed << (stale.size() > 3 ? ", ...)" : ")");
    previousUnfinished += (previousUnfinished.empty() ? "" : "; ") + removed.str();
  }
  write("running", "");
  // The stop signals (kStopSignals) mark the run interrupted; its checkpoints stay for
  // --resume. SIGKILL cannot be caught: the manifest says running.
  std::ostringstream text;
  text << "status: interrupted\nscene: " << scene_ << "\npid: " << ::getpid() << "\nstarted: " << started_
       << "\nerror: stopped by a signal (a stop, interrupt, hang-up, time or size limit); run again with --resume to "
          "continue from its checkpoints\n";
  keep(gInterruptedText, sizeof gInterruptedText, text.str());
  gInterruptedLength = std::strlen(gInterruptedText);
  keep(gInterruptedTemp, sizeof gInterruptedTemp, manifest + ".interrupted.tmp");
  keep(gManifestPath, sizeof gManifestPath, manifest);
  for (int signal : kStopSignals) std::signal(signal, markInterrupted);
}

RunManifest::~RunManifest() {
  for (int signal : kStopSignals) std::signal(signal, SIG_DFL);
  if (!finished_) {
    try {
      write("failed", "error: stopped before the end\n");
    } catch (...) {
    }
  }
  if (lock_ >= 0) ::close(lock_);  // releases the lock
}

std::vector<std::string> RunManifest::earlierFilesLeft(const std::vector<std::string>& written) const {
  std::vector<std::string> mine, left;
  for (const auto& f : written) mine.push_back(std::filesystem::path(f).lexically_relative(dir_).generic_string());
  for (const auto& f : earlierFiles_)
    if (std::find(mine.begin(), mine.end(), f) == mine.end() && std::filesystem::exists(dir_ + "/" + f))
      left.push_back(f);
  return left;
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
  const std::string path = dir_ + "/run_manifest.txt";
  std::ostringstream text;
  text << "status: " << status << "\nscene: " << scene_ << "\npid: " << ::getpid() << "\nstarted: " << started_ << "\n"
       << extra;
  // Until this run completes, the earlier run's files still in the directory are kept on
  // record: a refused run's manifest had dropped them, and the next run no longer said that
  // they stay beside its own (issue 49's fourth probe).
  if (status != "complete") {
    bool first = true;
    for (const auto& f : earlierFiles_)
      if (std::filesystem::exists(dir_ + "/" + f)) text << (std::exchange(first, false) ? "earlier files:\n" : "") << "  - " << f << "\n";
  }
  const std::string bytes = text.str();
  AtomicFile file(path);
  try {
    file.write(bytes.data(), bytes.size());
  } catch (const Error&) {
    // A full disk has no room for a second copy: the manifest is written over in place
    // (its truncation frees the old one's space), so a failed run still says so. Not
    // atomic, but a reader meets at worst a manifest cut short, never a false status.
    std::FILE* f = std::fopen(path.c_str(), "wb");
    const bool written = f && std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    if (!(f && std::fclose(f) == 0 && written)) throw;
    return;
  }
  file.commit();
}

}  // namespace cyclone::scenes
