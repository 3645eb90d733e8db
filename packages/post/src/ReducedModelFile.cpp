#include "cyclone/post/ReducedModelFile.hpp"

#include <H5Cpp.h>

#include "Hdf5Datasets.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::post {

using namespace hdf5;

namespace {

// Row-major 2D dataset of an Eigen matrix, and back.
void writeMatrix(H5::H5File& file, const char* name, const Eigen::MatrixXd& A) {
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rowMajor = A;
  const hsize_t dims[2] = {hsize_t(A.rows()), hsize_t(A.cols())};
  H5::DataSpace space(2, dims);
  file.createDataSet(name, H5::PredType::NATIVE_DOUBLE, space).write(rowMajor.data(), H5::PredType::NATIVE_DOUBLE);
}

Eigen::MatrixXd readMatrix(H5::H5File& file, const char* name) {
  auto set = file.openDataSet(name);
  hsize_t dims[2] = {0, 0};
  if (set.getSpace().getSimpleExtentNdims() != 2) throw Error(std::string(name) + " is not a matrix");
  set.getSpace().getSimpleExtentDims(dims);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rowMajor(dims[0], dims[1]);
  if (rowMajor.size()) set.read(rowMajor.data(), H5::PredType::NATIVE_DOUBLE);
  return rowMajor;
}

}  // namespace

rom::HybridFrfModel ReducedModelRecord::model() const {
  return staticCorrection ? rom::HybridFrfModel(modes, staticCompliance, lossFactor)
                          : rom::HybridFrfModel::modalTruncation(modes, lossFactor);
}

ReducedModelRecord makeReducedModelRecord(const rom::HybridFrfModel& model, int harmonic, int sectors, double rpm,
                                          std::vector<int> nodes, std::vector<int> directions,
                                          std::vector<int> copies) {
  const std::size_t r = std::size_t(model.size());
  if (nodes.size() != r || directions.size() != r || copies.size() != r)
    throw InputError("reduced model", "one node, direction and copy per retained DOF (" + std::to_string(r) +
                                          ") are needed");
  ReducedModelRecord rec;
  rec.harmonic = harmonic, rec.sectors = sectors, rec.rpm = rpm;
  rec.retainedNodes = std::move(nodes), rec.retainedDirections = std::move(directions);
  rec.retainedCopies = std::move(copies);
  rec.modes = model.modes();
  rec.staticCorrection = model.hasStaticCorrection();
  rec.staticCompliance = model.staticCompliance();
  rec.lossFactor = model.lossFactor();
  return rec;
}

void writeReducedModelHdf5(const std::string& path, const ReducedModelRecord& rec) {
  const Eigen::Index r = rec.modes.shapes.rows();
  if (rec.modes.shapes.cols() != Eigen::Index(rec.modes.eigenvalues.size()))
    throw Error("reduced model: shapes and eigenvalues disagree on the number of modes");
  if (rec.staticCorrection && (rec.staticCompliance.matrix.rows() != r || rec.staticCompliance.matrix.cols() != r))
    throw Error("reduced model: the static compliance must be retained DOFs square");
  AtomicFile file(path);
  try {
    H5::Exception::dontPrint();
    H5::H5File h5(file.tempPath(), H5F_ACC_TRUNC);
    writeVector(h5, "eigenvalues", rec.modes.eigenvalues, H5::PredType::NATIVE_DOUBLE);
    writeMatrix(h5, "shapes", rec.modes.shapes);
    if (rec.staticCorrection) writeMatrix(h5, "static_compliance", rec.staticCompliance.matrix);
    writeVector(h5, "retained_nodes", rec.retainedNodes, H5::PredType::NATIVE_INT);
    writeVector(h5, "retained_directions", rec.retainedDirections, H5::PredType::NATIVE_INT);
    writeVector(h5, "retained_copies", rec.retainedCopies, H5::PredType::NATIVE_INT);
    writeIntAttribute(h5, "format_version", 1);
    writeIntAttribute(h5, "harmonic", rec.harmonic);
    writeIntAttribute(h5, "sectors", rec.sectors);
    writeIntAttribute(h5, "copies", rec.modes.copies);
    writeIntAttribute(h5, "static_correction", rec.staticCorrection ? 1 : 0);
    writeDoubleAttribute(h5, "loss_factor", rec.lossFactor);
    writeDoubleAttribute(h5, "omega0", rec.staticCompliance.omega0);
    writeDoubleAttribute(h5, "shift", rec.staticCompliance.shift);
    writeDoubleAttribute(h5, "rpm", rec.rpm);
  } catch (const H5::Exception& e) {
    throw Error("cannot write " + path + ": " + e.getDetailMsg());
  }
  file.commit();
}

ReducedModelRecord readReducedModelHdf5(const std::string& path) {
  ReducedModelRecord rec;
  try {
    H5::Exception::dontPrint();
    H5::H5File h5(path, H5F_ACC_RDONLY);
    const int version = readIntAttribute(h5, "format_version");
    if (version != 1) throw InputError(path, "reduced-model format version " + std::to_string(version) + " (expected 1)");
    rec.modes.eigenvalues = readVector<double>(h5, "eigenvalues", H5::PredType::NATIVE_DOUBLE);
    rec.modes.shapes = readMatrix(h5, "shapes");
    rec.modes.copies = readIntAttribute(h5, "copies");
    rec.staticCorrection = readIntAttribute(h5, "static_correction") != 0;
    if (rec.staticCorrection) rec.staticCompliance.matrix = readMatrix(h5, "static_compliance");
    rec.staticCompliance.omega0 = readDoubleAttribute(h5, "omega0");
    rec.staticCompliance.shift = readDoubleAttribute(h5, "shift");
    rec.retainedNodes = readVector<int>(h5, "retained_nodes", H5::PredType::NATIVE_INT);
    rec.retainedDirections = readVector<int>(h5, "retained_directions", H5::PredType::NATIVE_INT);
    rec.retainedCopies = readVector<int>(h5, "retained_copies", H5::PredType::NATIVE_INT);
    rec.harmonic = readIntAttribute(h5, "harmonic");
    rec.sectors = readIntAttribute(h5, "sectors");
    rec.lossFactor = readDoubleAttribute(h5, "loss_factor");
    rec.rpm = readDoubleAttribute(h5, "rpm");
  } catch (const H5::Exception& e) {
    throw InputError(path, "not a Cyclone reduced-model HDF5 file: " + e.getDetailMsg());
  } catch (const Error& e) {
    throw InputError(path, e.what());
  }
  const std::size_t r = std::size_t(rec.modes.shapes.rows());
  if (rec.modes.shapes.cols() != Eigen::Index(rec.modes.eigenvalues.size()) || rec.retainedNodes.size() != r ||
      rec.retainedDirections.size() != r || rec.retainedCopies.size() != r ||
      (rec.staticCorrection && rec.staticCompliance.matrix.rows() != Eigen::Index(r)))
    throw InputError(path, "inconsistent reduced model: datasets of different retained-DOF or mode counts");
  return rec;
}

}  // namespace cyclone::post
