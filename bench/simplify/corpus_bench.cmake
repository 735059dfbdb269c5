# corpus_bench: cadlod vs peers on the CAD corpus with the shading measure (issue 14), and
# issue 13's far-field check (--far-field; VRML inputs through bench/lod/mesh_loading.h).
# Included from bench/simplify/CMakeLists.txt (needs CGAL and meshoptimizer found there).
add_executable(corpus_bench corpus_bench.cpp "${CMAKE_SOURCE_DIR}/tests/support/mesh_files.cpp"
  "${CADLOD_VCGLIB_DIR}/wrap/ply/plylib.cpp")
target_include_directories(corpus_bench PRIVATE
  "${CMAKE_SOURCE_DIR}/tests/simplify" "${CMAKE_SOURCE_DIR}/tests/support" "${CMAKE_SOURCE_DIR}/bench/lod")
target_link_libraries(corpus_bench PRIVATE cadlod::lod cadlod::shading cadlod::convert CGAL::CGAL
  "${MESHOPTIMIZER_LIBRARY}")
target_compile_definitions(corpus_bench PRIVATE CADLOD_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
target_compile_options(corpus_bench PRIVATE -Wall -Wextra)
