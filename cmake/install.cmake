# `cmake --install build --prefix DIR`: the `impact` command in DIR/bin, and the core library as a
# package that a program finds with find_package(impact 0.2) and links as impact::impact, or with
# pkg-config (impact.pc); the scene reader as its component `scene` (impact::scene, impact-scene.pc).
# The analyses and the CLI's sources stay private.
include(CMakePackageConfigHelpers)

install(TARGETS impact_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The public headers: every header of src/impact, in its folder (<impact/model/model.hpp>, ...; the
# umbrella <impact/impact.hpp> includes the API), so that a new method or law needs no edit here.
# Left out, as the core's implementation: the few that no public header includes.
file(GLOB_RECURSE IMPACT_PUBLIC_HEADERS RELATIVE ${PROJECT_SOURCE_DIR}/src/impact
     ${PROJECT_SOURCE_DIR}/src/impact/*.hpp)
list(REMOVE_ITEM IMPACT_PUBLIC_HEADERS ensemble/ensemble_tally.hpp ensemble/processor.hpp
     forces/gsl_errors.hpp forces/step_quadrature.hpp)
list(SORT IMPACT_PUBLIC_HEADERS)
list(TRANSFORM IMPACT_PUBLIC_HEADERS PREPEND ${PROJECT_SOURCE_DIR}/src/impact/)
# A public header that includes a header left out would break every program that includes it:
# stop at configure time naming both (a header left out must stay unincluded by the public ones).
foreach(header ${IMPACT_PUBLIC_HEADERS})
  file(STRINGS ${header} includes REGEX "^#include \"impact/")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"impact/([^\"]+)\".*" "\\1" included "${line}")
    if(NOT "${PROJECT_SOURCE_DIR}/src/impact/${included}" IN_LIST IMPACT_PUBLIC_HEADERS)
      message(FATAL_ERROR "cmake/install.cmake: the public header ${header} includes "
                          "impact/${included}, which is not installed: take it off the list left out")
    endif()
  endforeach()
  file(RELATIVE_PATH installed ${PROJECT_SOURCE_DIR}/src ${header})
  get_filename_component(folder ${installed} DIRECTORY)
  install(FILES ${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${folder})
endforeach()

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
