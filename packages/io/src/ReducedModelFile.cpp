#include "cyclone/io/ReducedModelFile.hpp"

#include <H5Cpp.h>

#include "Hdf5Datasets.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/ContentHash.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/rom/CraigBamptonModel.hpp"
#include "cyclone/rom/GuyanModel.hpp"

namespace cyclone::io {

using namespace hdf5;

namespace {

constexpr int kFormatVersion = 2;  // 2 added `kind` and the Guyan and Craig-Bampton datasets

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
  hdf5::checkedExtent(set, name, sizeof(double), 2);
  set.getSpace().getSimpleExtentDims(dims);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rowMajor(dims[0], dims[1]);
  if (rowMajor.size()) set.read(rowMajor.data(), H5::PredType::NATIVE_DOUBLE);
  return rowMajor;
}

bool modal(const std::string& kind) { return kind == "hybrid" || kind == "truncation"; }
bool boundary(const std::string& kind) { return kind == "guyan" || kind == "craig_bampton"; }

ReducedModelRecord labelled(std::size_t r, int nodalDiameter, int sectors, double rpm, std::vector<int> nodes,
                            std::vector<int> directions, std::vector<int> copies) {
  if (nodes.size() != r || directions.size() != r || copies.size() != r)
    throw InputError("reduced model", "one node, direction and copy per retained DOF (" + std::to_string(r) +
                                          ") are needed");
  ReducedModelRecord rec;
  rec.nodalDiameter = nodalDiameter, rec.sectors = sectors, rec.rpm = rpm;
  rec.retainedNodes = std::move(nodes), rec.retainedDirections = std::move(directions);
  rec.retainedCopies = std::move(copies);
  return rec;
}

// The number of retained DOFs the model's own datasets have.
Eigen::Index retainedSize(const ReducedModelRecord& rec) {
  return modal(rec.kind) ? rec.modes.shapes.rows() : rec.reduction.stiffness.rows();
}

}  // namespace

std::shared_ptr<const rom::ComplianceModel> ReducedModelRecord::model() const {
  if (modal(kind)) return std::make_shared<rom::HybridFrfModel>(hybridModel());
  if (kind == "guyan") return std::make_shared<rom::GuyanModel>(reduction, lossFactor);
  if (kind == "craig_bampton")
    return std::make_shared<rom::CraigBamptonModel>(reduction, reduction.numInterfaceModes() / reduction.copies,
                                                    lossFactor);
  throw InputError("reduced model", "unknown kind '" + kind + "' (hybrid, truncation, guyan, craig_bampton)");
}

rom::HybridFrfModel ReducedModelRecord::hybridModel() const {
  if (!modal(kind)) throw InputError("reduced model", "is a " + kind + " model, not a hybrid or truncation one");
  return staticCorrection ? rom::HybridFrfModel(modes, staticCompliance, lossFactor)
                          : rom::HybridFrfModel::modalTruncation(modes, lossFactor);
}

ReducedModelRecord makeReducedModelRecord(const rom::HybridFrfModel& model, int nodalDiameter, int sectors, double rpm,
                                          std::vector<int> nodes, std::vector<int> directions,
                                          std::vector<int> copies) {
  auto rec = labelled(std::size_t(model.size()), nodalDiameter, sectors, rpm, std::move(nodes), std::move(directions),
                      std::move(copies));
  rec.kind = model.hasStaticCorrection() ? "hybrid" : "truncation";
  rec.modes = model.modes();
  rec.staticCorrection = model.hasStaticCorrection();
  rec.staticCompliance = model.staticCompliance();
  rec.lossFactor = model.lossFactor();
  return rec;
}

ReducedModelRecord makeReducedModelRecord(const rom::GuyanModel& model, int nodalDiameter, int sectors, double rpm,
                                          std::vector<int> nodes, std::vector<int> directions,
                                          std::vector<int> copies) {
  auto rec = labelled(std::size_t(model.size()), nodalDiameter, sectors, rpm, std::move(nodes), std::move(directions),
                      std::move(copies));
  rec.kind = "guyan";
  rec.reduction.copies = model.modes().copies;
  rec.reduction.stiffness = model.stiffness();
  rec.reduction.mass = model.mass();
  rec.reduction.massCoupling.resize(model.size(), 0);
  rec.lossFactor = model.lossFactor();
  return rec;
}

