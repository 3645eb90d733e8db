#pragma once
// Small HDF5 helpers shared by the package's file formats (private header).
#include <H5Cpp.h>

#include <string>
#include <vector>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::io::hdf5 {

// A file to be written, built in memory (HDF5's core driver, no backing store) and saved
// whole by saveImage. HDF5 writing to disk itself met a full disk in its close, which
// fails in a destructor: the file was renamed into place cut short, and HDF5, left with
// a file it could not close, crashed at the program's exit (issue 49). In memory nothing
// fails but the one checked write of the image.
inline H5::H5File inMemoryFile(const AtomicFile& target) {
  H5::FileAccPropList access;
  access.setCore(1 << 16, false);
  return H5::H5File(target.tempPath(), H5F_ACC_TRUNC, H5::FileCreatPropList::DEFAULT, access);
}

// The in-memory file's bytes written to the target's temporary (AtomicFile::write: a full
// disk is an Error naming the final path and the reason). The caller commits.
inline void saveImage(H5::H5File& file, const AtomicFile& target) {
  file.flush(H5F_SCOPE_GLOBAL);
  const ssize_t size = H5Fget_file_image(file.getId(), nullptr, 0);
  if (size < 0) throw H5::FileIException("H5Fget_file_image", "the file's size in memory is not known");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(file.getId(), image.data(), image.size()) != size)
    throw H5::FileIException("H5Fget_file_image", "the file's image could not be copied");
  target.write(image.data(), image.size());
}

template <class T>
void writeVector(H5::H5File& file, const char* name, const std::vector<T>& v, const H5::PredType& type) {
  const hsize_t dims[1] = {v.size()};
  H5::DataSpace space(1, dims);
  file.createDataSet(name, type, space).write(v.data(), type);
}

// A dataset's size as it claims, checked against the file's bytes before anything is
// allocated for it: the package writes contiguous, uncompressed datasets, so a damaged
// extent (one mutated byte made a reduced model's file claim terabytes, issue 49) is an
// Error naming the dataset, not a std::bad_alloc.
inline hsize_t checkedExtent(const H5::DataSet& set, const char* name, std::size_t elementSize, int rank) {
  const H5::DataSpace space = set.getSpace();
  if (space.getSimpleExtentNdims() != rank) throw Error(std::string(name) + (rank == 1 ? ": not a vector" : ": not a matrix"));
  hsize_t dims[2] = {1, 1};
  space.getSimpleExtentDims(dims);
  const hid_t file = H5Iget_file_id(set.getId());
  hsize_t bytes = 0;
  const herr_t got = file < 0 ? -1 : H5Fget_filesize(file, &bytes);
  if (file >= 0) H5Fclose(file);
  const hsize_t most = got < 0 ? 0 : bytes / elementSize;
  if (dims[0] > most || (rank == 2 && dims[0] > 0 && dims[1] > most / dims[0]))
    throw Error(std::string(name) + " claims " + std::to_string(dims[0]) + (rank == 2 ? " x " + std::to_string(dims[1]) : "") +
                " values, more than the file's " + std::to_string(bytes) + " bytes hold (a damaged file)");
  return rank == 2 ? dims[0] * dims[1] : dims[0];
}

template <class T>
std::vector<T> readVector(H5::H5File& file, const char* name, const H5::PredType& type) {
  auto set = file.openDataSet(name);
  hsize_t dims[1];
  checkedExtent(set, name, sizeof(T), 1);
  set.getSpace().getSimpleExtentDims(dims);
  std::vector<T> v(dims[0]);
  if (!v.empty()) set.read(v.data(), type);
  return v;
}

// Scalar attributes on the file's root group.
template <class T>
void writeAttribute(H5::H5File& file, const char* name, T value, const H5::PredType& type) {
  file.createAttribute(name, type, H5::DataSpace(H5S_SCALAR)).write(type, &value);
}

template <class T>
T readAttribute(H5::H5File& file, const char* name, const H5::PredType& type) {
  T value{};
  file.openAttribute(name).read(type, &value);
  return value;
}

inline void writeIntAttribute(H5::H5File& f, const char* n, int v) { writeAttribute(f, n, v, H5::PredType::NATIVE_INT); }
inline int readIntAttribute(H5::H5File& f, const char* n) { return readAttribute<int>(f, n, H5::PredType::NATIVE_INT); }
inline void writeDoubleAttribute(H5::H5File& f, const char* n, double v) {
  writeAttribute(f, n, v, H5::PredType::NATIVE_DOUBLE);
}
inline double readDoubleAttribute(H5::H5File& f, const char* n) {
  return readAttribute<double>(f, n, H5::PredType::NATIVE_DOUBLE);
}

// Fixed-length string attributes (what h5dump and h5py show as plain strings).
inline void writeStringAttribute(H5::H5File& f, const char* n, const std::string& v) {
  const H5::StrType type(H5::PredType::C_S1, v.empty() ? 1 : v.size());
  f.createAttribute(n, type, H5::DataSpace(H5S_SCALAR)).write(type, v);
}
inline std::string readStringAttribute(H5::H5File& f, const char* n) {
  auto attr = f.openAttribute(n);
  std::string v;
  attr.read(attr.getStrType(), v);
  return v;
}

}  // namespace cyclone::io::hdf5
