# Third-party dependencies, all from Debian 12 packages (scripts/debian-packages.txt).
# Imported targets defined here are reused by cmake/CycloneConfig.cmake.in for consumers.

find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(Threads REQUIRED)  # the cyclic sweep's nodal diameters on threads

# One call with all components: TrilinosConfig.cmake is include-guarded.
find_package(Trilinos 13.2 REQUIRED
  COMPONENTS Teuchos Kokkos Tpetra Belos Anasazi Ifpack2 MueLu NOX Thyra)
if(NOT TARGET cyclone_trilinos)
  add_library(cyclone_trilinos INTERFACE)
  # Debian's imported Trilinos targets carry no include directories.
  target_include_directories(cyclone_trilinos SYSTEM INTERFACE ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
  target_link_libraries(cyclone_trilinos INTERFACE ${Trilinos_LIBRARIES} MPI::MPI_CXX)
endif()

find_package(Eigen3 3.4 REQUIRED NO_MODULE)

find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
# ARPACK (ARPACK-NG): the Floquet exponents nearest zero of a large Hill problem.
pkg_check_modules(ARPACK REQUIRED IMPORTED_TARGET arpack)

# Same (openmpi) HDF5 flavour as Trilinos and Exodus link, never both.
set(HDF5_PREFER_PARALLEL TRUE)
set(HDF5_CXX_COMPILER_EXECUTABLE /usr/bin/h5c++.openmpi CACHE FILEPATH "")
find_package(HDF5 REQUIRED COMPONENTS C CXX)

find_path(EXODUS_INCLUDE_DIR exodusII.h REQUIRED)
find_library(EXODUS_LIBRARY exoIIv2c REQUIRED)
find_library(NETCDF_LIBRARY netcdf REQUIRED)  # Exodus files are netCDF: the reader checks their size
if(NOT TARGET cyclone_exodus)
  add_library(cyclone_exodus INTERFACE)
  target_include_directories(cyclone_exodus SYSTEM INTERFACE ${EXODUS_INCLUDE_DIR})
  target_link_libraries(cyclone_exodus INTERFACE ${EXODUS_LIBRARY} ${NETCDF_LIBRARY} m)
endif()

find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
if(NOT TARGET cyclone_gmsh)
  add_library(cyclone_gmsh INTERFACE)
  target_include_directories(cyclone_gmsh SYSTEM INTERFACE ${GMSH_INCLUDE_DIR})
  target_link_libraries(cyclone_gmsh INTERFACE ${GMSH_LIBRARY})
endif()

find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(UMFPACK_LIBRARY umfpack REQUIRED)  # complex LU (frequency responses); same SuiteSparse package
if(NOT TARGET cyclone_cholmod)
  add_library(cyclone_cholmod INTERFACE)
  target_include_directories(cyclone_cholmod SYSTEM INTERFACE ${CHOLMOD_INCLUDE_DIR})
  target_link_libraries(cyclone_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${UMFPACK_LIBRARY})
endif()

# CHOLMOD is 9-20x slower on Debian's reference BLAS: insist that the BLAS
# alternative resolves to OpenBLAS (docs/solvers.md has the measurements).
get_filename_component(_cyclone_blas_real /usr/lib/x86_64-linux-gnu/libblas.so.3 REALPATH)
if(NOT _cyclone_blas_real MATCHES "openblas")
  message(WARNING "libblas.so.3 resolves to ${_cyclone_blas_real}, not OpenBLAS: sparse direct "
                  "solves will be 9-20x slower. Install libopenblas0-pthread (scripts/setup).")
else()
  message(STATUS "Cyclone: BLAS is ${_cyclone_blas_real}")
endif()
