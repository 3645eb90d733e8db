#include "cyclone/io/TraceCheckpointDirectory.hpp"

#include <H5Cpp.h>

#include <filesystem>

#include "Hdf5Datasets.hpp"

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/ContentHash.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"

namespace cyclone::io {

using namespace hdf5;
using continuation::TraceState;

namespace {

// Rows of equal length as a [rows x n] dataset (rows of another length are stored as
// zeros: the caller marks them).
void writeRows(H5::H5File& h5, const char* name, const std::vector<Eigen::VectorXd>& rows, std::size_t n) {
  std::vector<double> flat(rows.size() * n, 0.0);
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (std::size_t(rows[i].size()) == n) std::copy(rows[i].data(), rows[i].data() + n, flat.begin() + long(i * n));
  const hsize_t dims[2] = {rows.size(), n};
  H5::DataSpace space(2, dims);
  auto set = h5.createDataSet(name, H5::PredType::NATIVE_DOUBLE, space);
  if (!flat.empty()) set.write(flat.data(), H5::PredType::NATIVE_DOUBLE);
}

std::vector<Eigen::VectorXd> readRows(H5::H5File& h5, const char* name) {
  auto set = h5.openDataSet(name);
  hsize_t dims[2];
  hdf5::checkedExtent(set, name, sizeof(double), 2);
  set.getSpace().getSimpleExtentDims(dims);
  std::vector<double> flat(dims[0] * dims[1]);
  if (!flat.empty()) set.read(flat.data(), H5::PredType::NATIVE_DOUBLE);
  std::vector<Eigen::VectorXd> rows;
  for (hsize_t i = 0; i < dims[0]; ++i)
    rows.push_back(Eigen::Map<const Eigen::VectorXd>(flat.data() + i * dims[1], Eigen::Index(dims[1])));
  return rows;
}

// A digest of what a state holds that the trace's answer depends on (the points, how
// the trace ended, the stepper's state for a resume; not its timings), with the key it
// is filed under: an edited or damaged checkpoint, or one copied under another key, does
// not match it.
std::string stateDigest(const std::string& key, const TraceState& s) {
  ContentHash h;
  h.add(std::string("cyclone trace checkpoint v1")).add(key);
  const auto& b = s.branch;
  h.add((long long)b.points.size());
  for (const auto& pt : b.points) {
    h.add(pt.parameter).add((long long)pt.x.size());
    if (pt.x.size()) h.add(pt.x.data(), sizeof(double) * std::size_t(pt.x.size()));
  }
  for (std::size_t v : b.segmentStarts) h.add((long long)v);
  h.add(s.complete ? 1 : 0).add(b.finished ? 1 : 0).add(b.returnedToStart ? 1 : 0).add(b.reached).add(b.stopReason);
  h.add(static_cast<int>(b.end));
  if (!s.complete) {
    for (const auto& t : s.tangentX) {
      h.add((long long)t.size());
      if (t.size()) h.add(t.data(), sizeof(double) * std::size_t(t.size()));
    }
    h.addAll(s.tangentP).addAll(s.measures).add((long long)s.directionX.size());
    if (s.directionX.size()) h.add(s.directionX.data(), sizeof(double) * std::size_t(s.directionX.size()));
    h.add(s.directionP).add(s.step).add(s.scaleP).addAll(s.scaleX).addAll(s.largestNorm).addAll(s.scaleFloor);
    h.add((long long)s.retractions).add((long long)s.anchor).add((long long)s.creepChecked);
    h.add((long long)s.secant).add((long long)s.smoothRun).addAll(s.heldSteps);
  }
  return h.hex();
}

void writeLong(H5::H5File& h5, const char* name, long v) { writeAttribute(h5, name, v, H5::PredType::NATIVE_LONG); }
long readLong(H5::H5File& h5, const char* name) { return readAttribute<long>(h5, name, H5::PredType::NATIVE_LONG); }

}  // namespace

void TraceCheckpointDirectory::save(const std::string& key, const TraceState& s) {
  if (readOnly_) return;
  std::filesystem::create_directories(dir_);
  const std::string final = path(key);
  AtomicFile file(final);
  const auto& b = s.branch;
  const std::size_t P = b.points.size(), n = P > 0 ? std::size_t(b.points.front().x.size()) : 0;
  try {
    H5::Exception::dontPrint();
    H5::H5File h5 = hdf5::inMemoryFile(file);
    std::vector<double> parameter;
    std::vector<Eigen::VectorXd> x;
    for (const auto& pt : b.points) parameter.push_back(pt.parameter), x.push_back(pt.x);
    writeVector(h5, "parameter", parameter, H5::PredType::NATIVE_DOUBLE);
    writeRows(h5, "x", x, n);
    std::vector<long> starts(b.segmentStarts.begin(), b.segmentStarts.end());
    writeVector(h5, "segment_starts", starts, H5::PredType::NATIVE_LONG);
    writeIntAttribute(h5, "complete", s.complete);
    writeIntAttribute(h5, "finished", b.finished);
    writeIntAttribute(h5, "returned_to_start", b.returnedToStart);
    writeDoubleAttribute(h5, "reached", b.reached);
    writeStringAttribute(h5, "stop_reason", b.stopReason);
    writeIntAttribute(h5, "end", static_cast<int>(b.end));
    writeIntAttribute(h5, "failed_steps", b.failedSteps);
    const auto& st = b.statistics;
    writeIntAttribute(h5, "newton_iterations", st.newtonIterations);
    writeIntAttribute(h5, "rejected_steps", st.rejectedSteps);
    writeIntAttribute(h5, "spherical_steps", st.sphericalSteps);
    writeLong(h5, "secant_steps", st.secantSteps);
    writeLong(h5, "residuals", st.residuals);
    writeLong(h5, "jacobians", st.jacobians);
    writeLong(h5, "factorizations", st.factorizations);
    writeLong(h5, "double_fallbacks", st.doubleFallbacks);
    writeLong(h5, "reused_factorizations", st.reusedFactorizations);
    writeLong(h5, "krylov_iterations", st.krylovIterations);
    writeDoubleAttribute(h5, "residual_seconds", st.residualSeconds);
    writeDoubleAttribute(h5, "jacobian_seconds", st.jacobianSeconds);
    writeDoubleAttribute(h5, "factor_seconds", st.factorSeconds);
    writeDoubleAttribute(h5, "solve_seconds", st.solveSeconds);
    writeDoubleAttribute(h5, "seconds", st.seconds);
    if (!s.complete) {
      if (s.tangentX.size() != P || s.tangentP.size() != P || s.measures.size() != P)
        throw Error("trace checkpoint: per-point state of inconsistent length");
      std::vector<int> known;
      for (const auto& t : s.tangentX) known.push_back(std::size_t(t.size()) == n ? 1 : 0);
      writeVector(h5, "tangent_known", known, H5::PredType::NATIVE_INT);
      writeRows(h5, "tangent_x", s.tangentX, n);
      writeVector(h5, "tangent_p", s.tangentP, H5::PredType::NATIVE_DOUBLE);
      writeVector(h5, "measure", s.measures, H5::PredType::NATIVE_DOUBLE);
      writeRows(h5, "direction_x", {s.directionX}, std::size_t(s.directionX.size()));
      writeDoubleAttribute(h5, "direction_p", s.directionP);
      writeDoubleAttribute(h5, "step", s.step);
      writeVector(h5, "scale_x", s.scaleX, H5::PredType::NATIVE_DOUBLE);  // per scale group
      writeDoubleAttribute(h5, "scale_p", s.scaleP);
      writeVector(h5, "largest_norm", s.largestNorm, H5::PredType::NATIVE_DOUBLE);
      writeVector(h5, "scale_floor", s.scaleFloor, H5::PredType::NATIVE_DOUBLE);
      writeLong(h5, "retractions", s.retractions);
      writeLong(h5, "anchor", s.anchor);
      writeLong(h5, "creep_checked", s.creepChecked);
      writeLong(h5, "secant", s.secant);
      writeLong(h5, "smooth_run", s.smoothRun);
      writeVector(h5, "held_steps", s.heldSteps, H5::PredType::NATIVE_INT);
    }
    writeStringAttribute(h5, "content_digest", stateDigest(key, s));  // last: a file cut short has none
    hdf5::saveImage(h5, file);
  } catch (const H5::Exception& e) {
    throw Error("cannot write " + final + ": " + e.getDetailMsg());
  }
  file.commit();
}

std::optional<TraceState> TraceCheckpointDirectory::load(const std::string& key) {
  const std::string p = path(key);
  if (!std::filesystem::exists(p)) return std::nullopt;
  TraceState s;
  try {
    H5::Exception::dontPrint();
    H5::H5File h5(p, H5F_ACC_RDONLY);
    auto& b = s.branch;
    const auto parameter = readVector<double>(h5, "parameter", H5::PredType::NATIVE_DOUBLE);
    auto x = readRows(h5, "x");
    if (x.size() != parameter.size()) throw Error("points and parameters differ in number");
    for (std::size_t i = 0; i < x.size(); ++i) b.points.push_back({parameter[i], std::move(x[i])});
    for (long v : readVector<long>(h5, "segment_starts", H5::PredType::NATIVE_LONG)) b.segmentStarts.push_back(std::size_t(v));
    s.complete = readIntAttribute(h5, "complete") != 0;
    b.finished = readIntAttribute(h5, "finished") != 0;
    b.returnedToStart = readIntAttribute(h5, "returned_to_start") != 0;
    b.reached = readDoubleAttribute(h5, "reached");
    b.stopReason = readStringAttribute(h5, "stop_reason");
    const int end = readIntAttribute(h5, "end");
    if (end < 0 || end > static_cast<int>(continuation::BranchEnd::EngineStopped)) throw Error("an unknown way to end");
    b.end = static_cast<continuation::BranchEnd>(end);
    b.failedSteps = readIntAttribute(h5, "failed_steps");
    auto& st = b.statistics;
    st.newtonIterations = readIntAttribute(h5, "newton_iterations");
    st.rejectedSteps = readIntAttribute(h5, "rejected_steps");
    st.sphericalSteps = readIntAttribute(h5, "spherical_steps");
    st.secantSteps = readLong(h5, "secant_steps");
    st.residuals = readLong(h5, "residuals");
    st.jacobians = readLong(h5, "jacobians");
    st.factorizations = readLong(h5, "factorizations");
    st.doubleFallbacks = readLong(h5, "double_fallbacks");
    st.reusedFactorizations = readLong(h5, "reused_factorizations");
    st.krylovIterations = readLong(h5, "krylov_iterations");
    st.residualSeconds = readDoubleAttribute(h5, "residual_seconds");
    st.jacobianSeconds = readDoubleAttribute(h5, "jacobian_seconds");
    st.factorSeconds = readDoubleAttribute(h5, "factor_seconds");
    st.solveSeconds = readDoubleAttribute(h5, "solve_seconds");
    st.seconds = readDoubleAttribute(h5, "seconds");
    if (!s.complete) {
      if (b.points.empty()) throw Error("an unfinished trace without points");
      const auto known = readVector<int>(h5, "tangent_known", H5::PredType::NATIVE_INT);
      s.tangentX = readRows(h5, "tangent_x");
      s.tangentP = readVector<double>(h5, "tangent_p", H5::PredType::NATIVE_DOUBLE);
      s.measures = readVector<double>(h5, "measure", H5::PredType::NATIVE_DOUBLE);
      const std::size_t P = b.points.size();
      if (known.size() != P || s.tangentX.size() != P || s.tangentP.size() != P || s.measures.size() != P)
        throw Error("per-point state of inconsistent length");
      for (std::size_t i = 0; i < P; ++i)
        if (!known[i]) s.tangentX[i].resize(0);
      auto direction = readRows(h5, "direction_x");
      if (direction.size() != 1) throw Error("no direction");
      s.directionX = std::move(direction[0]);
      s.directionP = readDoubleAttribute(h5, "direction_p");
      s.step = readDoubleAttribute(h5, "step");
      s.scaleX = readVector<double>(h5, "scale_x", H5::PredType::NATIVE_DOUBLE);
      s.scaleP = readDoubleAttribute(h5, "scale_p");
      s.largestNorm = readVector<double>(h5, "largest_norm", H5::PredType::NATIVE_DOUBLE);
      s.scaleFloor = readVector<double>(h5, "scale_floor", H5::PredType::NATIVE_DOUBLE);
      if (s.scaleX.empty() || s.largestNorm.size() != s.scaleX.size() || s.scaleFloor.size() != s.scaleX.size())
        throw Error("scale groups of inconsistent length");
      s.retractions = readLong(h5, "retractions");
      s.anchor = readLong(h5, "anchor");
      s.creepChecked = readLong(h5, "creep_checked");
      s.secant = readLong(h5, "secant");
      s.smoothRun = readLong(h5, "smooth_run");
      s.heldSteps = readVector<int>(h5, "held_steps", H5::PredType::NATIVE_INT);
      if (s.anchor < 0 || std::size_t(s.anchor) >= P || s.creepChecked < 0 || s.smoothRun < 0 || s.heldSteps.size() > 10)
        throw Error("counters out of range");
    }
    if (!h5.attrExists("content_digest")) throw Error("no content digest (written by an older version)");
    if (readStringAttribute(h5, "content_digest") != stateDigest(key, s))
      throw Error("its content does not match the digest written with it: a damaged or edited file, or one "
                  "filed under another trace's key");
  } catch (const std::exception& e) {
    log::warn("continuation: checkpoint " + p + " cannot be read (" + e.what() + "); that trace is computed again");
    return std::nullopt;
  } catch (const H5::Exception& e) {
    log::warn("continuation: checkpoint " + p + " cannot be read (" + e.getDetailMsg() + "); that trace is computed again");
    return std::nullopt;
  }
  return s;
}

}  // namespace cyclone::io
