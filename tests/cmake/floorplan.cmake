# The floor-plan importer library (worlds/floorplan) and the `floorplan` world plugin.
if(CROWDSIM_BUILD_TESTS)
  find_package(PNG REQUIRED)  # the tests write RGBA PNGs of their own
  crowdsim_add_gtest(floorplan_test unit
    SOURCES
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/floorplan/raster_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/floorplan/import_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/floorplan/floorplan_plugin_test.cc
    LIBS crowdsim_floorplan_lib PNG::PNG)
endif()

if(CROWDSIM_BUILD_BENCHMARKS)
  crowdsim_add_benchmark(floorplan_bench
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench/floorplan/floorplan_bench.cc
    LIBS crowdsim_floorplan_lib)
endif()
