# The `torchscript` policy plugin (plugins/policies/torchscript): tiny modules scripted and saved by the
# test with python3-torch run through the CLI (tests/python/test_torchscript_plugin.py). The
# test exits 77 (skipped) when python3-torch is missing; the Python package, when built, is on
# PYTHONPATH for the layout check against crowdsim_bench.evaluate().
if(CROWDSIM_BUILD_TESTS AND TARGET crowdsim_plugin_torchscript)
  if(CROWDSIM_PYTHON_EXECUTABLE)
    set(_torchscript_python "${CROWDSIM_PYTHON_EXECUTABLE}")
  else()
    find_package(Python3 COMPONENTS Interpreter)
    set(_torchscript_python "${Python3_EXECUTABLE}")
  endif()
  if(_torchscript_python)
    # torchscript_plugin: the tiny modules; torchscript_export: the committed CADRL/SARL
    # weights exported to TorchScript (crowdsim_bench.torchscript_export) decide as the built-in
    # plugins. Both exit 77 (skipped) without python3-torch or the Python package.
    foreach(_test plugin export)
      add_test(NAME torchscript_${_test}
        COMMAND "${_torchscript_python}" tests/python/test_torchscript_${_test}.py
        WORKING_DIRECTORY "${CMAKE_SOURCE_DIR}")
      set_tests_properties(torchscript_${_test} PROPERTIES LABELS integration TIMEOUT 300
        SKIP_RETURN_CODE 77
        ENVIRONMENT "CROWDSIM_BENCH=$<TARGET_FILE:crowdsim-bench>;PYTHONPATH=${CROWDSIM_PYTHON_DIR}")
    endforeach()
  endif()
endif()
