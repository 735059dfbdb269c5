# ASan + UBSan for the whole build (scripts/test.sh --sanitize).
if(CADLOD_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# MeshLab's executables are not instrumented: the sanitizer runtime must be preloaded into
# meshlabserver/meshlab for our instrumented plugins to load (tests/support, e2e tests).
set(CADLOD_SANITIZER_PRELOAD "")
if(CADLOD_SANITIZE)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so
                  OUTPUT_VARIABLE CADLOD_SANITIZER_PRELOAD OUTPUT_STRIP_TRAILING_WHITESPACE)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libubsan.so
                  OUTPUT_VARIABLE _ubsan OUTPUT_STRIP_TRAILING_WHITESPACE)
  set(CADLOD_SANITIZER_PRELOAD "${CADLOD_SANITIZER_PRELOAD}:${_ubsan}")
endif()
