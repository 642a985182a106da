# weathergen_add_materials(): one custom command per material graph, so editing one
# graph or one of its image files recompiles that material alone.
#
#   weathergen_add_materials(TARGET name
#                            GRAPHS graph.json...
#                            [TARGETS glsl hlsl spirv msl glsles surface filament all]   (default: all)
#                            [OUTPUT_DIR dir]                           (default: <binary dir>/<name>)
#                            [EMIT_HEADER] [ALL]
#                            [OPTIONS extra compile flags...])
#
# Relative GRAPHS are read from the current source directory, a relative OUTPUT_DIR is
# in the current binary directory. The custom target <name> depends on every output;
# its WEATHERGEN_OUTPUTS property lists them. Documented in docs/build-integration.md.

include_guard(GLOBAL)

# Ninja reads the depfile's paths relative to the top build directory; NEW makes CMake
# rewrite the absolute paths weathergen writes into that form. Functions keep the
# policies set where they are defined, whatever the caller's cmake_minimum_required.
cmake_policy(PUSH)
cmake_policy(SET CMP0116 NEW)

# The material NAME from the graph's "name", made file-safe the way the compiler does
# (driver/material_compiler.cpp, fileStemFor): [A-Za-z0-9_-] kept, others '_', 64 bytes.
function(_weathergen_material_stem graph out_var)
  file(READ "${graph}" text)
  string(JSON name ERROR_VARIABLE json_error GET "${text}" name)
  if(json_error OR name STREQUAL "")
    # The build will run weathergen on it and print the real diagnostic.
    get_filename_component(name "${graph}" NAME_WE)
    message(WARNING "weathergen_add_materials: cannot read the material \"name\" of ${graph} "
                    "(${json_error}); assuming \"${name}\" until it is fixed")
  endif()
  string(REGEX REPLACE "[^A-Za-z0-9_-]" "_" stem "${name}")
  string(SUBSTRING "${stem}" 0 64 stem)
  set(${out_var} "${stem}" PARENT_SCOPE)
endfunction()

# The files `weathergen compile` writes for one material (cli/compile_command.cpp).
function(_weathergen_material_outputs dir stem targets emit_header out_var)
  set(files "${stem}.reflect.json")
  foreach(target IN LISTS targets)
    if(target STREQUAL "glsl")
      list(APPEND files "${stem}.vert.glsl" "${stem}.frag.glsl")
    elseif(target STREQUAL "hlsl")
      list(APPEND files "${stem}.vert.hlsl" "${stem}.frag.hlsl")
    elseif(target STREQUAL "spirv")
      foreach(language glsl hlsl)
        foreach(stage vert frag)
          list(APPEND files "${stem}.${language}.${stage}.spv" "${stem}.${language}.${stage}.spvasm")
        endforeach()
      endforeach()
    elseif(target STREQUAL "msl")
      list(APPEND files "${stem}.vert.msl" "${stem}.frag.msl")
    elseif(target STREQUAL "glsles")
      list(APPEND files "${stem}.vert.es.glsl" "${stem}.frag.es.glsl")
    elseif(target STREQUAL "surface")
      list(APPEND files "${stem}.surface.glsl" "${stem}.surface.es.glsl" "${stem}.surface.hlsl")
    elseif(target STREQUAL "filament")
      list(APPEND files "${stem}.mat")
    endif()
  endforeach()
  if(emit_header)
    list(APPEND files "${stem}.hpp")
  endif()
  # Byte order, as weathergen writes its depfile: Ninja requires the depfile's first
  # output to be the custom command's first OUTPUT.
  list(REMOVE_DUPLICATES files)
  list(SORT files COMPARE STRING)
  list(TRANSFORM files PREPEND "${dir}/")
  set(${out_var} "${files}" PARENT_SCOPE)
endfunction()

