# Why: the Python module `topocut` (pybind11 + numpy from Debian), built for Debian's /usr/bin/python3
# unless -DPython_EXECUTABLE=... names another (a pyenv python3 may come first on PATH), tested with
# pytest through ctest and installed into that Python's dist-packages under the install prefix.
option(TOPOCUT_BUILD_PYTHON "Build the Python module (needs pybind11-dev, python3-dev, python3-numpy)" ON)
if(NOT TOPOCUT_BUILD_PYTHON)
  return()
endif()
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python 3 COMPONENTS Interpreter Development.Module)
set(PYBIND11_FINDPYTHON ON)
find_package(pybind11 CONFIG QUIET)
if(NOT Python_FOUND OR NOT pybind11_FOUND)
  message(STATUS "topocut: Python module not built (needs python3-dev and pybind11-dev)")
  return()
endif()

file(GLOB python_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/python/*.cpp)
pybind11_add_module(topocut_python MODULE ${python_sources})
set_target_properties(topocut_python PROPERTIES OUTPUT_NAME topocut LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/python)
target_include_directories(topocut_python PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_link_libraries(topocut_python PRIVATE topocut_lib)

set(TOPOCUT_PYTHON_INSTALL_DIR lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/dist-packages
    CACHE STRING "Where cmake --install puts the Python module, relative to the prefix (Debian's python3 reads <prefix>/lib/python3.X/dist-packages for /usr/local)")
install(TARGETS topocut_python LIBRARY DESTINATION ${TOPOCUT_PYTHON_INSTALL_DIR})

if(TOPOCUT_BUILD_TESTS)
  set(python_test_env PYTHONPATH=${CMAKE_BINARY_DIR}/python TOPOCUT_CLI=$<TARGET_FILE:topocut>
      TOPOCUT_SOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR} TOPOCUT_SHARED_DIR=${CMAKE_CURRENT_SOURCE_DIR}/../shared)
  if(TOPOCUT_SANITIZE)
    # The interpreter is not instrumented: pybind11's documentation has the ASan runtime preloaded
    # into it, which also instruments numpy, matplotlib and Python's own allocator. Not tried here
    # yet, so the sanitizer suite skips the Python tests with a message; the Release suite runs them.
    add_test(NAME python_tests COMMAND ${CMAKE_COMMAND} -E echo
             "python_tests skipped under TOPOCUT_SANITIZE: run them in the Release build (bash .ci/setup.sh test)")
    set_tests_properties(python_tests PROPERTIES SKIP_REGULAR_EXPRESSION "skipped under TOPOCUT_SANITIZE")
    return()
  endif()
  add_test(NAME python_tests COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_SOURCE_DIR}/tests/python)
  set_tests_properties(python_tests PROPERTIES ENVIRONMENT "${python_test_env}" TIMEOUT 600)
endif()
