# End-to-end CAD Quadric Edge Collapse through the staged meshlabserver (included by
# tests/e2e/CMakeLists.txt).
cadlod_add_e2e_test(e2e_simplify SOURCES test_simplify_filter.cpp LIBS cadlod::lod)
target_include_directories(e2e_simplify PRIVATE "${CMAKE_SOURCE_DIR}/tests/simplify")
