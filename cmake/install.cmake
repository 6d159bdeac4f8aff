# Why: `cmake --install` makes topocut a package other projects use: headers, the module libraries,
# the command, a CMake config package (find_package(topocut CONFIG REQUIRED) -> topocut::topocut)
# and a pkg-config file. Included from the top-level CMakeLists.txt after the targets exist.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(TOPOCUT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/topocut)

# The modules' include path is the source tree while building and <prefix>/include once installed.
foreach(module IN LISTS TOPOCUT_MODULES)
  get_target_property(module_type topocut_${module} TYPE)
  if(module_type STREQUAL "INTERFACE_LIBRARY")
    set(scope INTERFACE)
  else()
    set(scope PUBLIC)
  endif()
  set_property(TARGET topocut_${module} PROPERTY INTERFACE_INCLUDE_DIRECTORIES
               $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<BUILD_INTERFACE:${CMAKE_CURRENT_BINARY_DIR}/generated/include>
               $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
endforeach()
set_target_properties(topocut_lib PROPERTIES EXPORT_NAME topocut)
add_library(topocut::topocut ALIAS topocut_lib)

set(topocut_module_targets)
foreach(module IN LISTS TOPOCUT_MODULES)
  list(APPEND topocut_module_targets topocut_${module})
endforeach()
install(TARGETS ${topocut_module_targets} topocut_lib EXPORT topocutTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS topocut RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY include/topocut DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/generated/include/topocut/core/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/topocut/core)
install(EXPORT topocutTargets NAMESPACE topocut:: DESTINATION ${TOPOCUT_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/topocutConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/topocutConfig.cmake INSTALL_DESTINATION ${TOPOCUT_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/topocutConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/topocutConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/topocutConfigVersion.cmake
        DESTINATION ${TOPOCUT_INSTALL_CMAKEDIR})

# pkg-config: the public headers need C++20 and OpenCV's core headers only, so Cflags give -std=c++20
# and OpenCV's include folder (as -isystem, as CMake includes imported targets: OpenCV's headers warn
# under C++20). The module libraries are static, so Libs name every module (users first) and, after
# them, the few libraries they link privately, never the whole of opencv4.pc (about 60 libraries).
set(TOPOCUT_PC_LIBS)
set(reversed_modules ${TOPOCUT_MODULES})
list(REVERSE reversed_modules)
foreach(module IN LISTS reversed_modules)
  get_target_property(module_type topocut_${module} TYPE)
  if(NOT module_type STREQUAL "INTERFACE_LIBRARY")
    string(APPEND TOPOCUT_PC_LIBS " -ltopocut_${module}")
  endif()
endforeach()
# "-L<folder> -l<name>" for an imported target or a library file; the folder is left out when the
# linker searches it anyway.
function(topocut_pc_link_flags out)
  set(flags "")
  set(items ${ARGN})
  list(REMOVE_DUPLICATES items)
  foreach(item IN LISTS items)
    set(file "${item}")
    if(TARGET ${item})
      get_target_property(configurations ${item} IMPORTED_CONFIGURATIONS)
      set(file "")
      foreach(suffix _RELEASE "" _NONE)
        if(NOT file)
          get_target_property(file ${item} IMPORTED_LOCATION${suffix})
        endif()
      endforeach()
      if(NOT file AND configurations)
        list(GET configurations 0 configuration)
        get_target_property(file ${item} IMPORTED_LOCATION_${configuration})
      endif()
      if(NOT file)
        message(FATAL_ERROR "topocut.pc: no library file for the imported target ${item}")
      endif()
    endif()
    if(file MATCHES "^-")
      string(APPEND flags " ${file}")
      continue()
    endif()
    get_filename_component(folder "${file}" DIRECTORY)
    get_filename_component(name "${file}" NAME)
    string(REGEX REPLACE "^lib([^.]+)\\..*$" "\\1" name "${name}")
    if(folder AND NOT folder IN_LIST CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES)
      string(APPEND flags " -L${folder}")
    endif()
    string(APPEND flags " -l${name}")
  endforeach()
  set(${out} "${flags}" PARENT_SCOPE)
endfunction()
topocut_pc_link_flags(TOPOCUT_PC_PRIVATE_LIBS opencv_imgproc opencv_core yaml-cpp ${PNG_LIBRARIES} ${JPEG_LIBRARIES}
                      ${ZLIB_LIBRARIES} -lgmp -lmpfr -lpthread ${CMAKE_DL_LIBS})
set(TOPOCUT_PC_CFLAGS "")
foreach(folder IN LISTS OpenCV_INCLUDE_DIRS)
  string(APPEND TOPOCUT_PC_CFLAGS " -isystem ${folder}")
endforeach()
# Relocatable: the prefix is found from the .pc file's own place, so `cmake --install --prefix DIR` works.
file(RELATIVE_PATH TOPOCUT_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
string(REGEX REPLACE "/$" "" TOPOCUT_PC_TO_PREFIX "${TOPOCUT_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/topocut.pc.in ${CMAKE_CURRENT_BINARY_DIR}/topocut.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/topocut.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
