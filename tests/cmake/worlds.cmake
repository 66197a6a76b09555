# World plugins (random_rect, crowdnav) and the shared human placement: one test executable,
# linked to the random-room library for the layout generator and the frozen sets.
if(CROWDSIM_BUILD_TESTS)
  crowdsim_add_gtest(worlds_test unit
    SOURCES
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/worlds/human_placement_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/worlds/rect_layout_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/worlds/frozen_sets_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/worlds/random_rect_plugin_test.cc
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/worlds/crowdnav_plugin_test.cc
    LIBS crowdsim_random_rect_lib)
endif()
