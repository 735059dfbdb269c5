# End-to-end VRML import through the staged meshlabserver (included by tests/e2e/CMakeLists.txt).
find_package(ZLIB REQUIRED)
cadlod_add_e2e_test(e2e_vrml SOURCES test_vrml_import.cpp LIBS ZLIB::ZLIB)
