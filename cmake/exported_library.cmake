# vascsim_exported_library(TARGET NAME): TARGET is a library other programs link. It is
# installed and exported as vascsim::NAME (cmake/install.cmake), with the project version as its
# version and MAJOR.MINOR as the soname version when shared (0.x releases may break the ABI at
# every minor version), and the same name works inside this build as an alias.
function(vascsim_exported_library target name)
  set_target_properties(${target} PROPERTIES
    EXPORT_NAME ${name}
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  add_library(vascsim::${name} ALIAS ${target})
  set_property(GLOBAL APPEND PROPERTY VASCSIM_EXPORTED_LIBRARIES ${target})
endfunction()
