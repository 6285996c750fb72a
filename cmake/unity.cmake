# Unity batches for niwa_core, the CLI and the test binaries: niwa_unity_batches(target SIZE N ALONE files...).
# Each compile takes up to N of the target's files of one folder at once, so the heavy headers and the
# templates every file instantiates again (nlohmann-json, glm, GoogleTest's macros, CLI11, the STL) are
# parsed and generated once per batch instead of once per file. Results do not change: no fast-math and
# no FMA contraction, so inlining across files cannot change a float.
# The batches are made within each folder (files in name order), never across folders: a file added to
# one folder shifts only that folder's batches, so two file-local helpers of the same name (an anonymous
# namespace is one per batch) can clash only within one folder, where its author builds.
# A file that compiles a header-only library's implementation (`#define ..._IMPLEMENTATION`) stays alone:
# its macros would leak into the batch; so do the caller's ALONE files and generated files.
# -DNIWA_UNITY=OFF compiles file by file (a faster rebuild after editing one file).
option(NIWA_UNITY "Compile in unity batches (niwa_core, niwa_cli, the test binaries)" ON)

function(niwa_unity_batches target)
  cmake_parse_arguments(arg "" "SIZE" "ALONE" ${ARGN})
  if(NOT NIWA_UNITY)
    return()
  endif()
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  set(sorted "")
  foreach(source ${sources})
    if(NOT IS_ABSOLUTE ${source})
      set(source ${source_dir}/${source})
    endif()
    # Generated files (outside the target's source folder) stay alone too.
    string(FIND "${source}" "${source_dir}/" at)
    if(source MATCHES "\\.cpp$" AND at EQUAL 0 AND NOT source IN_LIST arg_ALONE)
      file(STRINGS ${source} implementation REGEX "^#define [A-Z_]+_IMPLEMENTATION")
      if(NOT implementation)
        list(APPEND sorted ${source})
      endif()
    endif()
  endforeach()
  list(SORT sorted)
  set(folder "")
  set(index 0)
  foreach(source ${sorted})
    get_filename_component(dir ${source} DIRECTORY)
    if(NOT dir STREQUAL folder)
      set(folder ${dir})
      set(index 0)
    endif()
    math(EXPR batch "${index} / ${arg_SIZE}")
    file(RELATIVE_PATH tag ${source_dir} ${dir})
    string(REPLACE "/" "_" tag "${tag}")
    if(tag STREQUAL "")
      set(tag top)
    endif()
    # The group names the target too: a source file's UNITY_GROUP is one property for every target.
    set_source_files_properties(${source} PROPERTIES UNITY_GROUP "${target}_${tag}_${batch}")
    math(EXPR index "${index} + 1")
  endforeach()
endfunction()
