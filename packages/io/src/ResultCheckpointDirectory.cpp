#include "cyclone/io/ResultCheckpointDirectory.hpp"

#include <H5Cpp.h>

#include <filesystem>

#include "Hdf5Datasets.hpp"

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"

namespace cyclone::io {

void ResultCheckpointDirectory::save(const std::string& key, const std::vector<double>& values) {
  std::filesystem::create_directories(dir_);
  const std::string final = path(key);
  AtomicFile file(final);
  try {
    H5::Exception::dontPrint();
    H5::H5File h5(file.tempPath(), H5F_ACC_TRUNC);
    hdf5::writeVector(h5, "values", values, H5::PredType::NATIVE_DOUBLE);
  } catch (const H5::Exception& e) {
    throw Error("cannot write " + final + ": " + e.getDetailMsg());
  }
  file.commit();
}

std::optional<std::vector<double>> ResultCheckpointDirectory::load(const std::string& key) {
  const std::string p = path(key);
  if (!std::filesystem::exists(p)) return std::nullopt;
  try {
    H5::Exception::dontPrint();
    H5::H5File h5(p, H5F_ACC_RDONLY);
    return hdf5::readVector<double>(h5, "values", H5::PredType::NATIVE_DOUBLE);
  } catch (const H5::Exception& e) {
    log::warn("checkpoint " + p + " cannot be read (" + e.getDetailMsg() + "); it is computed again");
  }
  return std::nullopt;
}

}  // namespace cyclone::io
