#include "MeasuredCommand.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <thread>
#include <vector>

namespace cyclone::regression {

namespace {

// Every process whose parent chain reaches root (root included).
std::vector<long> processTree(long root) {
  std::map<long, std::vector<long>> children;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || !std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string text;
    if (!std::getline(stat, text)) continue;
    const auto close = text.rfind(')');  // the command name may hold spaces and ')'
    if (close == std::string::npos) continue;
    char state = 0;
    long parent = 0;
    if (std::sscanf(text.c_str() + close + 1, " %c %ld", &state, &parent) == 2)
      children[parent].push_back(std::stol(name));
  }
  std::vector<long> tree{root};
  for (std::size_t i = 0; i < tree.size(); ++i)
    for (long c : children[tree[i]]) tree.push_back(c);
  return tree;
}

// Pss of one process in kB (0 where it is gone).
long pssKb(long pid) {
  std::ifstream rollup("/proc/" + std::to_string(pid) + "/smaps_rollup");
  std::string key;
  long value = 0;
  while (rollup >> key) {
    if (key == "Pss:") {
      rollup >> value;
      return value;
    }
    rollup.ignore(1 << 20, '\n');
  }
  return 0;
}

}  // namespace

MeasuredCommand runMeasured(const std::string& command) {
  MeasuredCommand run;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  if (pid < 0) throw std::runtime_error("could not start: " + command);
  int status = 0;
  rusage usage{};
  long peakKb = 0;
  // Sampled every 250 ms, the tree found again every 2.5 s: the walk over /proc and the
  // kernel's page-table walk behind smaps_rollup cost a quarter of a core at 20 ms and
  // 1 s (8 % at 100 ms), time the measured run would lose on a 2-core machine.
  std::vector<long> tree;
  for (int sample = 0;; ++sample) {
    const pid_t done = wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) break;
    if (done < 0) throw std::runtime_error("lost the child of: " + command);
    if (sample % 10 == 0) tree = processTree(pid);
    long sum = 0;
    for (long p : tree) sum += pssKb(p);
    peakKb = std::max(peakKb, sum);
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw std::runtime_error("command failed: " + command);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.peakResidentMb = usage.ru_maxrss / 1024.0;
  run.peakTreePssMb = peakKb / 1024.0;
  return run;
}

}  // namespace cyclone::regression
