# The floor-plan importer (tools/floorplan) and the `floorplan` world plugin (plugins/worlds/floorplan),
# whose test imports a synthetic plan to have a world.
if(CROWDSIM_BUILD_TESTS)
  find_package(PNG REQUIRED)  # the tests write RGBA PNGs of their own
  crowdsim_add_gtest(floorplan_test unit
    SOURCES
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/floorplan/raster_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/floorplan/import_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/floorplan/floorplan_plugin_test.cc
    LIBS crowdsim_floorplan_importer PNG::PNG)
  # `crowdsim-bench floorplan`, run as a user would.
  crowdsim_add_gtest(floorplan_cli_test integration
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/floorplan/floorplan_cli_test.cc
    LIBS crowdsim_floorplan_importer)
  add_dependencies(floorplan_cli_test crowdsim-bench)
endif()

if(CROWDSIM_BUILD_BENCHMARKS)
  crowdsim_add_benchmark(floorplan_bench
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench/floorplan/floorplan_bench.cc
    LIBS crowdsim_floorplan_importer)
endif()
