#include "IsolatedRead.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh::detail {

namespace {

// A flat byte image of a mesh: sizes, then the arrays as they are in memory.
class Writer {
public:
  template <class T>
  void pod(const T& v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  template <class T>
  void array(const std::vector<T>& v) {
    pod(std::uint64_t(v.size()));
    bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    pod(std::uint64_t(s.size()));
    bytes.append(s);
  }
  std::string bytes;
};

class Reader {
public:
  explicit Reader(const std::string& b) : bytes_(b) {}
  template <class T>
  T pod() {
    T v;
    take(&v, sizeof(T));
    return v;
  }
  template <class T>
  std::vector<T> array() {
    const auto n = pod<std::uint64_t>();
    if (n > bytes_.size() / sizeof(T)) throw Error("mesh from the reading process: damaged");
    std::vector<T> v(n);
    take(v.data(), n * sizeof(T));
    return v;
  }
  std::string text() {
    const auto n = pod<std::uint64_t>();
    if (n > bytes_.size()) throw Error("mesh from the reading process: damaged");
    std::string s(n, '\0');
    take(s.data(), n);
    return s;
  }

private:
  void take(void* to, std::size_t n) {
    if (at_ + n > bytes_.size()) throw Error("mesh from the reading process: damaged");
    std::memcpy(to, bytes_.data() + at_, n);
    at_ += n;
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

std::string serialize(const Mesh& m) {
  Writer w;
  w.text(m.source);
  w.array(m.coords);
  w.array(m.nodeIds);
  w.pod(std::uint64_t(m.blocks.size()));
  for (const auto& b : m.blocks) {
    w.text(b.name);
    w.pod(b.id);
    w.pod(int(b.type));
    w.array(b.connectivity);
    w.array(b.elementIds);
  }
  for (const auto* sets : {&m.nodeSets, &m.elementSets}) {
    w.pod(std::uint64_t(sets->size()));
    for (const auto& [name, entries] : *sets) w.text(name), w.array(entries);
  }
  w.pod(std::uint64_t(m.sideSets.size()));
  for (const auto& [name, entries] : m.sideSets) w.text(name), w.array(entries);
  return w.bytes;
}

Mesh deserialize(const std::string& bytes) {
  Reader r(bytes);
  Mesh m;
  m.source = r.text();
  m.coords = r.array<Point>();
  m.nodeIds = r.array<Index>();
  const auto blocks = r.pod<std::uint64_t>();
  for (std::uint64_t i = 0; i < blocks; ++i) {
    ElementBlock b;
    b.name = r.text();
    b.id = r.pod<int>();
    b.type = ElementType(r.pod<int>());
    b.connectivity = r.array<Index>();
    b.elementIds = r.array<Index>();
    m.blocks.push_back(std::move(b));
  }
  for (auto* sets : {&m.nodeSets, &m.elementSets}) {
    const auto n = r.pod<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i) {
      auto name = r.text();
      (*sets)[name] = r.array<Index>();
    }
  }
  const auto n = r.pod<std::uint64_t>();
  for (std::uint64_t i = 0; i < n; ++i) {
    auto name = r.text();
    m.sideSets[name] = r.array<SideEntry>();
  }
  return m;
}

void writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const auto n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += std::size_t(n);
  }
}

}  // namespace

Mesh readInChildProcess(const std::string& path, const std::function<Mesh()>& read) {
  int fds[2];
  if (::pipe(fds) != 0) throw Error(path + ": cannot create a pipe for the reading process");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    throw Error(path + ": cannot start the reading process");
  }
  if (pid == 0) {
    // The default action for a fault: no MPI handler printing a stack trace from here.
    for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(s, SIG_DFL);
    ::close(fds[0]);
    std::string payload;
    try {
      payload = "M" + serialize(read());
    } catch (const InputError& e) {
      payload = std::string("I") + e.what();
    } catch (const std::exception& e) {
      payload = std::string("E") + e.what();
    } catch (...) {
      payload = "Ean unknown exception while reading";
    }
    writeAll(fds[1], payload);
    ::close(fds[1]);
    ::_exit(0);  // no atexit handlers, no MPI: the parent owns those
  }
  ::close(fds[1]);
  std::string data;
  char buffer[1 << 16];
  for (;;) {
    const auto n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    data.append(buffer, std::size_t(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status))
    throw InputError(path, std::string("the reader stopped with signal ") + std::to_string(WTERMSIG(status)) + " (" +
                               strsignal(WTERMSIG(status)) + ") while reading the file: it is damaged, or not a " +
                               "mesh the reader can read");
  if (data.empty()) throw InputError(path, "the reading process returned nothing");
  const std::string rest = data.substr(1);
  // The child's message already names the file: kept as it is.
  const std::string prefix = path + ": ";
  if (data[0] == 'I') throw InputError(path, rest.rfind(prefix, 0) == 0 ? rest.substr(prefix.size()) : rest);
  if (data[0] == 'E') throw Error(rest);
  return deserialize(rest);
}

}  // namespace cyclone::mesh::detail
