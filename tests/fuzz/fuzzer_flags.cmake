# CADLOD_BUILD_FUZZERS: instrument everything for libFuzzer (clang only). The targets
# themselves are defined in tests/fuzz/CMakeLists.txt; build only them in this tree:
#   cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
#         -DCADLOD_BUILD_FUZZERS=ON
#   cmake --build build-fuzz --target cadlod_fuzzers
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "CADLOD_BUILD_FUZZERS needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                    -fno-sanitize-recover=undefined)
add_link_options(-fsanitize=address,undefined)
