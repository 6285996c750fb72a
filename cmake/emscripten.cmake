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
# keep IEEE semantics (no fast-math), so the tests see the same bits; the CLI (niwa.js, used by the
# native-against-WASM tests), the web module and the bench runner keep the -O3 link.
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
