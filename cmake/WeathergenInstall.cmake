# `cmake --install`: the CLI in bin/, the engine library in lib/ with its header, and a
# CMake package in lib/cmake/weathergen so that other projects can find_package(weathergen),
# call weathergen_add_materials() and link weathergen::compiler (and weathergen::snow).
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

set(WG_PACKAGE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/weathergen")

install(TARGETS weathergen EXPORT weathergenTargets RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
# The bundled graphs: `weathergen render` finds them at ../share/weathergen/graphs.
install(DIRECTORY graphs/ DESTINATION "${CMAKE_INSTALL_DATADIR}/weathergen/graphs" FILES_MATCHING PATTERN "*.json")
install(EXPORT weathergenTargets NAMESPACE weathergen:: DESTINATION "${WG_PACKAGE_DIR}")
# The engine library has an export set of its own: unlike the CLI it is only usable by a
# consumer with the same pointer size, so the config loads it only then.
install(TARGETS weathergen_shared EXPORT weathergenCompilerTargets
        LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(FILES include/weathergen/weathergen.hpp DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/weathergen")
install(EXPORT weathergenCompilerTargets NAMESPACE weathergen:: DESTINATION "${WG_PACKAGE_DIR}")
# The weather loop: its own export set, loaded with the engine library (no dependencies).
install(TARGETS weathergen_weather_shared EXPORT weathergenWeatherTargets LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(FILES include/weathergen/weather.hpp DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/weathergen")
install(EXPORT weathergenWeatherTargets NAMESPACE weathergen:: DESTINATION "${WG_PACKAGE_DIR}")
# The deformable snow library: its own export set, loaded by the config only for the
# `snow` component, since it brings a dependency (the Vulkan headers).
install(TARGETS weathergen_snow_shared EXPORT weathergenSnowTargets LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(FILES include/weathergen/snow.hpp DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/weathergen")
install(EXPORT weathergenSnowTargets NAMESPACE weathergen:: DESTINATION "${WG_PACKAGE_DIR}")

configure_package_config_file(cmake/weathergenConfig.cmake.in
  "${CMAKE_CURRENT_BINARY_DIR}/weathergenConfig.cmake" INSTALL_DESTINATION "${WG_PACKAGE_DIR}")
# The CLI is a host tool: usable whatever the consuming project's pointer size (the config
# checks it before loading the library). 0.x minors may break.
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/weathergenConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/weathergenConfig.cmake"
              "${CMAKE_CURRENT_BINARY_DIR}/weathergenConfigVersion.cmake"
              cmake/WeathergenMaterials.cmake
        DESTINATION "${WG_PACKAGE_DIR}")
