# cyclone_add_package(NAME SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# Builds library cyclone_<NAME> (alias Cyclone::<NAME>) from packages/<NAME>;
# public headers live in packages/<NAME>/include/cyclone/<NAME>/.
function(cyclone_add_package name)
  cmake_parse_arguments(P "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(cyclone_${name} ${P_SOURCES})
  add_library(Cyclone::${name} ALIAS cyclone_${name})
  set_target_properties(cyclone_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME cyclone_${name})
  target_include_directories(cyclone_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_options(cyclone_${name} PRIVATE -Wall -Wextra)
  target_link_libraries(cyclone_${name} PUBLIC ${P_PUBLIC_DEPS} PRIVATE ${P_PRIVATE_DEPS})
  install(TARGETS cyclone_${name} EXPORT CycloneTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
