# cpack -G DEB: a Debian package with the two plugins, tied to the exact meshlab version
# whose headers they were compiled against.
set(CPACK_PACKAGE_NAME "meshlab-cadlod")
set(CPACK_PACKAGE_CONTACT "cadlod developers <cadlod@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_DEBIAN_PACKAGE_DEPENDS "meshlab (= ${MESHLAB_VERSION})")
set(CPACK_DEBIAN_PACKAGE_SECTION "graphics")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
set(CPACK_COMPONENTS_ALL plugins)
set(CPACK_DEB_COMPONENT_INSTALL OFF)
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
include(CPack)
