// Trace checkpoints in HDF5: what is saved is read back bit for bit (points, the
// tangents known and unknown, the step and counters); a damaged file reads as none,
// so the trace is computed again instead of stopping the run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <H5Cpp.h>

#include "cyclone/io/ResultCheckpointDirectory.hpp"
#include "cyclone/io/TraceCheckpointDirectory.hpp"

using namespace cyclone;
namespace fs = std::filesystem;

namespace {

continuation::TraceState unfinishedState() {
  continuation::TraceState s;
  for (int i = 0; i < 5; ++i) {
    s.branch.points.push_back({0.5 + 0.1 * i + 1e-17 * i, Eigen::VectorXd::Random(7)});
    s.tangentX.push_back(i == 2 ? Eigen::VectorXd() : Eigen::VectorXd::Random(7));  // one unknown
    s.tangentP.push_back(0.3 * i);
    s.measures.push_back(std::sqrt(2.0) * i);
  }
  s.branch.segmentStarts = {3};
  s.branch.stopReason = "";
  s.branch.statistics.newtonIterations = 17, s.branch.statistics.residuals = 123456789012L;
  s.branch.statistics.seconds = 1.25;
  s.directionX = Eigen::VectorXd::Random(7), s.directionP = -0.7, s.step = 3.3e-4;
  s.scaleX = {2.5, 0.7}, s.scaleP = 1.5, s.largestNorm = {3.1, 0.9}, s.scaleFloor = {1e-9, 2e-9};
  s.retractions = 4, s.anchor = 3, s.creepChecked = 2;
  s.secant = 1, s.smoothRun = 3, s.heldSteps = {1, 0, 1, 1};
  s.branch.statistics.secantSteps = 41;
  return s;
}

}  // namespace

TEST(TraceCheckpointFile, AnUnfinishedStateReadsBackExactly) {
  const fs::path dir = fs::temp_directory_path() / "cyclone_trace_checkpoint_test";
  fs::remove_all(dir);
  io::TraceCheckpointDirectory store(dir.string());
  EXPECT_FALSE(store.load("0123").has_value());
  const auto s = unfinishedState();
  store.save("0123", s);
  const auto r = store.load("0123");
  ASSERT_TRUE(r.has_value());
  EXPECT_FALSE(r->complete);
  ASSERT_EQ(r->branch.points.size(), s.branch.points.size());
  for (std::size_t i = 0; i < s.branch.points.size(); ++i) {
    EXPECT_EQ(r->branch.points[i].parameter, s.branch.points[i].parameter);
    EXPECT_EQ(r->branch.points[i].x, s.branch.points[i].x);
    EXPECT_EQ(r->tangentX[i].size(), s.tangentX[i].size());
    if (s.tangentX[i].size() > 0) {
      EXPECT_EQ(r->tangentX[i], s.tangentX[i]);
    }
    EXPECT_EQ(r->tangentP[i], s.tangentP[i]);
    EXPECT_EQ(r->measures[i], s.measures[i]);
  }
  EXPECT_EQ(r->branch.segmentStarts, s.branch.segmentStarts);
  EXPECT_EQ(r->branch.statistics.newtonIterations, 17);
  EXPECT_EQ(r->branch.statistics.residuals, 123456789012L);
  EXPECT_EQ(r->branch.statistics.seconds, 1.25);
  EXPECT_EQ(r->directionX, s.directionX);
  EXPECT_EQ(r->directionP, s.directionP);
  EXPECT_EQ(r->step, s.step);
  EXPECT_EQ(r->scaleX, s.scaleX);
  EXPECT_EQ(r->scaleFloor, s.scaleFloor);
  EXPECT_EQ(r->largestNorm, s.largestNorm);
  EXPECT_EQ(r->retractions, 4);
  EXPECT_EQ(r->anchor, 3);
  EXPECT_EQ(r->creepChecked, 2);
  EXPECT_EQ(r->secant, 1);
  EXPECT_EQ(r->smoothRun, 3);
  EXPECT_EQ(r->heldSteps, s.heldSteps);
  EXPECT_EQ(r->branch.statistics.secantSteps, 41);

  // A finished one replaces it; its stop reason and flags come back.
  continuation::TraceState done;
  done.complete = true;
  done.branch = s.branch;
  done.branch.finished = true;
  done.branch.stopReason = "end of the parameter range reached";
  done.branch.end = continuation::BranchEnd::MetFromTheEnd;  // not the default: read back, not assumed
  store.save("0123", done);
  const auto d = store.load("0123");
  ASSERT_TRUE(d.has_value());
  EXPECT_TRUE(d->complete);
  EXPECT_TRUE(d->branch.finished);
  EXPECT_EQ(d->branch.stopReason, done.branch.stopReason);
  EXPECT_EQ(d->branch.end, continuation::BranchEnd::MetFromTheEnd);
  EXPECT_EQ(d->branch.points.size(), 5u);

  // Damaged (truncated) or not HDF5 at all: none, with a warning.
  const fs::path file = dir / "trace_0123.h5";
  fs::resize_file(file, fs::file_size(file) / 2);
  EXPECT_FALSE(store.load("0123").has_value());
  std::ofstream(dir / "trace_0456.h5") << "not hdf5";
  EXPECT_FALSE(store.load("0456").has_value());

  // A read-only view (the other MPI ranks) never writes.
  io::TraceCheckpointDirectory readOnly(dir.string(), true);
  readOnly.save("0789", s);
  EXPECT_FALSE(fs::exists(dir / "trace_0789.h5"));
  fs::remove_all(dir);
}

