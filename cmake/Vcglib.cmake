include_guard(GLOBAL)
# vcglib (+ Eigen) headers for the MeshLab-independent cores, without the rest of the
# MeshLab SDK: the vcglib bundled in MeshLab 2020.09's source package (scripts/bootstrap.sh
# unpacks it into .cache/meshlab-src), so the cores and the plugins see one vcglib.
# Provides:
#  cadlod::vcglib       vcglib + Eigen headers (INTERFACE)
#  MESHLAB_SOURCE_DIR   the unpacked MeshLab source package (vcglib/ inside)
#  CADLOD_VCGLIB_DIR    the vcglib directory (holds vcg/ and wrap/)
set(MESHLAB_SOURCE_DIR "${CMAKE_SOURCE_DIR}/.cache/meshlab-src" CACHE PATH
    "MeshLab source package of the installed meshlab version (scripts/bootstrap.sh unpacks it)")
set(CADLOD_VCGLIB_DIR "${MESHLAB_SOURCE_DIR}/vcglib" CACHE PATH
    "vcglib headers (by default the copy in MeshLab's source package)")

if(NOT EXISTS "${CADLOD_VCGLIB_DIR}/vcg/complex/complex.h")
  message(FATAL_ERROR "cadlod: vcglib headers not found at ${CADLOD_VCGLIB_DIR}: run scripts/bootstrap.sh "
                      "(as root) to unpack MeshLab's source package, or set CADLOD_VCGLIB_DIR")
endif()

find_package(Eigen3 REQUIRED NO_MODULE)

add_library(cadlod_vcglib INTERFACE)
add_library(cadlod::vcglib ALIAS cadlod_vcglib)
target_include_directories(cadlod_vcglib SYSTEM INTERFACE "${CADLOD_VCGLIB_DIR}")
target_link_libraries(cadlod_vcglib INTERFACE Eigen3::Eigen)
