# What `cmake --install` puts under the prefix P, and the CMake package that lets other projects
# use it with find_package(vascsim 0.2 REQUIRED) (docs/install.md):
#   P/bin/vascsim, P/libexec/vascsim/vascsim-render (the program that draws, with the renderer)
#   P/lib/libvascsim_{sim,io,render}.a (.so.0.2.0 with VASCSIM_SHARED), P/lib/cmake/vascsim/
#   P/include/vascsim/{sim,render}/...   the API's headers and what they include, nothing else
#   P/share/vascsim/{scenes,assets,sweeps,docs,python,examples}, README.md
#   P/share/man/man1/vascsim.1, P/share/bash-completion/completions/vascsim
# Two components: `runtime` (the program, shared libraries, data, man page, completion) and
# `development` (headers, static libraries and links, the CMake package); the Debian packages
# vascsim and vascsim-dev (cmake/debian_package.cmake) are made of them.
include(CMakePackageConfigHelpers)
include(cmake/public_headers.cmake)

get_property(VASCSIM_INSTALLED_LIBRARIES GLOBAL PROPERTY VASCSIM_EXPORTED_LIBRARIES)

# vascsim::sim: what a program that simulates links (scene reading, compile, run, frame logs).
add_library(vascsim_sim_package INTERFACE)
target_link_libraries(vascsim_sim_package INTERFACE vascsim_io vascsim_sim)
set_target_properties(vascsim_sim_package PROPERTIES EXPORT_NAME sim)
add_library(vascsim::sim ALIAS vascsim_sim_package)

install(TARGETS ${VASCSIM_INSTALLED_LIBRARIES} vascsim_sim_package EXPORT vascsimTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development)
install(TARGETS vascsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
if(VASCSIM_RENDER)
  # The program vascsim hands the commands that draw (apps/vascsim/renderer_program.h).
  install(TARGETS vascsim-render RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/vascsim COMPONENT runtime)
endif()

# The API: scene reading, compile, run, the frame log's reader and writer and its metadata, the
# run summary; rendering a run directory.
set(VASCSIM_API_HEADERS
  sim/io/scene_reader.h sim/run/compile.h sim/run/run.h sim/log/frame_log.h sim/io/log_metadata.h
  sim/io/run_log.h sim/io/run_summary.h sim/io/log_run_check.h sim/io/output_file.h sim/io/provenance.h sim/scene/input_error.h)
if(VASCSIM_RENDER)
  list(APPEND VASCSIM_API_HEADERS render/render_run.h render/frame_source.h)
endif()
vascsim_header_closure(VASCSIM_INSTALLED_HEADERS ${VASCSIM_API_HEADERS})
foreach(header IN LISTS VASCSIM_INSTALLED_HEADERS)
  get_filename_component(dir ${header} DIRECTORY)
  install(FILES ${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vascsim/${dir} COMPONENT development)
endforeach()

set(VASCSIM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/vascsim)
install(EXPORT vascsimTargets NAMESPACE vascsim:: DESTINATION ${VASCSIM_CMAKE_DIR} COMPONENT development)
# Static libraries carry their private dependencies into the consumer's link: the package
# config looks them up again (Clipper, zlib, OSMesa, libav*); shared ones need only the public.
if(VASCSIM_SHARED)
  set(VASCSIM_CONFIG_STATIC FALSE)
else()
  set(VASCSIM_CONFIG_STATIC TRUE)
endif()
set(VASCSIM_CONFIG_RENDER ${VASCSIM_RENDER})
configure_package_config_file(cmake/vascsimConfig.cmake.in ${CMAKE_BINARY_DIR}/vascsimConfig.cmake
  INSTALL_DESTINATION ${VASCSIM_CMAKE_DIR})
# 0.x: a minor version may break the API, so 0.2 accepts 0.2.z only.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/vascsimConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/vascsimConfig.cmake ${CMAKE_BINARY_DIR}/vascsimConfigVersion.cmake
  DESTINATION ${VASCSIM_CMAKE_DIR} COMPONENT development)

# Data. Scenes name their mask images relative to themselves (../assets/), so the tree is kept.
set(VASCSIM_DATA_DIR ${CMAKE_INSTALL_DATADIR}/vascsim)
install(DIRECTORY scenes sweeps assets docs python examples DESTINATION ${VASCSIM_DATA_DIR} COMPONENT runtime
  PATTERN "__pycache__" EXCLUDE)
install(FILES README.md DESTINATION ${VASCSIM_DATA_DIR} COMPONENT runtime)

# The man page, generated from the help text of every command, and the bash completion, which
# reads the same help text when it completes (apps/vascsim/).
set(VASCSIM_MANPAGE ${CMAKE_BINARY_DIR}/vascsim.1)
add_custom_command(OUTPUT ${VASCSIM_MANPAGE}
  COMMAND ${CMAKE_COMMAND} -DVASCSIM=$<TARGET_FILE:vascsim> -DVERSION=${PROJECT_VERSION} -DOUTPUT=${VASCSIM_MANPAGE}
          -P ${PROJECT_SOURCE_DIR}/apps/vascsim/make_manpage.cmake
  DEPENDS vascsim ${PROJECT_SOURCE_DIR}/apps/vascsim/make_manpage.cmake
  COMMENT "Writing the man page from the help text")
add_custom_target(vascsim_manpage ALL DEPENDS ${VASCSIM_MANPAGE})
install(FILES ${VASCSIM_MANPAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT runtime)
install(FILES apps/vascsim/vascsim.bash-completion DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
  RENAME vascsim COMPONENT runtime)

include(cmake/debian_package.cmake)
