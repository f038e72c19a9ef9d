# Installing tagmap: `cmake --install build --prefix P` puts the libraries,
# their public headers, the MRPT plugin, the `tagmap` command and share/ under
# P, with a CMake package (find_package(tagmap) -> tagmap::core, tagmap::detect,
# ...) and a pkg-config file. tests/install/ builds a program against it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(TAGMAP_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/tagmap)
# MRPT apps are pointed at the plugin by path (`RawLogViewer -l`), so it has
# a folder of its own rather than sitting among the link libraries.
set(TAGMAP_INSTALL_PLUGINDIR ${CMAKE_INSTALL_LIBDIR}/tagmap)
set(TAGMAP_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/tagmap)

# tagmap_library(tagmap_X): the target's public headers (include/ next to its
# CMakeLists.txt) in the build and the install tree, the alias tagmap::X that
# both the build and the installed package use, and its install rules.
function(tagmap_library target)
  string(REGEX REPLACE "^tagmap_" "" short ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${short})
  add_library(tagmap::${short} ALIAS ${target})
  install(TARGETS ${target} EXPORT tagmapTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  set_property(GLOBAL APPEND PROPERTY TAGMAP_LIBRARIES ${target})
endfunction()

# After every target exists: the package files and the pkg-config file.
function(tagmap_install_package)
  install(EXPORT tagmapTargets NAMESPACE tagmap:: DESTINATION ${TAGMAP_INSTALL_CMAKEDIR})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tagmapConfig.cmake.in
    ${PROJECT_BINARY_DIR}/tagmapConfig.cmake INSTALL_DESTINATION ${TAGMAP_INSTALL_CMAKEDIR}
    PATH_VARS TAGMAP_INSTALL_PLUGINDIR TAGMAP_INSTALL_DATADIR)
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/tagmapConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/tagmapConfig.cmake ${PROJECT_BINARY_DIR}/tagmapConfigVersion.cmake
    DESTINATION ${TAGMAP_INSTALL_CMAKEDIR})

  # pkg-config: the libraries in link order (users first), then their
  # non-tagmap dependencies as pkg-config names.
  get_property(libs GLOBAL PROPERTY TAGMAP_LIBRARIES)
  list(REVERSE libs)
  set(TAGMAP_PC_LIBS "")
  foreach(l ${libs})
    string(APPEND TAGMAP_PC_LIBS " -l${l}")
  endforeach()
  # MRPT 2.5 ships no pkg-config files: its headers (one include/ folder per
  # module) and libraries are named here directly.
  get_target_property(core_inc mrpt::core INTERFACE_INCLUDE_DIRECTORIES)
  list(GET core_inc 0 core_inc)
  get_filename_component(mrpt_root ${core_inc} DIRECTORY)
  get_filename_component(mrpt_root ${mrpt_root} DIRECTORY)
  file(GLOB mrpt_incs LIST_DIRECTORIES true ${mrpt_root}/*/include)
  set(TAGMAP_PC_MRPT_CFLAGS "")
  foreach(d ${mrpt_incs})
    string(APPEND TAGMAP_PC_MRPT_CFLAGS " -I${d}")
  endforeach()
  set(TAGMAP_PC_MRPT_LIBS "")
  foreach(m slam vision maps obs opengl poses math serialization io config containers system core)
    string(APPEND TAGMAP_PC_MRPT_LIBS " -lmrpt-${m}")
  endforeach()
  configure_file(${PROJECT_SOURCE_DIR}/cmake/tagmap.pc.in ${PROJECT_BINARY_DIR}/tagmap.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/tagmap.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

  install(DIRECTORY ${PROJECT_SOURCE_DIR}/share/ DESTINATION ${TAGMAP_INSTALL_DATADIR})
endfunction()
