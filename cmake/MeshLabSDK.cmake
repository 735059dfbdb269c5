# Finds the MeshLab 2020.09 "SDK" this project builds against:
#  - Debian's meshlab binary package: libmeshlab-common.so, the system plugins,
#    meshlab and meshlabserver;
#  - the headers of the same version from Debian's source package (MeshLab src/common
#    and the bundled vcglib), unpacked by scripts/bootstrap.sh.
# Only the plugins (and the tests that run them) need it: with -DCADLOD_BUILD_PLUGINS=OFF
# the cores are built from vcglib's headers alone (cmake/Vcglib.cmake, included here too).
# Provides:
#  cadlod::meshlab      everything a MeshLab plugin needs (headers, flags, Qt, libmeshlab-common)
#  MESHLAB_BIN_DIR, MESHLAB_LIB_DIR, MESHLAB_PLUGIN_DIR, MESHLAB_VERSION

include(Vcglib)
set(MESHLAB_LIB_DIR "/usr/lib/x86_64-linux-gnu/meshlab" CACHE PATH "Directory of libmeshlab-common.so")
set(MESHLAB_PLUGIN_DIR "${MESHLAB_LIB_DIR}/plugins" CACHE PATH "MeshLab's system plugin directory")
set(MESHLAB_BIN_DIR "/usr/bin" CACHE PATH "Directory of meshlab and meshlabserver")
# Relative to CMAKE_INSTALL_PREFIX (/usr by default): where `cmake --install` puts the plugins.
set(MESHLAB_PLUGIN_INSTALL_DIR "lib/x86_64-linux-gnu/meshlab/plugins" CACHE STRING
    "Plugin install directory, relative to CMAKE_INSTALL_PREFIX")

set(_fix "run scripts/bootstrap.sh (as root) to install meshlab and unpack its source package")

function(_cadlod_require_file path what)
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "cadlod: ${what} not found at ${path}: ${_fix}")
  endif()
endfunction()

_cadlod_require_file("${MESHLAB_LIB_DIR}/libmeshlab-common.so" "libmeshlab-common.so (Debian package meshlab)")
_cadlod_require_file("${MESHLAB_BIN_DIR}/meshlabserver" "meshlabserver (Debian package meshlab)")
_cadlod_require_file("${MESHLAB_SOURCE_DIR}/src/common/interfaces.h" "MeshLab headers")

# Source and binary must be the very same Debian version: plugins compiled against other
# headers load but corrupt memory.
execute_process(COMMAND dpkg-query -W -f=\${Version} meshlab
                OUTPUT_VARIABLE MESHLAB_BINARY_VERSION RESULT_VARIABLE _rc
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT _rc EQUAL 0 OR MESHLAB_BINARY_VERSION STREQUAL "")
  message(FATAL_ERROR "cadlod: the Debian package meshlab is not installed: ${_fix}")
endif()
file(STRINGS "${MESHLAB_SOURCE_DIR}/debian/changelog" _changelog_head LIMIT_COUNT 1)
string(REGEX MATCH "\\(([^)]+)\\)" _m "${_changelog_head}")
set(MESHLAB_SOURCE_VERSION "${CMAKE_MATCH_1}")
if(NOT MESHLAB_SOURCE_VERSION STREQUAL MESHLAB_BINARY_VERSION)
  message(FATAL_ERROR
    "cadlod: meshlab binary package is ${MESHLAB_BINARY_VERSION} but the source in "
    "${MESHLAB_SOURCE_DIR} is ${MESHLAB_SOURCE_VERSION}. Delete that directory and ${_fix}.")
endif()
if(NOT MESHLAB_BINARY_VERSION MATCHES "^2020\\.09")
  message(FATAL_ERROR "cadlod: needs MeshLab 2020.09, found ${MESHLAB_BINARY_VERSION}")
endif()
set(MESHLAB_VERSION "${MESHLAB_BINARY_VERSION}")
message(STATUS "cadlod: MeshLab ${MESHLAB_VERSION} (binary and source match)")

find_package(Qt5 REQUIRED COMPONENTS Core Widgets OpenGL Xml XmlPatterns)
find_package(OpenGL REQUIRED)
find_package(ZLIB REQUIRED)

add_library(meshlab_common SHARED IMPORTED)
set_target_properties(meshlab_common PROPERTIES
  IMPORTED_LOCATION "${MESHLAB_LIB_DIR}/libmeshlab-common.so"
  IMPORTED_NO_SONAME TRUE)

add_library(cadlod_meshlab INTERFACE)
add_library(cadlod::meshlab ALIAS cadlod_meshlab)
target_include_directories(cadlod_meshlab SYSTEM INTERFACE
  "${MESHLAB_SOURCE_DIR}/src" "${MESHLAB_SOURCE_DIR}/src/common")
target_compile_definitions(cadlod_meshlab INTERFACE MESHLAB_SCALAR=float)
target_link_libraries(cadlod_meshlab INTERFACE
  cadlod::vcglib meshlab_common Qt5::Core Qt5::Widgets Qt5::OpenGL Qt5::Xml OpenGL::GL)

# A MeshLab plugin: a Qt MODULE library with our flags.
function(cadlod_add_meshlab_plugin name)
  add_library(${name} MODULE ${ARGN})
  set_target_properties(${name} PROPERTIES AUTOMOC ON PREFIX "lib"
                        LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/plugins")
  target_link_libraries(${name} PRIVATE cadlod::meshlab)
  target_link_options(${name} PRIVATE -Wl,--no-undefined)
  install(TARGETS ${name} LIBRARY DESTINATION "${MESHLAB_PLUGIN_INSTALL_DIR}" COMPONENT plugins)
endfunction()
