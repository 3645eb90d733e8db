#pragma once
// Private to ExodusIO: a classic or 64-bit-offset netCDF file's header walked before
// netCDF opens it. netCDF allocates what the header's counts say (names, attribute
// values) before it checks them, so a damaged 42 kB Exodus file took 18.9 GB and 45 s
// to fail (found by fuzz_readers under ASan). Every count and length must fit in the
// bytes left, or the file is refused with what and where.
#include <string>

namespace cyclone::mesh::detail {

/// Returns quietly for a file that is not classic netCDF (HDF5-based netCDF-4, or not
/// netCDF at all: ex_open says what it is) and for a header whose counts fit.
void checkNetcdfHeader(const std::string& path);

}  // namespace cyclone::mesh::detail
