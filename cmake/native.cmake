# Native build settings: warnings are errors, optional sanitizers, system header-only libraries.
set(NIWA_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Werror)
set(NIWA_THIRD_PARTY_INCLUDES "")  # glm, nlohmann, tinygltf, CLI11 live in /usr/include
if(NIWA_SANITIZE)
  # GCC 12 reports false maybe-uninitialized warnings inside libstdc++'s <regex> under the sanitizers
  # (tests/params/strict_number_test.cpp's regex twin); the release build keeps the warning.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    list(APPEND NIWA_WARNINGS -Wno-maybe-uninitialized)
  endif()
  # UBSan plus float-cast-overflow (hostile numbers cast to integers; GCC's -fsanitize=undefined leaves
  # it out), without the null, alignment, vptr and nonnull checks: at -O0 those were about a quarter of
  # the ASan build's compile time (tree_state.cpp 12.5 s against 9.7 s, terrain_commands.cpp 15.8 s
  # against 11.4 s), ASan reports a null dereference itself (SEGV), misaligned loads are legal on x86
  # and in WASM, and the core has almost no virtual calls. Kept: signed-integer-overflow, shift,
  # bounds, bool, enum, return, integer-divide-by-zero, pointer-overflow, unreachable, vla-bound.
  add_compile_options(-fsanitize=address,undefined,float-cast-overflow
                      -fno-sanitize=null,alignment,vptr,nonnull-attribute,returns-nonnull-attribute
                      -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined,float-cast-overflow)
endif()
# Link a program that runs natively (the CLI, test and bench binaries): libstdc++ and libgcc
# statically (and Draco's static library, below), so a fresh process does not spend its start
# binding libstdc++'s and libdraco's symbols (issue 17 item 7: 4.8 M of a fresh
# 'niwa tree grow --preset sakura-thesis --years 15's 154 M instructions were in ld.so). Not with
# the sanitizers, whose runtimes want the shared libraries.
function(niwa_node_program target)
  if(NOT NIWA_SANITIZE)
    target_link_options(${target} PRIVATE -static-libstdc++ -static-libgcc)
  endif()
endfunction()
# Link a unit-test binary (no-op here; the WASM build links tests at -O1, see cmake/emscripten.cmake).
function(niwa_test_program target)
endfunction()

# Registers every <dir>/*.test.mjs as a ctest test run by node with the native CLI and the repo root.
function(niwa_add_node_script_tests dir)
  find_program(NODE_EXECUTABLE node REQUIRED)
  file(GLOB scripts CONFIGURE_DEPENDS ${dir}/*.test.mjs)
  # The sanitized build's runs leave the WASM comparisons to the release build's.
  set(sanitized "")
  if(NIWA_SANITIZE)
    set(sanitized ";NIWA_SANITIZED=1")
  endif()
  foreach(script ${scripts})
    get_filename_component(name ${script} NAME_WE)
    add_test(NAME cli_${name} COMMAND ${NODE_EXECUTABLE} ${script})
    set_tests_properties(cli_${name} PROPERTIES LABELS cli
      ENVIRONMENT "NIWA_NATIVE=${CMAKE_BINARY_DIR}/bin/niwa;NIWA_ROOT=${PROJECT_SOURCE_DIR}${sanitized}")
  endforeach()
endfunction()

# Google Benchmark exists as a Debian library for the native build only.
set(NIWA_GOOGLE_BENCHMARK ON)

# Which build a program belongs to, for reports (bench runner).
add_compile_definitions(NIWA_BUILD_NAME="native")

# Draco (Debian libdraco-dev) decodes KHR_draco_mesh_compression in io/gltf_reader; native only (the
# page decodes Draco with npm draco3d before the WASM core sees the mesh).
find_path(NIWA_DRACO_INCLUDE draco/compression/decode.h)
find_library(NIWA_DRACO_LIBRARY draco)
find_library(NIWA_DRACO_ARCHIVE libdraco.a)
if(NIWA_DRACO_ARCHIVE AND NOT NIWA_SANITIZE)
  set(NIWA_DRACO_LIBRARY ${NIWA_DRACO_ARCHIVE})  # static, as libstdc++: see niwa_node_program
endif()
if(NIWA_DRACO_INCLUDE AND NIWA_DRACO_LIBRARY)
  set(NIWA_DRACO_DEFINITIONS NIWA_HAVE_DRACO)
else()
  set(NIWA_DRACO_LIBRARY "")
  set(NIWA_DRACO_DEFINITIONS "")
endif()

# Threads (native only): the BVH build runs the root's two halves on two threads (core/geom/bvh.cpp;
# the same nodes as one thread, bit for bit), and the bark's 4-layer passes run on two lanes
# (core/bark/step_lanes.cpp; the same bits). The WASM build has no threads and runs on one.
find_package(Threads REQUIRED)
set(NIWA_THREADS_LIBRARY Threads::Threads)
set(NIWA_THREADS_DEFINITIONS NIWA_HAVE_THREADS=1)