// A checkpoint whose content was edited, or that was copied under another trace's key,
// reads as none (computed again), not as a wrong curve (issue 49: scaled values in a
// modal checkpoint moved a frequency from 476.73 to 481.49 Hz after --resume, exit 0).
// The same for result checkpoints (the modal and static stages').
TEST(TraceCheckpointFile, EditedOrMisfiledCheckpointsReadAsNone) {
  const fs::path dir = fs::temp_directory_path() / "cyclone_trace_checkpoint_digest";
  fs::remove_all(dir);
  io::TraceCheckpointDirectory store(dir.string());
  store.save("0123", unfinishedState());
  ASSERT_TRUE(store.load("0123").has_value());
  {
    H5::H5File h5((dir / "trace_0123.h5").string(), H5F_ACC_RDWR);
    auto set = h5.openDataSet("parameter");
    std::vector<double> values(std::size_t(set.getSpace().getSimpleExtentNpoints()));
    set.read(values.data(), H5::PredType::NATIVE_DOUBLE);
    values[2] *= 1 + 1e-12;
    set.write(values.data(), H5::PredType::NATIVE_DOUBLE);
  }
  EXPECT_FALSE(store.load("0123").has_value());
  store.save("0123", unfinishedState());
  fs::copy_file(dir / "trace_0123.h5", dir / "trace_0456.h5");
  EXPECT_FALSE(store.load("0456").has_value());
  EXPECT_TRUE(store.load("0123").has_value());

  io::ResultCheckpointDirectory results(dir.string());
  results.save("modes_a", {476.73, 512.0, 0.25});
  ASSERT_TRUE(results.load("modes_a").has_value());
  EXPECT_EQ(*results.load("modes_a"), (std::vector<double>{476.73, 512.0, 0.25}));
  {
    H5::H5File h5((dir / "result_modes_a.h5").string(), H5F_ACC_RDWR);
    auto set = h5.openDataSet("values");
    std::vector<double> values(3);
    set.read(values.data(), H5::PredType::NATIVE_DOUBLE);
    values[0] = 481.49;
    set.write(values.data(), H5::PredType::NATIVE_DOUBLE);
  }
  EXPECT_FALSE(results.load("modes_a").has_value());
  results.save("modes_a", {476.73, 512.0, 0.25});
  fs::copy_file(dir / "result_modes_a.h5", dir / "result_modes_b.h5");
  EXPECT_FALSE(results.load("modes_b").has_value());
}
