# collido_add_plugin(<name> SOURCES <file>... [LIBRARIES <library>...])
#
# Builds lib<name>.so, a Collidoscope backend plugin that `collido --plugin FILE` and
# `collido conformance FILE` load. The plugin links Collidoscope::plugin_api (Eigen and the
# standard library only) and the LIBRARIES given (the engine it adapts). One source file exports
# the entry point with COLLIDO_EXPORT_PLUGIN(<id>, <describe>).
#
# Installed with Collidoscope (find_package(Collidoscope COMPONENTS plugin_api)) and used by its
# own tree, so a plugin builds the same way inside and outside it.
function(collido_add_plugin name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "collido_add_plugin(${name}): no SOURCES given")
  endif()
  add_library(${name} MODULE ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE Collidoscope::plugin_api ${ARG_LIBRARIES})
  collido_plugin_module_settings(${name})
endfunction()

# The link settings every plugin library needs, whoever builds it:
# - only the entry point is visible, so two plugins loaded into one process, or a plugin and the
#   host, never bind each other's symbols (hidden visibility; the static libraries linked in,
#   the engine's and plugin_api's, stay local with --exclude-libs);
# - a symbol the plugin forgot to link fails the link, not the later dlopen (--no-undefined).
function(collido_plugin_module_settings target)
  set_target_properties(${target} PROPERTIES
    PREFIX "lib"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  target_link_options(${target} PRIVATE -Wl,--exclude-libs,ALL)
  # Clang links its sanitizer runtimes into executables only, so an instrumented plugin's calls into
  # them resolve when it is loaded: the sanitizer build leaves this check to the ordinary one.
  if(NOT COLLIDO_SANITIZE)
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
  endif()
endfunction()
