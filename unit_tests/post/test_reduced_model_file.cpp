// Reduced models in HDF5: written and read back bit-identical (the read model's
// compliance equals the original's exactly), readable by a real HDF5 client
// (h5dump), and a file that is not one is named in the error.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "cyclone/core/Error.hpp"
#include "cyclone/post/ReducedModelFile.hpp"

using namespace cyclone;
namespace fs = std::filesystem;

namespace {

rom::HybridFrfModel syntheticModel(bool hybrid) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  rom::RetainedModes modes;
  modes.copies = 2;
  modes.eigenvalues = {1.0e4, 1.0e4, 3.7e5, 3.7e5};
  modes.shapes.resize(6, 4);
  for (int i = 0; i < modes.shapes.size(); ++i) modes.shapes.data()[i] = g(rng);
  if (!hybrid) return rom::HybridFrfModel::modalTruncation(modes, 0.003);
  rom::StaticCompliance a0;
  Eigen::MatrixXd B(6, 6);
  for (int i = 0; i < B.size(); ++i) B.data()[i] = g(rng);
  a0.matrix = B * B.transpose() * 1e-6;
  a0.omega0 = 12.5, a0.shift = 12.5 * 12.5;
  return rom::HybridFrfModel(modes, a0, 0.003);
}

}  // namespace

TEST(ReducedModelFile, RoundTripIsBitIdenticalAndH5dumpReadsIt) {
  const auto dir = fs::temp_directory_path() / "cyclone_rom_file_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (bool hybrid : {true, false}) {
    const auto model = syntheticModel(hybrid);
    const auto rec = post::makeReducedModelRecord(model, 3, 24, 9500.0, {10, 10, 10, 42, 42, 42}, {0, 1, 2, 0, 1, 2},
                                                  {0, 0, 0, 1, 1, 1});
    const auto path = (dir / (hybrid ? "hybrid.h5" : "truncated.h5")).string();
    post::writeReducedModelHdf5(path, rec);
    const auto back = post::readReducedModelHdf5(path);
    EXPECT_EQ(back.harmonic, 3);
    EXPECT_EQ(back.sectors, 24);
    EXPECT_EQ(back.rpm, 9500.0);
    EXPECT_EQ(back.retainedNodes, rec.retainedNodes);
    EXPECT_EQ(back.retainedDirections, rec.retainedDirections);
    EXPECT_EQ(back.retainedCopies, rec.retainedCopies);
    EXPECT_EQ(back.staticCorrection, hybrid);
    const auto again = back.model();
    for (double w : {0.0, 50.0, 100.0, 99.99, 700.0})
      EXPECT_EQ((again.compliance(w) - model.compliance(w)).cwiseAbs().maxCoeff(), 0.0) << w;
    const std::string out = (dir / "h5dump.txt").string();
    ASSERT_EQ(std::system(("h5dump -H '" + path + "' > '" + out + "' 2>&1").c_str()), 0);
    std::ifstream in(out);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("DATASET \"shapes\""), std::string::npos) << text;
    EXPECT_EQ(text.find("DATASET \"static_compliance\"") != std::string::npos, hybrid) << text;
    EXPECT_NE(text.find("ATTRIBUTE \"harmonic\""), std::string::npos) << text;
  }
}

TEST(ReducedModelFile, BadFilesAndLabelsAreNamed) {
  const auto dir = fs::temp_directory_path() / "cyclone_rom_file_bad";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto path = (dir / "not_hdf5.h5").string();
  std::ofstream(path) << "hello";
  try {
    post::readReducedModelHdf5(path);
    ADD_FAILURE() << "a text file was read as a reduced model";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not_hdf5.h5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(post::makeReducedModelRecord(syntheticModel(true), 1, 8, 0, {1, 2}, {0, 1}, {0, 0}), InputError);
}
