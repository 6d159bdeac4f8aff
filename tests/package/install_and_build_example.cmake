# ctest script: install the build into a fresh temporary prefix, configure and build examples/ against
# it with find_package(topocut), run the program on a bundled map and on its in-memory grid, and check
# that pkg-config resolves the installed topocut.pc. Arguments: BUILD_DIR SOURCE_DIR WORK_DIR
# EXTRA_LINK_FLAGS (the sanitizer runtime when the library was built with it).
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

function(expect text pattern)
  if(NOT text MATCHES "${pattern}")
    message(FATAL_ERROR "expected output matching '${pattern}', got:\n${text}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed include/topocut/topocut.h bin/topocut)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "cmake --install did not install ${installed}")
  endif()
endforeach()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_EXE_LINKER_FLAGS=${EXTRA_LINK_FLAGS}")
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/segment_map ${SOURCE_DIR}/maps/floorplan.yaml)
expect("${run_output}" "room 1: [0-9.]+ m2, inside")
expect("${run_output}" "passage [0-9]+ - [0-9]+: [0-9.]+ m (door|opening)")
# The in-memory grid: two rooms joined by one door.
run(${WORK_DIR}/build/segment_map)
expect("${run_output}" "room 1: .*room 2: ")
expect("${run_output}" "passage 1 - 2: [0-9.]+ m door")
run(${prefix}/bin/topocut --help)

find_program(PKG_CONFIG pkg-config)
if(PKG_CONFIG)
  set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig:${prefix}/lib/x86_64-linux-gnu/pkgconfig)
  run(${PKG_CONFIG} --cflags --libs topocut)
  expect("${run_output}" "-I.*-ltopocut_segmentation.*-ltopocut_core")
  run(${PKG_CONFIG} --variable=includedir topocut)
  string(STRIP "${run_output}" includedir)
  if(NOT EXISTS ${includedir}/topocut/topocut.h)
    message(FATAL_ERROR "pkg-config's includedir ${includedir} does not hold topocut/topocut.h")
  endif()
endif()
file(REMOVE_RECURSE ${WORK_DIR})
