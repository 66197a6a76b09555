# Recorded crowds: the track reader (plugins/lib/crowd_tracks), the `crowds` world and the
# `replay` policy through episodes, the importer's command line and the validation of the human
# models against the recorded people (tools/crowds).
if(CROWDSIM_BUILD_TESTS)
  crowdsim_add_gtest(crowds_test unit
    SOURCES
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/crowds/tracks_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/crowds/crowds_world_test.cc
    LIBS crowdsim_crowd_tracks)
  crowdsim_add_gtest(crowds_validation_test unit
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/crowds/crowds_validation_test.cc
    LIBS crowdsim_crowds_importer)
  crowdsim_add_gtest(crowds_cli_test integration
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/crowds/crowds_cli_test.cc
    LIBS crowdsim_crowd_tracks)
  add_dependencies(crowds_cli_test crowdsim-bench)
endif()
