// Reduced models in HDF5: written and read back bit-identical (the read model's
// compliance equals the original's exactly) for every kind (hybrid, truncation,
// Guyan, Craig-Bampton), readable by a real HDF5 client (h5dump), a version 1
// file (no kind) still read as hybrid or truncation, and a file that is not one
// is named in the error.
#include <H5Cpp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "cyclone/core/Error.hpp"
#include "cyclone/io/ReducedModelFile.hpp"
#include "cyclone/rom/CraigBamptonModel.hpp"
#include "cyclone/rom/GuyanModel.hpp"

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
  modes.loads.resize(4, 2);  // two load patterns' modal forces
  for (int i = 0; i < modes.loads.size(); ++i) modes.loads.data()[i] = g(rng);
  if (!hybrid) return rom::HybridFrfModel::modalTruncation(modes, 0.003);
  rom::StaticCompliance a0;
  Eigen::MatrixXd B(6, 6);
  for (int i = 0; i < B.size(); ++i) B.data()[i] = g(rng);
  a0.matrix = B * B.transpose() * 1e-6;
  a0.loadResponse = 1e-6 * B.leftCols(2);
  a0.omega0 = 12.5, a0.shift = 12.5 * 12.5;
  return rom::HybridFrfModel(modes, a0, 0.003);
}

// A boundary reduction of 6 retained DOFs (2 copies) with 2 interface pairs:
// K_g, M_g symmetric positive definite, a small coupling so M_r stays definite.
rom::BoundaryReduction syntheticReduction() {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  const auto random = [&](int rows, int cols) {
    Eigen::MatrixXd B(rows, cols);
    for (int i = 0; i < B.size(); ++i) B.data()[i] = g(rng);
    return B;
  };
  rom::BoundaryReduction r;
  r.copies = 2;
  const Eigen::MatrixXd B = random(6, 6), C = random(6, 6);
  r.stiffness = 1e6 * (B * B.transpose() + Eigen::MatrixXd::Identity(6, 6));
  r.mass = 1e-2 * (C * C.transpose() + Eigen::MatrixXd::Identity(6, 6));
  r.interfaceEigenvalues = {2.0e6, 2.0e6, 5.5e6, 5.5e6};
  r.massCoupling = 1e-3 * random(6, 4);
  return r;
}

// h5dump's output with `options` (-H: the structure; -a NAME: an attribute's value).
std::string h5dump(const std::string& options, const std::string& path, const fs::path& dir) {
  const std::string out = (dir / "h5dump.txt").string();
  EXPECT_EQ(std::system(("h5dump " + options + " '" + path + "' > '" + out + "' 2>&1").c_str()), 0);
  std::ifstream in(out);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Largest |A_read(w) - A(w)| over frequencies around and between the modes, and at 0.
double largestDifference(const rom::ComplianceModel& read, const rom::ComplianceModel& original) {
  double worst = (read.zeroFrequencyCompliance() - original.zeroFrequencyCompliance()).cwiseAbs().maxCoeff();
  for (double w : {50.0, 100.0, 99.99, 700.0, 1414.2, 2345.0})
    worst = std::max(worst, (read.compliance(w) - original.compliance(w)).cwiseAbs().maxCoeff());
  return worst;
}

}  // namespace

TEST(ReducedModelFile, RoundTripIsBitIdenticalAndH5dumpReadsIt) {
  const auto dir = fs::temp_directory_path() / "cyclone_rom_file_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (bool hybrid : {true, false}) {
    const auto model = syntheticModel(hybrid);
    const auto rec = io::makeReducedModelRecord(model, 3, 24, 9500.0, {10, 10, 10, 42, 42, 42}, {0, 1, 2, 0, 1, 2},
                                                  {0, 0, 0, 1, 1, 1});
    const auto path = (dir / (hybrid ? "hybrid.h5" : "truncated.h5")).string();
    io::writeReducedModelHdf5(path, rec);
    const auto back = io::readReducedModelHdf5(path);
    EXPECT_EQ(back.nodalDiameter, 3);
    EXPECT_EQ(back.sectors, 24);
    EXPECT_EQ(back.rpm, 9500.0);
    EXPECT_EQ(back.retainedNodes, rec.retainedNodes);
    EXPECT_EQ(back.retainedDirections, rec.retainedDirections);
    EXPECT_EQ(back.retainedCopies, rec.retainedCopies);
    EXPECT_EQ(back.staticCorrection, hybrid);
    EXPECT_EQ(back.kind, hybrid ? "hybrid" : "truncation");
    const auto again = back.hybridModel();
    ASSERT_EQ(again.numLoads(), 2);
    for (double w : {0.0, 50.0, 100.0, 99.99, 700.0}) {
      EXPECT_EQ((again.compliance(w) - model.compliance(w)).cwiseAbs().maxCoeff(), 0.0) << w;
      EXPECT_EQ((again.loadResponse(w) - model.loadResponse(w)).cwiseAbs().maxCoeff(), 0.0) << w;
    }
    const std::string out = (dir / "h5dump.txt").string();
    ASSERT_EQ(std::system(("h5dump -H '" + path + "' > '" + out + "' 2>&1").c_str()), 0);
    std::ifstream in(out);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("DATASET \"shapes\""), std::string::npos) << text;
    EXPECT_EQ(text.find("DATASET \"static_compliance\"") != std::string::npos, hybrid) << text;
    EXPECT_NE(text.find("DATASET \"load_modal_forces\""), std::string::npos) << text;
    EXPECT_EQ(text.find("DATASET \"load_static_response\"") != std::string::npos, hybrid) << text;
    EXPECT_NE(text.find("ATTRIBUTE \"harmonic\""), std::string::npos) << text;
    EXPECT_NE(text.find("ATTRIBUTE \"kind\""), std::string::npos) << text;
  }
}

