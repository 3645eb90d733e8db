#include "cyclone/io/ResponseCurveFile.hpp"

#include <H5Cpp.h>

#include "Hdf5Datasets.hpp"

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::io {

using namespace hdf5;

void writeResponseCurveHdf5(const std::string& path, const ResponseCurve& c) {
  const std::size_t P = c.omega.size(), m = std::size_t(c.numDofs) * c.numCoefficients;
  if (c.coefficients.size() != P || c.stable.size() != P || (!c.segment.empty() && c.segment.size() != P))
    throw Error("response curve: inconsistent point counts");
  AtomicFile file(path);
  try {
    H5::Exception::dontPrint();
    H5::H5File h5 = hdf5::inMemoryFile(file);
    writeVector(h5, "omega", c.omega, H5::PredType::NATIVE_DOUBLE);
    writeVector(h5, "harmonics", c.harmonics, H5::PredType::NATIVE_INT);
    writeVector(h5, "stable", c.stable, H5::PredType::NATIVE_INT);
    writeVector(h5, "segment", c.segment.empty() ? std::vector<int>(P, 0) : c.segment, H5::PredType::NATIVE_INT);
    writeVector(h5, "parameter", c.parameter.empty() ? c.omega : c.parameter, H5::PredType::NATIVE_DOUBLE);
    std::vector<double> flat(P * m);
    for (std::size_t p = 0; p < P; ++p) {
      if (std::size_t(c.coefficients[p].size()) != m) throw Error("response curve: coefficient vector of the wrong size");
      for (std::size_t j = 0; j < m; ++j) flat[p * m + j] = c.coefficients[p](j);
    }
    const hsize_t dims[2] = {P, m};
    H5::DataSpace space(2, dims);
    h5.createDataSet("coefficients", H5::PredType::NATIVE_DOUBLE, space).write(flat.data(), H5::PredType::NATIVE_DOUBLE);
    writeIntAttribute(h5, "num_dofs", c.numDofs);
    writeIntAttribute(h5, "num_coefficients", c.numCoefficients);
    writeIntAttribute(h5, "samples", c.samples);
    hdf5::saveImage(h5, file);
  } catch (const H5::Exception& e) {
    throw Error("cannot write " + path + ": " + e.getDetailMsg());
  }
  file.commit();
}

ResponseCurve readResponseCurveHdf5(const std::string& path) {
  ResponseCurve c;
  try {
    H5::Exception::dontPrint();
    H5::H5File h5(path, H5F_ACC_RDONLY);
    c.omega = readVector<double>(h5, "omega", H5::PredType::NATIVE_DOUBLE);
    c.harmonics = readVector<int>(h5, "harmonics", H5::PredType::NATIVE_INT);
    c.stable = readVector<int>(h5, "stable", H5::PredType::NATIVE_INT);
    c.parameter = readVector<double>(h5, "parameter", H5::PredType::NATIVE_DOUBLE);
    // Files written before segments existed hold one sweep.
    c.segment = h5.nameExists("segment") ? readVector<int>(h5, "segment", H5::PredType::NATIVE_INT)
                                         : std::vector<int>(c.omega.size(), 0);
    c.numDofs = readIntAttribute(h5, "num_dofs");
    c.numCoefficients = readIntAttribute(h5, "num_coefficients");
    c.samples = readIntAttribute(h5, "samples");
    const std::size_t m = std::size_t(c.numDofs) * c.numCoefficients;
    std::vector<double> flat(c.omega.size() * m);
    if (!flat.empty()) h5.openDataSet("coefficients").read(flat.data(), H5::PredType::NATIVE_DOUBLE);
    for (std::size_t p = 0; p < c.omega.size(); ++p)
      c.coefficients.push_back(Eigen::Map<const Eigen::VectorXd>(flat.data() + p * m, Eigen::Index(m)));
  } catch (const H5::Exception& e) {
    throw InputError(path, "not a Cyclone response-curve HDF5 file: " + e.getDetailMsg());
  }
  return c;
}

}  // namespace cyclone::io
