# The API reference: Doxygen over the installed headers (cmake/install.cmake's lists), as the
# target impact_docs that `make docs` builds (it installs doxygen first). Without doxygen the
# target says what to install.
set(IMPACT_DOCS_DIR ${PROJECT_BINARY_DIR}/docs)
string(JOIN " " IMPACT_DOXYGEN_INPUT ${IMPACT_PUBLIC_HEADERS} ${IMPACT_SCENE_PUBLIC_HEADERS})
# The filter's interpreter: any python3 will do; Debian's first, as for the module.
find_program(IMPACT_DOCS_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(IMPACT_DOCS_PYTHON NAMES python3)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${PROJECT_BINARY_DIR}/Doxyfile @ONLY)
find_program(IMPACT_DOXYGEN doxygen)
if(IMPACT_DOXYGEN)
  add_custom_target(impact_docs
    COMMAND ${CMAKE_COMMAND} -E make_directory ${IMPACT_DOCS_DIR}
    COMMAND ${IMPACT_DOXYGEN} ${PROJECT_BINARY_DIR}/Doxyfile
    COMMAND ${CMAKE_COMMAND} -E echo "docs: the API reference is ${IMPACT_DOCS_DIR}/html/index.html"
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} VERBATIM)
else()
  add_custom_target(impact_docs
    COMMAND ${CMAKE_COMMAND} -E echo "impact_docs: doxygen not found (Debian: doxygen; make docs installs it)"
    COMMAND ${CMAKE_COMMAND} -E false VERBATIM)
endif()
