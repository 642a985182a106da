# The CLI option parsers and what they call, for targets that run
# tests/fuzz/cli_options_case.cpp: the CLI options fuzz target and the unit tests
# that replay its regressions.
function(weathergen_add_cli_options_case target)
  target_sources(${target} PRIVATE
    ${PROJECT_SOURCE_DIR}/tests/fuzz/cli_options_case.cpp
    ${PROJECT_SOURCE_DIR}/cli/bundled_graphs_directory.cpp
    ${PROJECT_SOURCE_DIR}/cli/command_line.cpp
    ${PROJECT_SOURCE_DIR}/cli/diagnostic_output.cpp
    ${PROJECT_SOURCE_DIR}/cli/effect_overrides_option.cpp
    ${PROJECT_SOURCE_DIR}/cli/eval_inputs.cpp
    ${PROJECT_SOURCE_DIR}/cli/number_text.cpp
    ${PROJECT_SOURCE_DIR}/cli/option_table.cpp
    ${PROJECT_SOURCE_DIR}/cli/orbit_camera_option.cpp
    ${PROJECT_SOURCE_DIR}/cli/render_options.cpp
    ${PROJECT_SOURCE_DIR}/cli/sample_count.cpp)
  # render_options.hpp holds a RenderRequest: runtime headers, Vulkan's included.
  target_link_libraries(${target} PRIVATE weathergen_compiler weathergen_weather glm::glm Vulkan::Headers)
  target_compile_definitions(${target} PRIVATE GLM_FORCE_DEPTH_ZERO_TO_ONE GLM_FORCE_RADIANS
    WG_GRAPHS_FROM_EXECUTABLE="${WG_GRAPHS_FROM_EXECUTABLE}")
endfunction()
