# The sanitizer build (the 'asan' preset): one build, with clang, serves the test suite and the
# libFuzzer targets. Everything is checked by AddressSanitizer and UndefinedBehaviorSanitizer;
# COLLIDO_FUZZ adds the fuzz targets (tests/fuzz/CMakeLists.txt), the only ones to link libFuzzer.
#
# Coverage instrumentation (fuzzer-no-link), which libFuzzer steers by, goes only into the
# libraries the fuzz targets exercise: elsewhere it cost a fifth of a file's compile time and
# steered nothing (docs/CI.md). The preset compiles at -O1: at -O0 a file compiled in half the
# time, but the suite ran so much slower that the stage took longer in all.

option(COLLIDO_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(COLLIDO_FUZZ "Also build the libFuzzer targets of tests/fuzz (clang; implies COLLIDO_SANITIZE)"
       OFF)

# The libraries the fuzz targets exercise (tests/fuzz/CMakeLists.txt), instrumented for coverage.
set(COLLIDO_FUZZED collido_scene collido_mesh collido_mesh_types collido_io obbtree collido_oracle
    collido_nurbs collido_frep)

if(COLLIDO_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "COLLIDO_FUZZ needs clang (libFuzzer); use the 'asan' preset "
                        "(tools/fuzz.sh), not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  set(COLLIDO_SANITIZE ON)
endif()

if(COLLIDO_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC's -Wmaybe-uninitialized misfires inside CGAL and the standard library once the
    # sanitizers instrument them; the Release build keeps the code warning-free.
    add_compile_options(-Wno-maybe-uninitialized)
  else()
    # Checks left out of code that is not ours, each with its reason. Named relative to the build
    # folder, where compilers run, so that the command (and ccache's key) is the same in any clone.
    file(RELATIVE_PATH ignorelist ${CMAKE_BINARY_DIR}
         ${CMAKE_CURRENT_LIST_DIR}/sanitizer_ignorelist.txt)
    add_compile_options(-fsanitize-ignorelist=${ignorelist})
  endif()
endif()

# Call once, after every target is defined: coverage for the fuzzed libraries.
function(collido_sanitizer_targets)
  if(COLLIDO_FUZZ)
    foreach(target ${COLLIDO_FUZZED})
      if(TARGET ${target})
        target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
      endif()
    endforeach()
  endif()
endfunction()

# collido_gtest_tests(<target> [PREFIX <prefix>] [SANITIZER_SHARDS <n>]): a GoogleTest executable's
# tests, registered with CTest. The ordinary build registers each test on its own, named
# <prefix><Suite>.<Test> (listed by running the executable once it links). The sanitizer build
# registers <n> tests, <prefix><target>.shard<i>, each running one of GoogleTest's shards (a test
# goes to shard i when its index modulo n is i): an instrumented process took about 0.2 s to start,
# and the listing ran every executable once more at build time: together a fifth of the stage.
include(GoogleTest)
function(collido_gtest_tests target)
  cmake_parse_arguments(ARG "" "PREFIX;SANITIZER_SHARDS" "" ${ARGN})
  if(NOT COLLIDO_SANITIZE)
    gtest_discover_tests(${target} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} TEST_PREFIX "${ARG_PREFIX}"
                         PROPERTIES LABELS ${target} DISCOVERY_TIMEOUT 60)
    return()
  endif()
  set(shards 1)
  if(ARG_SANITIZER_SHARDS)
    set(shards ${ARG_SANITIZER_SHARDS})
  endif()
  math(EXPR last "${shards} - 1")
  foreach(index RANGE ${last})
    set(test ${ARG_PREFIX}${target}.shard${index})
    add_test(NAME ${test} COMMAND ${target} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    set_tests_properties(${test} PROPERTIES LABELS ${target}
      ENVIRONMENT "GTEST_TOTAL_SHARDS=${shards};GTEST_SHARD_INDEX=${index}")
  endforeach()
endfunction()
