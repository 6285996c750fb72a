# Every Emscripten flag of the project (Debian emscripten 3.1.6); included only when EMSCRIPTEN.
set(NIWA_WARNINGS -Wall -Wextra -Wno-unused-command-line-argument -Werror)
set(ENV{NODE_PATH} "/usr/share/nodejs")  # acorn for emcc's JS optimizer (TOOLCHAIN gotcha 1)

# Header-only libraries through a folder of symlinks: never -I/usr/include (gotcha 2).
set(NIWA_SYSINC ${CMAKE_BINARY_DIR}/sysinc)
file(MAKE_DIRECTORY ${NIWA_SYSINC})
foreach(entry glm nlohmann CLI stb tiny_gltf.h stb_image.h tiny_obj_loader.h kissfft nanoflann.hpp)
  if(NOT EXISTS ${NIWA_SYSINC}/${entry})
    file(CREATE_LINK /usr/include/${entry} ${NIWA_SYSINC}/${entry} SYMBOLIC)
  endif()
endforeach()
if(NOT EXISTS ${NIWA_SYSINC}/stb_image.h AND EXISTS /usr/include/stb/stb_image.h)
  file(CREATE_LINK /usr/include/stb/stb_image.h ${NIWA_SYSINC}/stb_image.h SYMBOLIC)
endif()
set(NIWA_THIRD_PARTY_INCLUDES ${NIWA_SYSINC})

# C++ exceptions (nlohmann-json, CLI11, GoogleTest) as real WASM exceptions.
# SIMD128 auto-vectorization: lane-wise IEEE operations, no reassociation (no fast-math), so the
# results stay identical to the native build.
add_compile_options(-fwasm-exceptions -msimd128)
add_link_options(-fwasm-exceptions -sALLOW_MEMORY_GROWTH=1)
# Binaryen's -O3 link inlines every function that has one caller, however large (its
# --one-caller-inline-max-function-size defaults to unlimited). V8 (node 20, Chrome) runs a function in
# its baseline compiler (Liftoff) until a later call finds it optimised: there is no on-stack
# replacement for WASM, so a long loop inlined into a function called once never leaves Liftoff. The
# bark model's Step, inlined into BarkRun::Advance, ran its whole node pass there (node --prof: 29 % of
# the camphor 128x64 run in unoptimised code; 8.0 -> 3.1 ns a spring-step with this cap, 2026-12-06).
# Functions of up to 200 expressions (binaryen's measure) with one caller are still inlined.
add_link_options(-sBINARYEN_EXTRA_PASSES=--one-caller-inline-max-function-size=200)

# Programs that run under node (CLI, tests, benchmarks): synchronous compile (gotcha 4) and the real
# file system (gotcha 6).
function(niwa_node_program target)
  target_link_options(${target} PRIVATE -sWASM_ASYNC_COMPILATION=0 -sNODERAWFS=1 -sEXIT_RUNTIME=1
                     )
  set_target_properties(${target} PROPERTIES SUFFIX ".js")
endfunction()

# Unit-test binaries link at -O1: their objects are still compiled at -O3 (CMAKE_BUILD_TYPE), but the
# link skips binaryen's whole-module -O3 passes, which cost 30-65 CPU seconds per test binary (cli_tests:
# 65.6 s at -O3 against 1.4 s at -O1, measured 2026-12-02) and dominated a clean CI build. Those passes
# keep IEEE semantics (no fast-math), so the tests see the same bits. The CLI (niwa.js), which only the
# tests run (native against WASM), links at -O1 too: its -O3 link was 72 CPU s of a clean WASM build
# (2026-12-07, at load 5-10), and its runs were 0-15 % slower at -O1 (eight commands, 9.8 s against 10.1
# and 11.5 s of CPU). The web module and the bench runner (the WASM speed figures) keep the -O3 link.
function(niwa_test_program target)
  niwa_node_program(${target})
  target_link_options(${target} PRIVATE -O1)
endfunction()

# The web module: ES6 factory for the Web Worker, embind, no HTML (gotcha 3).
set(NIWA_WEB_LINK_OPTIONS -lembind -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createNiwaModule
    -sENVIRONMENT=worker -sFILESYSTEM=0)
set(CMAKE_CROSSCOMPILING_EMULATOR node)

# The node-script tests compare both builds and are registered once, by the native build.
function(niwa_add_node_script_tests dir)
endfunction()

# Google Benchmark exists as a Debian library for the native build only.
set(NIWA_GOOGLE_BENCHMARK OFF)

# Which build a program belongs to, for reports (bench runner).
add_compile_definitions(NIWA_BUILD_NAME="wasm")
