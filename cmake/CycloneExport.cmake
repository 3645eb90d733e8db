# Exported CMake package: an engineering code does find_package(Cyclone) and
# links Cyclone::fe, Cyclone::solvers, ...
include(CMakePackageConfigHelpers)
install(EXPORT CycloneTargets NAMESPACE Cyclone:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Cyclone)
configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/CycloneConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/CycloneConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Cyclone)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/CycloneConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/CycloneConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/CycloneConfigVersion.cmake
  cmake/CycloneDependencies.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Cyclone)
# The third-party interface targets travel with the export; the consumer's
# find_package calls in CycloneDependencies.cmake provide what they link.
install(TARGETS cyclone_trilinos cyclone_exodus cyclone_gmsh cyclone_cholmod EXPORT CycloneTargets)
