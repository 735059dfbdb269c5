# A private MeshLab for tests and the demo (design.md §2): copies of meshlab and
# meshlabserver whose RUNPATH and plugin lookup resolve relative to STAGE/bin, with the
# system plugins (symlinks) plus ours in STAGE/lib/x86_64-linux-gnu/meshlab/plugins.
# Nothing under the system's MeshLab directories is touched.
set(CADLOD_STAGE_DIR "${CMAKE_BINARY_DIR}/stage")
set(CADLOD_STAGE_MESHLABSERVER "${CADLOD_STAGE_DIR}/bin/meshlabserver")
set(CADLOD_STAGE_MESHLAB "${CADLOD_STAGE_DIR}/bin/meshlab")

add_custom_target(stage ALL
  COMMAND ${CMAKE_COMMAND}
          -DSTAGE=${CADLOD_STAGE_DIR}
          -DMESHLAB_BIN_DIR=${MESHLAB_BIN_DIR}
          -DMESHLAB_LIB_DIR=${MESHLAB_LIB_DIR}
          -DMESHLAB_PLUGIN_DIR=${MESHLAB_PLUGIN_DIR}
          "-DOUR_PLUGINS=$<TARGET_FILE:filter_cadlod>;$<TARGET_FILE:io_vrml_flt>"
          -P ${CMAKE_CURRENT_LIST_DIR}/make_stage.cmake
  DEPENDS filter_cadlod io_vrml_flt
  VERBATIM
  COMMENT "Staging meshlab/meshlabserver with the cadlod plugins in ${CADLOD_STAGE_DIR}")
