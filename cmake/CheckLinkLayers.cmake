# The link graph's layering, checked by the test layers.link_graph (tests/CMakeLists.txt): each
# library may link only libraries of lower layers, so a layer cannot quietly reach above itself
# (the host the constraint solver, the OBB tree a mesh importer). LINKS names a file of lines
# "<library>=<its direct links>" written when the build is generated.
#
#   cmake -DLINKS=<build>/link_graph.txt -P cmake/CheckLinkLayers.cmake
cmake_minimum_required(VERSION 3.16)

# Lowest first. Backends (collido_backend_*) sit beside host and scene: they link the plugin API
# and what they compute with, never the host or the scenes.
set(layer_0 plugin_api random record)
set(layer_1 mesh_types pose constraints convex frep io)
set(layer_2 oracle mesh)
set(layer_3 nurbs stress frep_mesh frep_preview obbtree)
set(layer_4 host scene urdf backend)
set(layer_5 backend_separation runner)
set(layer_6 study view)
# Links a library must not have whatever the layers say.
set(banned_obbtree mesh assimp::assimp)  # the OBB tree component installs without assimp

function(layer_of name out)
  foreach(candidate ${name} backend)
    foreach(layer RANGE 6)
      if(candidate IN_LIST layer_${layer})
        set(${out} ${layer} PARENT_SCOPE)
        return()
      endif()
    endforeach()
    if(NOT name MATCHES "^backend_")
      break()
    endif()
  endforeach()
  set(${out} "" PARENT_SCOPE)
endfunction()

file(STRINGS "${LINKS}" lines)
set(problems "")
foreach(line IN LISTS lines)
  string(REGEX MATCH "^([^=]+)=(.*)$" matched "${line}")
  set(library "${CMAKE_MATCH_1}")
  string(REPLACE "," ";" links "${CMAKE_MATCH_2}")
  layer_of(${library} own)
  if(own STREQUAL "")
    string(APPEND problems "  ${library} has no layer in cmake/CheckLinkLayers.cmake\n")
    continue()
  endif()
  foreach(link IN LISTS links)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
    string(REGEX REPLACE "^(collido::|Collidoscope::|collido_)" "" name "${link}")
    if(name IN_LIST banned_${library})
      string(APPEND problems "  ${library} links ${link}, which it must not\n")
      continue()
    endif()
    if(NOT link MATCHES "^(collido::|Collidoscope::|collido_|obbtree$)" OR link MATCHES "_engine$")
      continue()  # a library from outside: Eigen, CGAL, an engine (Bullet's in its two precisions)
    endif()
    layer_of(${name} theirs)
    if(theirs STREQUAL "")
      string(APPEND problems "  ${library} links ${link}, which has no layer\n")
    elseif(NOT theirs LESS own)
      string(APPEND problems
             "  ${library} (layer ${own}) links ${link} (layer ${theirs}): only lower layers\n")
    endif()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "the link graph breaks its layers:\n${problems}")
endif()
list(LENGTH lines count)
message(STATUS "link graph: ${count} libraries, each linking only lower layers")