TEST(ReducedModelFile, GuyanAndCraigBamptonRoundTripBitIdentical) {
  const auto dir = fs::temp_directory_path() / "cyclone_rom_file_boundary";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto reduction = syntheticReduction();
  const rom::GuyanModel guyan(reduction, 0.004);
  const rom::CraigBamptonModel cb(reduction, 2, 0.004);
  const std::vector<int> nodes{10, 10, 10, 42, 42, 42}, directions{0, 1, 2, 0, 1, 2}, copies{0, 0, 0, 1, 1, 1};
  const std::vector<double> fullEigenvalues{1.0e6, 1.0e6, 4.0e6, 4.0e6};
  for (const std::string kind : {"guyan", "craig_bampton"}) {
    auto rec = kind == "guyan" ? io::makeReducedModelRecord(guyan, 3, 24, 9500.0, nodes, directions, copies)
                               : io::makeReducedModelRecord(cb, 3, 24, 9500.0, nodes, directions, copies);
    rec.fullModelEigenvalues = fullEigenvalues;
    // Node 42's DOFs in a local frame (rows: its unit vectors, rotated 30 degrees about z).
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    rec.retainedAxes = Eigen::MatrixXd::Zero(6, 3);
    rec.retainedAxes.topRows(3).setIdentity();
    rec.retainedAxes.bottomRows(3) << c, s, 0, -s, c, 0, 0, 0, 1;
    const auto path = (dir / (kind + ".h5")).string();
    io::writeReducedModelHdf5(path, rec);
    const auto back = io::readReducedModelHdf5(path);
    EXPECT_EQ(back.kind, kind);
    EXPECT_EQ(back.nodalDiameter, 3);
    EXPECT_EQ(back.sectors, 24);
    EXPECT_EQ(back.rpm, 9500.0);
    EXPECT_EQ(back.lossFactor, 0.004);
    EXPECT_EQ(back.retainedNodes, nodes);
    EXPECT_EQ(back.retainedDirections, directions);
    EXPECT_EQ(back.retainedCopies, copies);
    EXPECT_EQ(back.fullModelEigenvalues, fullEigenvalues);
    EXPECT_EQ(back.retainedAxes, rec.retainedAxes);
    EXPECT_EQ(back.reduction.copies, 2);
    EXPECT_EQ((back.reduction.stiffness - reduction.stiffness).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((back.reduction.mass - reduction.mass).cwiseAbs().maxCoeff(), 0.0);
    const rom::ComplianceModel& original =
        kind == "guyan" ? static_cast<const rom::ComplianceModel&>(guyan) : static_cast<const rom::ComplianceModel&>(cb);
    const auto read = back.model();
    ASSERT_EQ(read->size(), original.size());
    EXPECT_EQ(largestDifference(*read, original), 0.0) << kind;
    if (kind == "craig_bampton") {
      EXPECT_EQ(back.reduction.interfaceEigenvalues, reduction.interfaceEigenvalues);
      EXPECT_EQ((back.reduction.massCoupling - reduction.massCoupling).cwiseAbs().maxCoeff(), 0.0);
    }
    EXPECT_THROW(back.hybridModel(), InputError);
    // A real HDF5 client sees the datasets and the kind.
    const std::string text = h5dump("-H", path, dir);
    EXPECT_NE(text.find("DATASET \"boundary_stiffness\""), std::string::npos) << text;
    EXPECT_NE(text.find("DATASET \"boundary_mass\""), std::string::npos) << text;
    EXPECT_NE(text.find("DATASET \"full_model_eigenvalues\""), std::string::npos) << text;
    EXPECT_NE(text.find("DATASET \"retained_axes\""), std::string::npos) << text;
    EXPECT_EQ(text.find("DATASET \"mass_coupling\"") != std::string::npos, kind == "craig_bampton") << text;
    EXPECT_EQ(text.find("DATASET \"interface_eigenvalues\"") != std::string::npos, kind == "craig_bampton") << text;
    EXPECT_EQ(text.find("DATASET \"shapes\""), std::string::npos) << text;
    const std::string kindText = h5dump("-a kind", path, dir);
    EXPECT_NE(kindText.find("\"" + kind + "\""), std::string::npos) << kindText;
  }
}

// Files written before `kind` existed (format_version 1) still read as hybrid or
// truncation: made here from a new file by removing the kind and setting version 1.
TEST(ReducedModelFile, VersionOneFilesReadAsHybridOrTruncation) {
  const auto dir = fs::temp_directory_path() / "cyclone_rom_file_v1";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (bool hybrid : {true, false}) {
    const auto model = syntheticModel(hybrid);
    const auto path = (dir / (hybrid ? "hybrid_v1.h5" : "truncated_v1.h5")).string();
    io::writeReducedModelHdf5(path, io::makeReducedModelRecord(model, 1, 8, 0.0, {1, 1, 1, 2, 2, 2},
                                                                   {0, 1, 2, 0, 1, 2}, {0, 0, 0, 1, 1, 1}));
    {
      H5::H5File h5(path, H5F_ACC_RDWR);
      h5.removeAttr("kind");
      const int one = 1;
      h5.openAttribute("format_version").write(H5::PredType::NATIVE_INT, &one);
    }
    const std::string text = h5dump("-H", path, dir);
    ASSERT_EQ(text.find("ATTRIBUTE \"kind\""), std::string::npos) << text;
    const auto back = io::readReducedModelHdf5(path);
    EXPECT_EQ(back.kind, hybrid ? "hybrid" : "truncation");
    EXPECT_EQ(largestDifference(*back.model(), model), 0.0);
  }
}

// The content digest written last: a file read back is verified; one value changed by
// 1e-12 (relative) in any dataset is refused, naming the file and the digest.
TEST(ReducedModelFile, ContentIsVerifiedByItsDigest) {
  const auto dir = fs::temp_directory_path() / "cyclone_rom_file_digest";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto path = (dir / "model.h5").string();
  const auto rec = io::makeReducedModelRecord(syntheticModel(true), 1, 8, 0, {1, 1, 1, 2, 2, 2}, {0, 1, 2, 0, 1, 2},
                                              {0, 0, 0, 1, 1, 1});
  for (const std::string dataset : {"eigenvalues", "shapes", "static_compliance"}) {
    io::writeReducedModelHdf5(path, rec);
    EXPECT_TRUE(io::readReducedModelHdf5(path).contentVerified);
    {
      H5::H5File h5(path, H5F_ACC_RDWR);
      auto set = h5.openDataSet(dataset);
      std::vector<double> values(std::size_t(set.getSpace().getSimpleExtentNpoints()));
      set.read(values.data(), H5::PredType::NATIVE_DOUBLE);
      values.back() *= 1 + 1e-12;
      set.write(values.data(), H5::PredType::NATIVE_DOUBLE);
    }
    try {
      io::readReducedModelHdf5(path);
      ADD_FAILURE() << dataset << " edited and read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("model.h5"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("does not match the digest"), std::string::npos) << e.what();
    }
  }
  // So is a changed label (the nodal diameter the file claims).
  io::writeReducedModelHdf5(path, rec);
  {
    H5::H5File h5(path, H5F_ACC_RDWR);
    const int other = 3;
    h5.openAttribute("harmonic").write(H5::PredType::NATIVE_INT, &other);
  }
  EXPECT_THROW(io::readReducedModelHdf5(path), InputError);
}

TEST(ReducedModelFile, BadFilesAndLabelsAreNamed) {
  const auto dir = fs::temp_directory_path() / "cyclone_rom_file_bad";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto path = (dir / "not_hdf5.h5").string();
  std::ofstream(path) << "hello";
  try {
    io::readReducedModelHdf5(path);
    ADD_FAILURE() << "a text file was read as a reduced model";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not_hdf5.h5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(io::makeReducedModelRecord(syntheticModel(true), 1, 8, 0, {1, 2}, {0, 1}, {0, 0}), InputError);
  // An unknown kind in an otherwise valid file is named with the file.
  const auto unknown = (dir / "unknown_kind.h5").string();
  auto rec = io::makeReducedModelRecord(syntheticModel(false), 1, 8, 0, {1, 1, 1, 2, 2, 2}, {0, 1, 2, 0, 1, 2},
                                          {0, 0, 0, 1, 1, 1});
  io::writeReducedModelHdf5(unknown, rec);
  {
    H5::H5File h5(unknown, H5F_ACC_RDWR);
    h5.removeAttr("kind");
    const H5::StrType type(H5::PredType::C_S1, 5);
    h5.createAttribute("kind", type, H5::DataSpace(H5S_SCALAR)).write(type, std::string("magic"));
  }
  try {
    io::readReducedModelHdf5(unknown);
    ADD_FAILURE() << "a model of kind 'magic' was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown_kind.h5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("magic"), std::string::npos) << e.what();
  }
}
