# Why: the Python package `topocut` (pybind11 + numpy from Debian), built for Debian's /usr/bin/python3
# unless -DPython_EXECUTABLE=... names another (a pyenv python3 may come first on PATH), tested with
# pytest through ctest and installed into that Python's dist-packages under the install prefix
# (pip install . builds it through this file too: setup.py).
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
# Not built under the sanitizers: the interpreter is not instrumented, and an instrumented extension
# loads only into one with the sanitizer runtime preloaded (pybind11's documentation does so, which
# also instruments numpy, matplotlib and Python's own allocator; not tried here). Nothing would load
# it, and building it cost CI's sanitizer build a minute; the Release suite builds and tests it.
if(TOPOCUT_SANITIZE)
  if(TOPOCUT_BUILD_TESTS)
    add_test(NAME python_tests COMMAND ${CMAKE_COMMAND} -E echo
             "python_tests skipped under TOPOCUT_SANITIZE: run them in the Release build (bash .ci/setup.sh test)")
    set_tests_properties(python_tests PROPERTIES SKIP_REGULAR_EXPRESSION "skipped under TOPOCUT_SANITIZE")
    add_test(NAME python_package COMMAND ${CMAKE_COMMAND} -E echo
             "python_package skipped under TOPOCUT_SANITIZE: pip installs the Release build's extension (bash .ci/setup.sh test)")
    set_tests_properties(python_package PROPERTIES SKIP_REGULAR_EXPRESSION "skipped under TOPOCUT_SANITIZE")
  endif()
  return()
endif()

# The package topocut in build/python/topocut: the extension _topocut, the pure-Python part
# (src/python/topocut) and the type stubs, which the build writes from the option table by importing
# the extension.
set(python_package_dir ${CMAKE_BINARY_DIR}/python/topocut)
file(GLOB python_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/python/*.cpp)
pybind11_add_module(topocut_python MODULE ${python_sources})
set_target_properties(topocut_python PROPERTIES OUTPUT_NAME _topocut LIBRARY_OUTPUT_DIRECTORY ${python_package_dir})
target_include_directories(topocut_python PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_link_libraries(topocut_python PRIVATE topocut_lib)
set(python_package_sources ${CMAKE_CURRENT_SOURCE_DIR}/src/python/topocut/__init__.py
    ${CMAKE_CURRENT_SOURCE_DIR}/src/python/topocut/py.typed)
foreach(file IN LISTS python_package_sources)
  get_filename_component(name ${file} NAME)
  configure_file(${file} ${python_package_dir}/${name} COPYONLY)
endforeach()
set(python_stubs ${python_package_dir}/__init__.pyi)
add_custom_command(OUTPUT ${python_stubs}
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${CMAKE_BINARY_DIR}/python ${Python_EXECUTABLE}
          ${CMAKE_CURRENT_SOURCE_DIR}/src/python/generate_stubs.py ${CMAKE_CURRENT_SOURCE_DIR}/src/python/topocut/__init__.pyi.in
          ${python_stubs}
  DEPENDS topocut_python ${CMAKE_CURRENT_SOURCE_DIR}/src/python/topocut/__init__.pyi.in
          ${CMAKE_CURRENT_SOURCE_DIR}/src/python/generate_stubs.py ${python_package_sources}
  COMMENT "Writing the topocut package's type stubs from the option table")
add_custom_target(topocut_python_stubs ALL DEPENDS ${python_stubs})

set(TOPOCUT_PYTHON_INSTALL_DIR lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/dist-packages
    CACHE STRING "Where cmake --install puts the Python package, relative to the prefix (Debian's python3 reads <prefix>/lib/python3.X/dist-packages for /usr/local)")
# Installed only when it was built (`bash .ci/setup.sh demo` builds the command alone): a package
# without its extension, even an empty folder, would import as an empty namespace package.
install(CODE "
  if(EXISTS \"$<TARGET_FILE:topocut_python>\")
    file(INSTALL \"$<TARGET_FILE:topocut_python>\" ${python_package_sources}
         DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${TOPOCUT_PYTHON_INSTALL_DIR}/topocut\")
    if(EXISTS \"${python_stubs}\")
      file(INSTALL \"${python_stubs}\" DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${TOPOCUT_PYTHON_INSTALL_DIR}/topocut\")
    endif()
  endif()")

if(TOPOCUT_BUILD_TESTS)
  set(python_test_env PYTHONPATH=${CMAKE_BINARY_DIR}/python TOPOCUT_CLI=$<TARGET_FILE:topocut>
      TOPOCUT_SOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR} TOPOCUT_SHARED_DIR=${CMAKE_CURRENT_SOURCE_DIR}/../shared)
  add_test(NAME python_tests COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_SOURCE_DIR}/tests/python)
  set_tests_properties(python_tests PROPERTIES ENVIRONMENT "${python_test_env}" TIMEOUT 600)
  # pip install . into a fresh virtual environment (reusing this build) and the example run there.
  add_test(NAME python_package COMMAND ${Python_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/tests/package/pip_install_in_venv.py
           ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_BINARY_DIR} ${CMAKE_BINARY_DIR}/python_package)
  set_tests_properties(python_package PROPERTIES TIMEOUT 600 SKIP_RETURN_CODE 77)
  # The README's Python starts as written (the example, and the block run with build/python on the path).
  foreach(block python_example python)
    add_test(NAME readme_${block} COMMAND ${Python_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/tests/package/readme_commands.py
             --source ${CMAKE_CURRENT_SOURCE_DIR} --build ${CMAKE_BINARY_DIR} --block ${block} --cli $<TARGET_FILE:topocut>)
    set_tests_properties(readme_${block} PROPERTIES TIMEOUT 120 SKIP_RETURN_CODE 77)
  endforeach()
  # The shipped merge model is what the training script produces from the shared data sets.
  add_test(NAME merge_model_trained COMMAND ${Python_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/train_merge_model.py
           --check --build ${CMAKE_BINARY_DIR} --shared ${CMAKE_CURRENT_SOURCE_DIR}/../shared)
  # It takes minutes, more than any other test: ctest starts it first (COST), not last, where it would
  # run alone on one of CI's two cores.
  set_tests_properties(merge_model_trained PROPERTIES TIMEOUT 900 SKIP_RETURN_CODE 77 COST 10000)
  # The Python update benchmark runs and prints its table (a few grids of one map).
  add_test(NAME python_update_benchmark_runs COMMAND ${Python_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/benchmarks/python_update_benchmark.py
           --build ${CMAKE_BINARY_DIR} --steps 3 --still 1 --rounds 1 lab_d_scan)
  set_tests_properties(python_update_benchmark_runs PROPERTIES TIMEOUT 120 SKIP_RETURN_CODE 77
                       PASS_REGULAR_EXPRESSION "\\| lab_d_scan \\| build \\| [0-9.]+ \\| [0-9.]+ \\|")
endif()
