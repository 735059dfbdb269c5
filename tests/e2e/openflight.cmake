# End-to-end OpenFlight export/import through the staged meshlabserver, each file
# checked with OpenSceneGraph (included by tests/e2e/CMakeLists.txt).
cadlod_add_e2e_test(e2e_openflight SOURCES test_flt_export.cpp test_flt_import.cpp test_flt_lod_set.cpp
  LIBS cadlod::openflight cadlod_osg_probe)

# The command line and the meshlabserver route side by side.
if(TARGET cadlod)
  cadlod_add_e2e_test(e2e_headless_routes SOURCES test_cli_vs_meshlabserver.cpp LIBS cadlod::openflight cadlod_osg_probe)
  target_compile_definitions(e2e_headless_routes PRIVATE CADLOD_CLI="$<TARGET_FILE:cadlod>")
  add_dependencies(e2e_headless_routes cadlod)
endif()
