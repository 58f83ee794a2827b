# `cpack -G DEB` (in the build directory, or `cpack --config BUILD/CPackConfig.cmake`): the
# Debian packages vascsim (the program, its data, man page and completion; shared libraries with
# VASCSIM_SHARED) and vascsim-dev (headers, static libraries, the CMake package), made by the
# same install rules as `cmake --install`. The program's library dependencies are computed by
# dpkg-shlibdeps; the font it opens at run time and the -dev package's build dependencies cannot
# be seen in the binaries and are named here. Build it from a Release build (docs/install.md).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME vascsim)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "vascsim developers <vascsim-dev@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "simulate and render a magnetically steered soft robot in 2D vessels")
set(CPACK_PACKAGE_DESCRIPTION
  "vascsim simulates a magnetically steered elastic catheter (a discrete elastic rod with wall contact and friction) in 2D mazes and vessel networks, renders review videos off-screen (OSMesa, H.264) and replays runs in a web browser.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES TRUE)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME vascsim)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "fonts-dejavu-core")  # the HUD and plot font (render/)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "python3-numpy, parallel, slurm-wlm")  # the reader, sweep engines
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME vascsim-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(VASCSIM_DEV_DEPENDS "vascsim (= ${PROJECT_VERSION}), cmake, pkg-config, libeigen3-dev, nlohmann-json3-dev, libpolyclipping-dev, zlib1g-dev")
if(VASCSIM_RENDER)
  string(APPEND VASCSIM_DEV_DEPENDS ", libglm-dev, libosmesa6-dev, libavcodec-dev, libavformat-dev, libswscale-dev, libavutil-dev")
endif()
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "${VASCSIM_DEV_DEPENDS}")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION "Headers, libraries and the CMake package (find_package(vascsim)) for programs that embed vascsim.")
include(CPack)