function(weathergen_add_materials)
  cmake_parse_arguments(PARSE_ARGV 0 arg "EMIT_HEADER;ALL" "TARGET;OUTPUT_DIR" "GRAPHS;TARGETS;OPTIONS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "weathergen_add_materials: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGET)
    message(FATAL_ERROR "weathergen_add_materials: TARGET <name> is required")
  endif()
  if(NOT arg_GRAPHS)
    message(FATAL_ERROR "weathergen_add_materials(${arg_TARGET}): GRAPHS is empty")
  endif()
  if(NOT TARGET weathergen::weathergen)
    message(FATAL_ERROR "weathergen_add_materials: weathergen::weathergen is not defined; "
                        "call find_package(weathergen) first")
  endif()
  # These flags decide the output names, so they have keywords of their own.
  foreach(flag IN LISTS arg_OPTIONS)
    if(flag MATCHES "^(-o|--output|--target|--depfile|--emit-header)")
      message(FATAL_ERROR "weathergen_add_materials(${arg_TARGET}): pass '${flag}' as OUTPUT_DIR, "
                          "TARGETS or EMIT_HEADER, not in OPTIONS")
    endif()
  endforeach()

  set(targets "${arg_TARGETS}")
  if(NOT targets OR "all" IN_LIST targets)
    list(REMOVE_ITEM targets all)
    list(APPEND targets glsl hlsl spirv)
  endif()
  list(REMOVE_DUPLICATES targets)
  foreach(target IN LISTS targets)
    if(NOT target MATCHES "^(glsl|hlsl|spirv|msl|glsles|surface|filament)$")
      message(FATAL_ERROR "weathergen_add_materials(${arg_TARGET}): unknown target '${target}' "
                          "(use glsl, hlsl, spirv, msl, glsles, surface, filament or all)")
    endif()
  endforeach()
  list(JOIN targets "," target_list)

  set(output_dir "${arg_OUTPUT_DIR}")
  if(NOT output_dir)
    set(output_dir "${arg_TARGET}")
  endif()
  cmake_path(ABSOLUTE_PATH output_dir BASE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}" NORMALIZE)
  string(REGEX REPLACE "/$" "" output_dir "${output_dir}")
  set(header_flag "")
  if(arg_EMIT_HEADER)
    set(header_flag "--emit-header")
  endif()

  set(all_outputs "")
  set(stems "")
  foreach(graph IN LISTS arg_GRAPHS)
    cmake_path(ABSOLUTE_PATH graph BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE)
    if(NOT EXISTS "${graph}")
      message(FATAL_ERROR "weathergen_add_materials(${arg_TARGET}): graph not found: ${graph}")
    endif()
    # The output names come from the graph's "name": re-configure when a graph changes.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${graph}")
    _weathergen_material_stem("${graph}" stem)
    if(stem IN_LIST stems)
      message(FATAL_ERROR "weathergen_add_materials(${arg_TARGET}): ${graph} writes the same files "
                          "as another graph (material name '${stem}'); give each material a distinct name")
    endif()
    list(APPEND stems "${stem}")
    _weathergen_material_outputs("${output_dir}" "${stem}" "${targets}" "${arg_EMIT_HEADER}" outputs)
    set(depfile_dir "${CMAKE_CURRENT_BINARY_DIR}/weathergen-deps/${arg_TARGET}")
    set(depfile "${depfile_dir}/${stem}.d")
    add_custom_command(
      OUTPUT ${outputs}
      # weathergen creates the output directory but not the depfile's.
      COMMAND "${CMAKE_COMMAND}" -E make_directory "${depfile_dir}"
      COMMAND weathergen::weathergen compile "${graph}" -o "${output_dir}" --target "${target_list}"
              ${header_flag} --depfile "${depfile}" ${arg_OPTIONS}
      DEPENDS "${graph}" weathergen::weathergen
      DEPFILE "${depfile}"
      COMMENT "weathergen: compiling material ${stem}"
      VERBATIM)
    list(APPEND all_outputs ${outputs})
  endforeach()

  set(all_flag "")
  if(arg_ALL)
    set(all_flag ALL)
  endif()
  add_custom_target(${arg_TARGET} ${all_flag} DEPENDS ${all_outputs})
  set_target_properties(${arg_TARGET} PROPERTIES WEATHERGEN_OUTPUTS "${all_outputs}"
                                                 WEATHERGEN_OUTPUT_DIR "${output_dir}")
endfunction()

cmake_policy(POP)
