# `cmake --install build --prefix DIR`: the `impact` command in DIR/bin, and the core library as a
# package that a program finds with find_package(impact 0.2) and links as impact::impact, or with
# pkg-config (impact.pc); the scene reader as its component `scene` (impact::scene, impact-scene.pc).
# The analyses and the CLI's sources stay private.
include(CMakePackageConfigHelpers)

install(TARGETS impact_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The public headers: the umbrella impact.hpp, the API it includes, and the headers those include.
# Left out, as the core's implementation: gsl_errors.hpp, processor.hpp and step_quadrature.hpp (no
# public header includes them).
set(IMPACT_PUBLIC_HEADERS
  impact.hpp any_stepper.hpp atomic_file.hpp bonding.hpp capabilities.hpp chain.hpp
  chain_moreau_jean.hpp chain_reference.hpp channels.hpp
  contact.hpp contact_law.hpp direct.hpp direct_located.hpp ensemble.hpp
  error_norms.hpp event.hpp event_driven.hpp exact.hpp exact_bonded.hpp exact_march.hpp
  expression.hpp
  fb_newton.hpp flight_search.hpp force.hpp format.hpp free_flight.hpp harmonic_series.hpp
  heap_value.hpp
  internal.hpp internal_floor.hpp internal_stepper.hpp linear_flight.hpp linear_law.hpp
  method_params.hpp model.hpp moreau_jean.hpp ode_flight.hpp output.hpp penalty.hpp repeats.hpp
  restitution.hpp row.hpp row_stream.hpp run.hpp run_result.hpp run_scene.hpp scene.hpp scheme_flight.hpp
  step_events.hpp stepper.hpp
  summary.hpp summary_lanes.hpp version.hpp work_energy.hpp)
list(TRANSFORM IMPACT_PUBLIC_HEADERS PREPEND ${PROJECT_SOURCE_DIR}/src/impact/)
# A public header that includes a header left out would break every program that includes it:
# stop at configure time naming both (a new header must join the list above or stay unincluded).
foreach(header ${IMPACT_PUBLIC_HEADERS})
  file(STRINGS ${header} includes REGEX "^#include \"impact/")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"impact/([^\"]+)\".*" "\\1" included "${line}")
    if(NOT "${PROJECT_SOURCE_DIR}/src/impact/${included}" IN_LIST IMPACT_PUBLIC_HEADERS)
      message(FATAL_ERROR "cmake/install.cmake: the public header ${header} includes "
                          "impact/${included}, which is not installed: add it to the list")
    endif()
  endforeach()
endforeach()
install(FILES ${IMPACT_PUBLIC_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impact)

# The scene reader's public headers, as <impact/scene/...>: they include the core's as
# "impact/..." and each other as "name.hpp" (same directory, which resolves in the tree and
# installed). toml++ stays the reader's own: a header here that includes it, or one of this
# directory that is not installed, stops the configuration.
set(IMPACT_SCENE_PUBLIC_HEADERS read_scene.hpp scene_error.hpp sweep_engine.hpp sweep_grid.hpp
                                 sweep_quantities.hpp)
list(TRANSFORM IMPACT_SCENE_PUBLIC_HEADERS PREPEND ${PROJECT_SOURCE_DIR}/src/scene/)
foreach(header ${IMPACT_SCENE_PUBLIC_HEADERS})
  file(STRINGS ${header} includes REGEX "^#include [\"<]")
  foreach(line ${includes})
    if(line MATCHES "toml")
      message(FATAL_ERROR "cmake/install.cmake: the installed scene header ${header} includes "
                          "toml++ (${line}), which is the reader's private dependency")
    elseif(line MATCHES "^#include \"impact/([^\"]+)\"")
      set(included ${PROJECT_SOURCE_DIR}/src/impact/${CMAKE_MATCH_1})
      set(list_name IMPACT_PUBLIC_HEADERS)
    elseif(line MATCHES "^#include \"([^\"/]+)\"")
      set(included ${PROJECT_SOURCE_DIR}/src/scene/${CMAKE_MATCH_1})
      set(list_name IMPACT_SCENE_PUBLIC_HEADERS)
    elseif(line MATCHES "^#include \"")
      message(FATAL_ERROR "cmake/install.cmake: the installed scene header ${header} has ${line}: "
                          "include the core as \"impact/...\" and this directory as \"name.hpp\"")
    else()
      continue()
    endif()
    if(NOT included IN_LIST ${list_name})
      message(FATAL_ERROR "cmake/install.cmake: the installed scene header ${header} includes "
                          "${included}, which is not installed: add it to ${list_name}")
    endif()
  endforeach()
endforeach()
install(FILES ${IMPACT_SCENE_PUBLIC_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impact/scene)

set(IMPACT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/impact)
install(TARGETS impact_core EXPORT impactTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT impactTargets NAMESPACE impact:: DESTINATION ${IMPACT_CMAKE_DIR})
# The scene component in an export set of its own, which the package config reads only when a
# program asks for it (find_package(impact 0.2 COMPONENTS scene)), so that a program of the core
# alone needs no toml++.
install(TARGETS impact_scene EXPORT impactSceneTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT impactSceneTargets NAMESPACE impact:: DESTINATION ${IMPACT_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/impactConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/impactConfig.cmake
                              INSTALL_DESTINATION ${IMPACT_CMAKE_DIR})
# Before 1.0 a minor release may change the API (0.2 is not 0.1), so a request for 0.2 accepts
# 0.2.x only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/impactConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/impactConfig.cmake ${PROJECT_BINARY_DIR}/impactConfigVersion.cmake
        DESTINATION ${IMPACT_CMAKE_DIR})

# impact.pc finds its prefix from where it lies (${pcfiledir}), so that it stays right under
# `cmake --install --prefix DIR`. The archive's dependencies are in Requires, not Requires.private:
# a static library needs them on every link.
file(RELATIVE_PATH IMPACT_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" IMPACT_PC_TO_PREFIX "${IMPACT_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/impact.pc.in ${PROJECT_BINARY_DIR}/impact.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/impact.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
configure_file(${PROJECT_SOURCE_DIR}/cmake/impact-scene.pc.in ${PROJECT_BINARY_DIR}/impact-scene.pc
               @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/impact-scene.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