ReducedModelRecord makeReducedModelRecord(const rom::CraigBamptonModel& model, int nodalDiameter, int sectors, double rpm,
                                          std::vector<int> nodes, std::vector<int> directions,
                                          std::vector<int> copies) {
  auto rec = labelled(std::size_t(model.size()), nodalDiameter, sectors, rpm, std::move(nodes), std::move(directions),
                      std::move(copies));
  rec.kind = "craig_bampton";
  rec.reduction.copies = model.modes().copies;
  rec.reduction.stiffness = model.boundaryStiffness();
  rec.reduction.mass = model.boundaryMass();
  rec.reduction.massCoupling = model.massCoupling();
  const auto& lambda = model.interfaceEigenvalues();
  rec.reduction.interfaceEigenvalues.assign(lambda.data(), lambda.data() + lambda.size());
  rec.lossFactor = model.lossFactor();
  return rec;
}

namespace {

void addMatrix(ContentHash& h, const Eigen::MatrixXd& m) {
  h.add((long long)m.rows()).add((long long)m.cols());
  if (m.size()) h.add(m.data(), sizeof(double) * std::size_t(m.size()));
}

}  // namespace

std::string contentDigest(const ReducedModelRecord& rec) {
  ContentHash h;
  h.add(std::string("cyclone reduced model content v1")).add(rec.kind).add(rec.nodalDiameter).add(rec.sectors);
  h.add(rec.rpm).add(rec.lossFactor);
  h.addAll(rec.retainedNodes).addAll(rec.retainedDirections).addAll(rec.retainedCopies);
  addMatrix(h, rec.retainedAxes);
  // Only when given, so that files written without it keep their digests.
  if (!rec.inputDigest.empty()) h.add(std::string("input digest")).add(rec.inputDigest);
  if (modal(rec.kind)) {
    h.add(rec.modes.copies).addAll(rec.modes.eigenvalues);
    addMatrix(h, rec.modes.shapes);
    addMatrix(h, rec.modes.loads);
    h.add(rec.staticCorrection ? 1 : 0);
    if (rec.staticCorrection) {
      addMatrix(h, rec.staticCompliance.matrix);
      addMatrix(h, rec.staticCompliance.loadResponse);
    }
  } else {
    h.add(rec.reduction.copies);
    addMatrix(h, rec.reduction.stiffness);
    addMatrix(h, rec.reduction.mass);
    if (rec.kind == "craig_bampton") {
      h.addAll(rec.reduction.interfaceEigenvalues);
      addMatrix(h, rec.reduction.massCoupling);
    }
  }
  h.add(rec.staticCompliance.omega0).add(rec.staticCompliance.shift);
  h.addAll(rec.fullModelEigenvalues);
  return h.hex();
}

