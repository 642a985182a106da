# weathergen::compiler: the engine API (include/weathergen/weathergen.hpp) as one shared
# library, libweathergen.so. The compiler and its static dependencies (glslang,
# SPIRV-Tools, SPIRV-Cross, nlohmann_json) are linked into it and hidden by a version
# script, so an engine links one library and needs none of them (docs/engine-api.md).
include(GNUInstallDirs)

# The static libraries end up in a shared object.
set_target_properties(weathergen_compiler weathergen_backends weathergen_compiler_core weathergen_nodes PROPERTIES POSITION_INDEPENDENT_CODE ON)

add_library(weathergen_shared SHARED driver/public_api.cpp driver/public_weather_noise.cpp)
add_library(weathergen::compiler ALIAS weathergen_shared)
# The public header is the whole interface: consumers see include/ and nothing else.
target_include_directories(weathergen_shared INTERFACE
  "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>" "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
target_compile_features(weathergen_shared INTERFACE cxx_std_17)
target_link_libraries(weathergen_shared PRIVATE weathergen_compiler)

set(WG_EXPORT_MAP "${CMAKE_CURRENT_SOURCE_DIR}/cmake/weathergen.map")
target_link_options(weathergen_shared PRIVATE "LINKER:--version-script=${WG_EXPORT_MAP}")
# Sanitizer and fuzzer runtimes are linked into executables only, so their hooks are
# undefined in the library there.
if(NOT WEATHERGEN_SANITIZE AND NOT WEATHERGEN_FUZZ)
  target_link_options(weathergen_shared PRIVATE "LINKER:--no-undefined")
endif()
# 0.x minors may break the ABI (as the package version file says), so the soname has both.
set_target_properties(weathergen_shared PROPERTIES
  OUTPUT_NAME weathergen
  EXPORT_NAME compiler
  VERSION "${PROJECT_VERSION}"
  SOVERSION "${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}"
  LINK_DEPENDS "${WG_EXPORT_MAP}")

# weathergen::snow: the deformable snow for engines (include/weathergen/snow.hpp) as
# libweathergen_snow.so. The snow and Vulkan code and their static dependencies
# are linked in and hidden like the compiler's; the engine's own libvulkan does the
# calls, and consumers get the Vulkan headers the API names (docs/engine-api.md).
set_target_properties(weathergen_snow weathergen_vulkan weathergen_weather PROPERTIES POSITION_INDEPENDENT_CODE ON)
add_library(weathergen_snow_shared SHARED snow/public_snow_api.cpp)
add_library(weathergen::snow ALIAS weathergen_snow_shared)
target_include_directories(weathergen_snow_shared INTERFACE
  "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>" "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
target_compile_features(weathergen_snow_shared INTERFACE cxx_std_17)
target_link_libraries(weathergen_snow_shared PUBLIC Vulkan::Headers PRIVATE weathergen_snow Vulkan::Vulkan)
set(WG_SNOW_EXPORT_MAP "${CMAKE_CURRENT_SOURCE_DIR}/cmake/weathergen_snow.map")
target_link_options(weathergen_snow_shared PRIVATE "LINKER:--version-script=${WG_SNOW_EXPORT_MAP}")
if(NOT WEATHERGEN_SANITIZE AND NOT WEATHERGEN_FUZZ)
  target_link_options(weathergen_snow_shared PRIVATE "LINKER:--no-undefined")
endif()
target_link_options(weathergen_snow_shared PRIVATE "LINKER:--as-needed")  # e.g. no libstb: the snow reads no image
set_target_properties(weathergen_snow_shared PROPERTIES
  OUTPUT_NAME weathergen_snow
  EXPORT_NAME snow
  VERSION "${PROJECT_VERSION}"
  SOVERSION "${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}"
  LINK_DEPENDS "${WG_SNOW_EXPORT_MAP}")

# weathergen::weather: the weather loop for engines (include/weathergen/weather.hpp) as
# libweathergen_weather.so: the simulation, the noise texture and the sky-exposure
# builder, CPU only, with nothing in its link interface.
add_library(weathergen_weather_shared SHARED weather/public_weather_api.cpp)
add_library(weathergen::weather ALIAS weathergen_weather_shared)
target_include_directories(weathergen_weather_shared INTERFACE
  "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>" "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
target_compile_features(weathergen_weather_shared INTERFACE cxx_std_17)
target_link_libraries(weathergen_weather_shared PRIVATE weathergen_weather)
set(WG_WEATHER_EXPORT_MAP "${CMAKE_CURRENT_SOURCE_DIR}/cmake/weathergen_weather.map")
target_link_options(weathergen_weather_shared PRIVATE "LINKER:--version-script=${WG_WEATHER_EXPORT_MAP}")
if(NOT WEATHERGEN_SANITIZE AND NOT WEATHERGEN_FUZZ)
  target_link_options(weathergen_weather_shared PRIVATE "LINKER:--no-undefined")
endif()
target_link_options(weathergen_weather_shared PRIVATE "LINKER:--as-needed")
set_target_properties(weathergen_weather_shared PROPERTIES
  OUTPUT_NAME weathergen_weather
  EXPORT_NAME weather
  VERSION "${PROJECT_VERSION}"
  SOVERSION "${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}"
  LINK_DEPENDS "${WG_WEATHER_EXPORT_MAP}")
