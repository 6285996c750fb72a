# Compiler cache: when ccache is installed (scripts/setup installs it), every compile goes through it.
# Paths are made relative to the folder above the checkout (CCACHE_BASEDIR), so clones and worktrees side by
# side share hits; the sloppiness lets the test binaries' precompiled header be cached (CMake's -include of
# cmake_pch.hxx, with -fpch-preprocess added in tests/CMakeLists.txt). NIWA_CCACHE=OFF builds without it
# (a cold-build measurement). It changes no object: ccache hands back the bytes the compiler wrote.
option(NIWA_CCACHE "Compile through ccache when it is installed" ON)
find_program(NIWA_CCACHE_PROGRAM ccache)
if(NIWA_CCACHE AND NIWA_CCACHE_PROGRAM)
  get_filename_component(niwa_ccache_base "${PROJECT_SOURCE_DIR}/.." ABSOLUTE)
  set(niwa_launcher ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${niwa_ccache_base} CCACHE_NOHASHDIR=1
      CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime ${NIWA_CCACHE_PROGRAM})
  set(CMAKE_CXX_COMPILER_LAUNCHER ${niwa_launcher})
  set(CMAKE_C_COMPILER_LAUNCHER ${niwa_launcher})
endif()