void writeReducedModelHdf5(const std::string& path, const ReducedModelRecord& rec) {
  if (!modal(rec.kind) && !boundary(rec.kind)) throw Error("reduced model: unknown kind '" + rec.kind + "'");
  const Eigen::Index r = retainedSize(rec);
  if (rec.retainedAxes.size() && (rec.retainedAxes.rows() != r || rec.retainedAxes.cols() != 3))
    throw Error("reduced model: retained axes must be retained DOFs x 3");
  if (modal(rec.kind)) {
    if (rec.modes.shapes.cols() != Eigen::Index(rec.modes.eigenvalues.size()))
      throw Error("reduced model: shapes and eigenvalues disagree on the number of modes");
    if (rec.staticCorrection && (rec.staticCompliance.matrix.rows() != r || rec.staticCompliance.matrix.cols() != r))
      throw Error("reduced model: the static compliance must be retained DOFs square");
  } else if (rec.reduction.mass.rows() != r || rec.reduction.mass.cols() != r || rec.reduction.stiffness.cols() != r ||
             rec.reduction.massCoupling.cols() != rec.reduction.numInterfaceModes() ||
             (rec.reduction.numInterfaceModes() > 0 && rec.reduction.massCoupling.rows() != r)) {
    throw Error("reduced model: K_g, M_g and M_bm disagree in size");
  }
  AtomicFile file(path);
  try {
    H5::Exception::dontPrint();
    H5::H5File h5 = hdf5::inMemoryFile(file);
    if (modal(rec.kind)) {
      writeVector(h5, "eigenvalues", rec.modes.eigenvalues, H5::PredType::NATIVE_DOUBLE);
      writeMatrix(h5, "shapes", rec.modes.shapes);
      if (rec.staticCorrection) writeMatrix(h5, "static_compliance", rec.staticCompliance.matrix);
      // The excitation part: modal forces phi_j^T f and (hybrid) the static response to each pattern.
      if (rec.modes.loads.size()) writeMatrix(h5, "load_modal_forces", rec.modes.loads);
      if (rec.staticCorrection && rec.staticCompliance.loadResponse.size())
        writeMatrix(h5, "load_static_response", rec.staticCompliance.loadResponse);
    } else {
      writeMatrix(h5, "boundary_stiffness", rec.reduction.stiffness);
      writeMatrix(h5, "boundary_mass", rec.reduction.mass);
      if (rec.kind == "craig_bampton") {
        writeVector(h5, "interface_eigenvalues", rec.reduction.interfaceEigenvalues, H5::PredType::NATIVE_DOUBLE);
        writeMatrix(h5, "mass_coupling", rec.reduction.massCoupling);
      }
    }
    if (!rec.fullModelEigenvalues.empty())
      writeVector(h5, "full_model_eigenvalues", rec.fullModelEigenvalues, H5::PredType::NATIVE_DOUBLE);
    writeVector(h5, "retained_nodes", rec.retainedNodes, H5::PredType::NATIVE_INT);
    writeVector(h5, "retained_directions", rec.retainedDirections, H5::PredType::NATIVE_INT);
    writeVector(h5, "retained_copies", rec.retainedCopies, H5::PredType::NATIVE_INT);
    if (rec.retainedAxes.size()) writeMatrix(h5, "retained_axes", rec.retainedAxes);
    writeIntAttribute(h5, "format_version", kFormatVersion);
    writeStringAttribute(h5, "kind", rec.kind);
    if (!rec.inputDigest.empty()) writeStringAttribute(h5, "input_digest", rec.inputDigest);
    writeIntAttribute(h5, "harmonic", rec.nodalDiameter);  // the file's name for it (caches stay readable)
    writeIntAttribute(h5, "sectors", rec.sectors);
    writeIntAttribute(h5, "copies", modal(rec.kind) ? rec.modes.copies : rec.reduction.copies);
    writeIntAttribute(h5, "static_correction", rec.staticCorrection ? 1 : 0);
    writeDoubleAttribute(h5, "loss_factor", rec.lossFactor);
    writeDoubleAttribute(h5, "omega0", rec.staticCompliance.omega0);
    writeDoubleAttribute(h5, "shift", rec.staticCompliance.shift);
    writeDoubleAttribute(h5, "rpm", rec.rpm);
    writeStringAttribute(h5, "content_digest", contentDigest(rec));  // last: a file cut short has none
    hdf5::saveImage(h5, file);
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
    if (version != 1 && version != kFormatVersion)
      throw InputError(path, "reduced-model format version " + std::to_string(version) + " (expected 1 or 2)");
    rec.staticCorrection = readIntAttribute(h5, "static_correction") != 0;
    // Version 1 files hold hybrid or truncation models only and have no kind.
    rec.kind = version >= 2 ? readStringAttribute(h5, "kind") : (rec.staticCorrection ? "hybrid" : "truncation");
    const int copies = readIntAttribute(h5, "copies");
    if (modal(rec.kind)) {
      rec.modes.eigenvalues = readVector<double>(h5, "eigenvalues", H5::PredType::NATIVE_DOUBLE);
      rec.modes.shapes = readMatrix(h5, "shapes");
      rec.modes.copies = copies;
      if (rec.staticCorrection) rec.staticCompliance.matrix = readMatrix(h5, "static_compliance");
      if (h5.nameExists("load_modal_forces")) rec.modes.loads = readMatrix(h5, "load_modal_forces");
      if (h5.nameExists("load_static_response"))
        rec.staticCompliance.loadResponse = readMatrix(h5, "load_static_response");
    } else if (boundary(rec.kind)) {
      rec.reduction.copies = copies;
      rec.reduction.stiffness = readMatrix(h5, "boundary_stiffness");
      rec.reduction.mass = readMatrix(h5, "boundary_mass");
      rec.reduction.massCoupling.resize(rec.reduction.stiffness.rows(), 0);
      if (rec.kind == "craig_bampton") {
        rec.reduction.interfaceEigenvalues =
            readVector<double>(h5, "interface_eigenvalues", H5::PredType::NATIVE_DOUBLE);
        rec.reduction.massCoupling = readMatrix(h5, "mass_coupling");
      }
    } else {
      throw InputError(path, "unknown reduced-model kind '" + rec.kind + "' (hybrid, truncation, guyan, craig_bampton)");
    }
    if (h5.nameExists("full_model_eigenvalues"))
      rec.fullModelEigenvalues = readVector<double>(h5, "full_model_eigenvalues", H5::PredType::NATIVE_DOUBLE);
    rec.staticCompliance.omega0 = readDoubleAttribute(h5, "omega0");
    rec.staticCompliance.shift = readDoubleAttribute(h5, "shift");
    rec.retainedNodes = readVector<int>(h5, "retained_nodes", H5::PredType::NATIVE_INT);
    rec.retainedDirections = readVector<int>(h5, "retained_directions", H5::PredType::NATIVE_INT);
    rec.retainedCopies = readVector<int>(h5, "retained_copies", H5::PredType::NATIVE_INT);
    if (h5.nameExists("retained_axes")) rec.retainedAxes = readMatrix(h5, "retained_axes");
    rec.nodalDiameter = readIntAttribute(h5, "harmonic");
    rec.sectors = readIntAttribute(h5, "sectors");
    rec.lossFactor = readDoubleAttribute(h5, "loss_factor");
    rec.rpm = readDoubleAttribute(h5, "rpm");
    if (h5.attrExists("input_digest")) rec.inputDigest = readStringAttribute(h5, "input_digest");
    if (h5.attrExists("content_digest")) {
      const std::string written = readStringAttribute(h5, "content_digest");
      if (written != contentDigest(rec))
        throw InputError(path, "its content does not match the digest written with it (" + written +
                                   "): a damaged or edited file");
      rec.contentVerified = true;
    }
  } catch (const H5::Exception& e) {
    throw InputError(path, "not a Cyclone reduced-model HDF5 file: " + e.getDetailMsg());
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(path, e.what());
  }
  const Eigen::Index r = retainedSize(rec);
  const std::size_t ru = std::size_t(r);
  bool consistent = rec.retainedNodes.size() == ru && rec.retainedDirections.size() == ru &&
                    rec.retainedCopies.size() == ru &&
                    (rec.retainedAxes.size() == 0 || (rec.retainedAxes.rows() == r && rec.retainedAxes.cols() == 3));
  if (modal(rec.kind))
    consistent = consistent && rec.modes.shapes.cols() == Eigen::Index(rec.modes.eigenvalues.size()) &&
                 (rec.modes.loads.size() == 0 || rec.modes.loads.rows() == rec.modes.shapes.cols()) &&
                 (!rec.staticCorrection || rec.staticCompliance.loadResponse.cols() == rec.modes.loads.cols()) &&
                 (rec.staticCompliance.loadResponse.size() == 0 || rec.staticCompliance.loadResponse.rows() == r) &&
                 (!rec.staticCorrection ||
                  (rec.staticCompliance.matrix.rows() == r && rec.staticCompliance.matrix.cols() == r));
  else
    consistent = consistent && rec.reduction.stiffness.cols() == r && rec.reduction.mass.rows() == r &&
                 rec.reduction.mass.cols() == r && rec.reduction.massCoupling.rows() == r &&
                 rec.reduction.massCoupling.cols() == rec.reduction.numInterfaceModes() &&
                 rec.reduction.copies >= 1 &&
                 (rec.kind == "guyan" || (rec.reduction.numInterfaceModes() >= rec.reduction.copies &&
                                            rec.reduction.numInterfaceModes() % rec.reduction.copies == 0));
  if (!consistent) throw InputError(path, "inconsistent reduced model: datasets of different retained-DOF or mode counts");
  return rec;
}

}  // namespace cyclone::io
