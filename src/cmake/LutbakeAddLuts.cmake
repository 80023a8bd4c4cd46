# lutbake_add_luts: bake lookup tables at build time and put their C++
# headers on a target's include path.
#
#   lutbake_add_luts(<target>
#                    [TABLES E Eavg Favg dfg]   # default: all four (or the plan's)
#                    [SCENE file.gltf ...]      # bake only what the scenes need
#                    [MANIFEST file.json ...]
#                    [OPTIONS --namespace engine::luts ...])
#
# The headers are written to <binary dir>/lutbake_luts/<target>/lutbake_luts/
# and both that folder and its parent are added to <target>'s include path,
# so the target includes <lutbake_luts/E.h> (or "E.h"), Eavg.h, Favg.h,
# dfg.h and kulla_conty.h. OPTIONS are passed to `lutbake bake` verbatim
# (any of its options but --out). The default here is --format header; the
# integration is the CLI's default (float32-exact, a fraction of a second
# for the default set) unless OPTIONS choose another.
#
# The bake is an add_custom_command: it reruns only when one of its inputs
# changes: the lutbake executable, a SCENE or MANIFEST file, or the
# arguments (kept in a file that is rewritten only when they change). With
# SCENE or MANIFEST, TABLES selects among the planned tables, and one the
# plan leaves out fails the build at the bake with the plan's reason.
#
# The executable is lutbake::cli: the installed one after
# find_package(lutbake), or the one built alongside after add_subdirectory.
include_guard(GLOBAL)

function(lutbake_add_luts target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "TABLES;SCENE;MANIFEST;OPTIONS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "lutbake_add_luts(${target}): unexpected arguments "
                        "'${ARG_UNPARSED_ARGUMENTS}'; accepted: TABLES, SCENE, MANIFEST, OPTIONS")
  endif()
  if(NOT TARGET ${target})
    message(FATAL_ERROR "lutbake_add_luts: '${target}' is not a target")
  endif()
  if(NOT TARGET lutbake::cli)
    message(FATAL_ERROR "lutbake_add_luts: no lutbake::cli target; call find_package(lutbake) "
                        "or add_subdirectory(<lutbake>) first")
  endif()
  get_target_property(done ${target} LUTBAKE_LUTS)
  if(done)
    message(FATAL_ERROR "lutbake_add_luts: called twice for '${target}'; give it one call with "
                        "every table")
  endif()
  set_target_properties(${target} PROPERTIES LUTBAKE_LUTS ON)
  foreach(table IN LISTS ARG_TABLES)
    if(NOT table MATCHES "^(E|Eavg|Favg|dfg)$")
      message(FATAL_ERROR "lutbake_add_luts(${target}): TABLES '${table}' is not a table; "
                          "accepted: E Eavg Favg dfg")
    endif()
  endforeach()
  if("--out" IN_LIST ARG_OPTIONS)
    message(FATAL_ERROR "lutbake_add_luts(${target}): OPTIONS cannot hold --out; the headers go "
                        "to the build tree")
  endif()

  set(root "${CMAKE_CURRENT_BINARY_DIR}/lutbake_luts/${target}")
  set(dir "${root}/lutbake_luts")
  set(args bake --out "${dir}")
  if(ARG_TABLES)
    list(JOIN ARG_TABLES "," tables)
    list(APPEND args --tables "${tables}")
  endif()
  set(depends "$<TARGET_FILE:lutbake::cli>")
  foreach(kind SCENE MANIFEST)
    string(TOLOWER "--${kind}" flag)
    foreach(file IN LISTS ARG_${kind})
      get_filename_component(file "${file}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
      list(APPEND args ${flag} "${file}")
      list(APPEND depends "${file}")
    endforeach()
  endforeach()
  if(NOT "--format" IN_LIST ARG_OPTIONS)
    list(APPEND args --format header)
  endif()
  list(APPEND args ${ARG_OPTIONS})

  # The arguments, in a file rewritten only when they change, so that a
  # changed OPTIONS reruns the bake under every generator.
  set(argsFile "${root}/bake_arguments.txt")
  list(JOIN args "\n" argsText)
  file(CONFIGURE OUTPUT "${argsFile}" CONTENT "${argsText}\n" @ONLY)
  list(APPEND depends "${argsFile}")

  # Outputs: a stamp, and the headers whenever they are known before the
  # bake (without a plan: one per table, kulla_conty.h with E and Eavg).
  set(stamp "${root}/bake.stamp")
  set(headers "")
  if(NOT ARG_SCENE AND NOT ARG_MANIFEST)
    set(known ${ARG_TABLES})
    if(NOT known)
      set(known E Eavg Favg dfg)
    endif()
    foreach(table IN LISTS known)
      list(APPEND headers "${dir}/${table}.h")
    endforeach()
    if("E" IN_LIST known AND "Eavg" IN_LIST known)
      list(APPEND headers "${dir}/kulla_conty.h")
    endif()
  endif()

  add_custom_command(
    OUTPUT "${stamp}" ${headers}
    COMMAND lutbake::cli ${args}
    COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
    DEPENDS ${depends}
    COMMENT "lutbake: baking the lookup tables of ${target}"
    VERBATIM)
  add_custom_target(${target}_lutbake_luts DEPENDS "${stamp}" ${headers})
  add_dependencies(${target} ${target}_lutbake_luts)
  # The generated headers are C++17 (inline variables); clang++ 14 defaults to C++14.
  target_compile_features(${target} PUBLIC cxx_std_17)
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${root}>"
                                              "$<BUILD_INTERFACE:${dir}>")
endfunction()
