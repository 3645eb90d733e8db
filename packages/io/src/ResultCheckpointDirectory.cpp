#include "cyclone/io/ResultCheckpointDirectory.hpp"

#include <H5Cpp.h>

#include <filesystem>

#include "Hdf5Datasets.hpp"

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/ContentHash.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"

namespace cyclone::io {

namespace {

// The values with the key they are filed under: an edited value, or a file copied under
// another key, does not match it.
std::string valuesDigest(const std::string& key, const std::vector<double>& values) {
  ContentHash h;
  h.add(std::string("cyclone result checkpoint v1")).add(key).addAll(values);
  return h.hex();
}

}  // namespace

void ResultCheckpointDirectory::save(const std::string& key, const std::vector<double>& values) {
  std::filesystem::create_directories(dir_);
  const std::string final = path(key);
  AtomicFile file(final);
  try {
    H5::Exception::dontPrint();
    H5::H5File h5 = hdf5::inMemoryFile(file);
    hdf5::writeVector(h5, "values", values, H5::PredType::NATIVE_DOUBLE);
    hdf5::writeStringAttribute(h5, "content_digest", valuesDigest(key, values));  // last
    hdf5::saveImage(h5, file);
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
    auto values = hdf5::readVector<double>(h5, "values", H5::PredType::NATIVE_DOUBLE);
    if (!h5.attrExists("content_digest")) {
      log::warn("checkpoint " + p + " has no content digest (written by an older version); it is computed again");
      return std::nullopt;
    }
    if (hdf5::readStringAttribute(h5, "content_digest") != valuesDigest(key, values)) {
      log::warn("checkpoint " + p + ": its content does not match the digest written with it (a damaged or edited "
                "file, or one filed under another key); it is computed again");
      return std::nullopt;
    }
    return values;
  } catch (const H5::Exception& e) {
    log::warn("checkpoint " + p + " cannot be read (" + e.getDetailMsg() + "); it is computed again");
  }
  return std::nullopt;
}

}  // namespace cyclone::io
